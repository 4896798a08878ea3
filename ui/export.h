#pragma once
// Export: CSV time series (the CLI's columns), plots (PNG, SVG, PDF) and images, every file
// written atomically through QSaveFile (an interrupted write never leaves half a file).

#include <vector>

#include <QImage>
#include <QString>

#include "params.h"
#include "simulation.h"

class QCustomPlot;

namespace elui {

struct PlotSpec;

// Returns an error message, or empty on success.
QString writeCsv(const QString& path, simcore::SceneKind kind, const std::vector<simcore::Diagnostics>& rows);
QString writeImage(const QString& path, const QImage& image);
// The plots stacked vertically; the format follows the suffix (.png, .svg, .pdf).
QString writePlots(const QString& path, const std::vector<QCustomPlot*>& plots,
                   const std::vector<PlotSpec>& specs, int width = 900, int heightEach = 300);

}  // namespace elui
