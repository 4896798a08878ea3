#pragma once
// Export: CSV time series (the CLI's columns), plots (PNG, SVG, PDF), images and scene files,
// every file written atomically through QSaveFile (a failed or interrupted write leaves the old
// file untouched and no partial or temporary file behind); an existing device such as
// /dev/null is written in place, never renamed over.

#include <vector>

#include <QImage>
#include <QString>

#include "simcore/params.h"
#include "simcore/simulation.h"

class QCustomPlot;

namespace elui {

struct PlotSpec;

// Each returns an error message naming the file and the system's reason, or empty on success.
QString writeFile(const QString& path, const QByteArray& bytes);
QString writeCsv(const QString& path, simcore::SceneKind kind, const std::vector<simcore::Diagnostics>& rows);
QString writeImage(const QString& path, const QImage& image);
// The plots stacked vertically; the format follows the suffix (.png, .svg, .pdf).
QString writePlots(const QString& path, const std::vector<QCustomPlot*>& plots,
                   const std::vector<PlotSpec>& specs, int width = 900, int heightEach = 300);

}  // namespace elui
