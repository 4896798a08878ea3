#pragma once
// The plotted quantities of a scene: only what the scene has (no volume, pressure or gas
// energy for the 1D spring), named like the CLI's CSV columns.

#include <array>
#include <functional>
#include <vector>

#include <QColor>
#include <QString>

#include "simcore/params.h"
#include "simcore/simulation.h"

namespace elui {

struct SeriesSpec {
    QString plot;     // "volume", "pressure" or "energy"
    QString name;     // legend text
    QColor color;
    std::function<double(const simcore::Diagnostics&)> value;
    // Half-width of the series' error band (Diagnostics::errors), NaN where the row has none;
    // empty for a series without a band.
    std::function<double(const simcore::Diagnostics&)> error = {};
};

struct PlotSpec {
    QString id;       // "volume", "pressure", "energy"
    QString title;
    QString yLabel;
    std::vector<SeriesSpec> series;
};

// world: a scene of several bodies of this kind: the world's energy only (per-body volume and
// pressure are the Bodies dock's).
std::vector<PlotSpec> plotSpecs(simcore::SceneKind kind, bool world = false);

// The energy book's terms. One colour table for the energy plot's curves and the energy bars
// (EnergyBarsDock): a term has the same colour wherever it is drawn.
enum class EnergyTerm {
    Kinetic,
    Spring,            // all families (the energy plot's curve)
    SpringStructural,  // the families (bars): the spring green, the first exactly, then lighter
    SpringRadius,
    SpringShear,
    Gravity,
    Gas,
    Contact,
    Mouse,
    Total,
    Removed,           // by damping, contact and the projection together (plot)
    RemovedDamping,
    RemovedContact,    // by contact dissipation and friction, or by the projection
    Drift,
};
QColor energyColor(EnergyTerm term);
// The colour of a gas layer (0 inner, 1 outer) in the volume, pressure and P–V plots.
QColor layerColor(int layer);
// The hue of body k (from 0) of a scene of several bodies: its outer layer in the viewport, its
// curves in the Bodies dock. Distinct for the first eight, then repeating.
QColor bodyColor(int body);

// One bar of the energy bar chart: a Diagnostics field, in the book's order.
struct EnergyBar {
    QString id;        // "kinetic", "spring-structural", ..., "drift"
    QString name;      // axis label
    EnergyTerm term;
    bool part;         // a part of the total (kinetic + potentials); else removed or drift
    double (*value)(const simcore::Diagnostics&);
};

// The bars a body has: spring families with springs in its topology (`families`), gas only
// in the gas scenes. `projection`: contact = projection (the contact bar is then always 0
// and the removed-by-contact bar is what the projection removed).
std::vector<EnergyBar> energyBars(simcore::SceneKind kind, const std::array<bool, 3>& families, bool projection);

}  // namespace elui
