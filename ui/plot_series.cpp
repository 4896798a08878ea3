#include "ui/plot_series.h"

#include <algorithm>
#include <iterator>
#include <limits>

#include <QObject>

#include "simcore/scenes.h"

namespace elui {

namespace {
double none() { return std::numeric_limits<double>::quiet_NaN(); }
}  // namespace

std::vector<PlotSpec> plotSpecs(simcore::SceneKind kind, bool world) {
    using D = simcore::Diagnostics;
    std::vector<PlotSpec> plots;
    const bool gas = simcore::hasGas(kind);
    const bool flat = kind == simcore::SceneKind::Ring2d;
    const QColor inner = layerColor(0), outer = layerColor(1);
    if (gas && !world) {
        plots.push_back({QStringLiteral("volume"), flat ? QObject::tr("Area per layer") : QObject::tr("Volume per layer"),
                         flat ? QObject::tr("area [m²]") : QObject::tr("volume [m³]"),
                         {{"volume", QObject::tr("inner"), inner, [](const D& d) { return d.volume[0]; },
                           [](const D& d) { return d.errors.valid ? d.errors.volume[0] : none(); }},
                          {"volume", QObject::tr("outer"), outer, [](const D& d) { return d.volume[1]; },
                           [](const D& d) { return d.errors.valid ? d.errors.volume[1] : none(); }}}});
        plots.push_back({QStringLiteral("pressure"), QObject::tr("Pressure per layer"),
                         flat ? QObject::tr("pressure [N/m]") : QObject::tr("pressure [Pa]"),
                         {{"pressure", QObject::tr("inner"), inner, [](const D& d) { return d.pressure[0]; },
                           [](const D& d) { return d.errors.valid ? d.errors.pressure[0] : none(); }},
                          {"pressure", QObject::tr("outer"), outer, [](const D& d) { return d.pressure[1]; },
                           [](const D& d) { return d.errors.valid ? d.errors.pressure[1] : none(); }}}});
    }
    PlotSpec energy{QStringLiteral("energy"), QObject::tr("Energy"), QObject::tr("energy [J]"), {}};
    using T = EnergyTerm;
    energy.series.push_back({"energy", QObject::tr("kinetic"), energyColor(T::Kinetic), [](const D& d) { return d.kinetic; }});
    energy.series.push_back({"energy", QObject::tr("spring"), energyColor(T::Spring), [](const D& d) { return d.springTotal(); }});
    energy.series.push_back({"energy", QObject::tr("gravity"), energyColor(T::Gravity), [](const D& d) { return d.gravity; }});
    if (gas) energy.series.push_back({"energy", QObject::tr("gas"), energyColor(T::Gas), [](const D& d) { return d.gas; }});
    // Every scene has the box walls: the contact energy (walls + layer barrier, 0 with
    // contact = projection) and what contact dissipation and friction removed.
    energy.series.push_back({"energy", QObject::tr("contact"), energyColor(T::Contact), [](const D& d) { return d.contact; }});
    energy.series.push_back({"energy", QObject::tr("total"), energyColor(T::Total), [](const D& d) { return d.total(); },
                             [](const D& d) { return d.errors.valid ? d.errors.energy : none(); }});
    energy.series.push_back({"energy", QObject::tr("removed"), energyColor(T::Removed), [](const D& d) { return d.removed(); }});
    energy.series.push_back({"energy", QObject::tr("removed by contact"), energyColor(T::RemovedContact),
                             [](const D& d) { return d.removedContact + d.removedCollisions; }});
    plots.push_back(std::move(energy));
    return plots;
}

QColor bodyColor(int body) {
    static const QColor hues[] = {{230, 110, 20}, {40, 110, 220}, {40, 160, 70}, {190, 50, 160},
                                  {200, 40, 40}, {20, 160, 170}, {140, 100, 30}, {110, 80, 200}};
    return hues[static_cast<std::size_t>(std::max(body, 0)) % std::size(hues)];
}

QColor layerColor(int layer) { return layer == 0 ? QColor(40, 90, 220) : QColor(235, 120, 20); }

QColor energyColor(EnergyTerm term) {
    switch (term) {
        case EnergyTerm::Kinetic: return {200, 30, 30};
        case EnergyTerm::Spring:
        case EnergyTerm::SpringStructural: return {30, 140, 60};
        // The same hue and saturation, lighter (HSL lightness 85 -> 125, 165 of 255).
        case EnergyTerm::SpringRadius: return QColor::fromHsl(136, 165, 125);
        case EnergyTerm::SpringShear: return QColor::fromHsl(136, 165, 165);
        case EnergyTerm::Gravity: return {120, 80, 30};
        case EnergyTerm::Gas: return {40, 110, 210};
        case EnergyTerm::Contact: return {0, 150, 150};
        case EnergyTerm::Mouse: return {230, 170, 0};
        case EnergyTerm::Total: return {0, 0, 0};
        case EnergyTerm::Removed: return {150, 60, 170};
        case EnergyTerm::RemovedDamping: return {110, 110, 120};
        case EnergyTerm::RemovedContact: return {210, 90, 170};
        case EnergyTerm::Drift: return {225, 60, 60};
    }
    return {0, 0, 0};
}

std::vector<EnergyBar> energyBars(simcore::SceneKind kind, const std::array<bool, 3>& families, bool projection) {
    using D = simcore::Diagnostics;
    using T = EnergyTerm;
    std::vector<EnergyBar> bars;
    // The parts of the total, in the order of Diagnostics::total(): kinetic + springs + gravity
    // + gas + mouse + contact.
    bars.push_back({QStringLiteral("kinetic"), QObject::tr("kinetic"), T::Kinetic, true, [](const D& d) { return d.kinetic; }});
    if (families[0])
        bars.push_back({QStringLiteral("spring-structural"), QObject::tr("spring: structural"), T::SpringStructural, true,
                        [](const D& d) { return d.spring[0]; }});
    if (families[1])
        bars.push_back({QStringLiteral("spring-radius"), QObject::tr("spring: radius"), T::SpringRadius, true,
                        [](const D& d) { return d.spring[1]; }});
    if (families[2])
        bars.push_back({QStringLiteral("spring-shear"), QObject::tr("spring: shear"), T::SpringShear, true,
                        [](const D& d) { return d.spring[2]; }});
    bars.push_back({QStringLiteral("gravity"), QObject::tr("gravity"), T::Gravity, true, [](const D& d) { return d.gravity; }});
    if (simcore::hasGas(kind))
        bars.push_back({QStringLiteral("gas"), QObject::tr("gas"), T::Gas, true, [](const D& d) { return d.gas; }});
    bars.push_back({QStringLiteral("contact"), QObject::tr("contact"), T::Contact, true, [](const D& d) { return d.contact; }});
    bars.push_back({QStringLiteral("mouse"), QObject::tr("mouse spring"), T::Mouse, true, [](const D& d) { return d.pointer; }});
    // What left the body, and the balance's error.
    bars.push_back({QStringLiteral("removed-damping"), QObject::tr("removed by damping"), T::RemovedDamping, false,
                    [](const D& d) { return d.removedDamping; }});
    bars.push_back({QStringLiteral("removed-contact"),
                    projection ? QObject::tr("removed by projection") : QObject::tr("removed by contact"),
                    T::RemovedContact, false, [](const D& d) { return d.removedContact + d.removedCollisions; }});
    bars.push_back({QStringLiteral("drift"), QObject::tr("drift (balance error)"), T::Drift, false,
                    [](const D& d) { return d.energyDrift(); }});
    return bars;
}

}  // namespace elui
