#pragma once
// The plotted quantities of a scene: only what the scene has (no volume, pressure or gas
// energy for the 1D spring), named like the CLI's CSV columns.

#include <functional>
#include <vector>

#include <QColor>
#include <QString>

#include "params.h"
#include "simulation.h"

namespace elui {

struct SeriesSpec {
    QString plot;     // "volume", "pressure" or "energy"
    QString name;     // legend text
    QColor color;
    std::function<double(const simcore::Diagnostics&)> value;
};

struct PlotSpec {
    QString id;       // "volume", "pressure", "energy"
    QString title;
    QString yLabel;
    std::vector<SeriesSpec> series;
};

std::vector<PlotSpec> plotSpecs(simcore::SceneKind kind);

}  // namespace elui
