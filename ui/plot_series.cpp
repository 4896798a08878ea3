#include "plot_series.h"

#include <QObject>

#include "scenes.h"

namespace elui {

std::vector<PlotSpec> plotSpecs(simcore::SceneKind kind) {
    using D = simcore::Diagnostics;
    std::vector<PlotSpec> plots;
    const bool gas = simcore::hasGas(kind);
    const bool flat = kind == simcore::SceneKind::Ring2d;
    const QColor inner(40, 90, 220), outer(235, 120, 20);
    if (gas) {
        plots.push_back({QStringLiteral("volume"), flat ? QObject::tr("Area per layer") : QObject::tr("Volume per layer"),
                         flat ? QStringLiteral("area [m²]") : QStringLiteral("volume [m³]"),
                         {{"volume", QObject::tr("inner"), inner, [](const D& d) { return d.volume[0]; }},
                          {"volume", QObject::tr("outer"), outer, [](const D& d) { return d.volume[1]; }}}});
        plots.push_back({QStringLiteral("pressure"), QObject::tr("Pressure per layer"),
                         flat ? QStringLiteral("pressure [N/m]") : QStringLiteral("pressure [Pa]"),
                         {{"pressure", QObject::tr("inner"), inner, [](const D& d) { return d.pressure[0]; }},
                          {"pressure", QObject::tr("outer"), outer, [](const D& d) { return d.pressure[1]; }}}});
    }
    PlotSpec energy{QStringLiteral("energy"), QObject::tr("Energy"), QStringLiteral("energy [J]"), {}};
    energy.series.push_back({"energy", QObject::tr("kinetic"), QColor(200, 30, 30), [](const D& d) { return d.kinetic; }});
    energy.series.push_back({"energy", QObject::tr("spring"), QColor(30, 140, 60), [](const D& d) { return d.springTotal(); }});
    energy.series.push_back({"energy", QObject::tr("gravity"), QColor(120, 80, 30), [](const D& d) { return d.gravity; }});
    if (gas) energy.series.push_back({"energy", QObject::tr("gas"), QColor(40, 110, 210), [](const D& d) { return d.gas; }});
    // Every scene has the box walls: the contact energy (walls + layer barrier, 0 with
    // contact = projection) and what contact dissipation and friction removed.
    energy.series.push_back({"energy", QObject::tr("contact"), QColor(0, 150, 150), [](const D& d) { return d.contact; }});
    energy.series.push_back({"energy", QObject::tr("total"), QColor(0, 0, 0), [](const D& d) { return d.total(); }});
    energy.series.push_back({"energy", QObject::tr("removed"), QColor(150, 60, 170), [](const D& d) { return d.removed(); }});
    energy.series.push_back({"energy", QObject::tr("removed by contact"), QColor(210, 90, 170),
                             [](const D& d) { return d.removedContact + d.removedCollisions; }});
    plots.push_back(std::move(energy));
    return plots;
}

}  // namespace elui
