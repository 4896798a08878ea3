#pragma once
// Export: CSV time series (the CLI's columns, in either CSV dialect) and .xlsx workbooks, plots (PNG, SVG, PDF), images and scene files,
// every file written atomically through QSaveFile (a failed or interrupted write leaves the old
// file untouched and no partial or temporary file behind); an existing device such as
// /dev/null is written in place, never renamed over.

#include <vector>

#include <QImage>
#include <QLocale>
#include <QString>

#include "simcore/params.h"
#include "simcore/simulation.h"
#include "simlab/output.h"

class QCustomPlot;

namespace elui {

struct PlotSpec;

// Each returns an error message naming the file and the system's reason, or empty on success.
QString writeFile(const QString& path, const QByteArray& bytes);
QString writeCsv(const QString& path, simcore::SceneKind kind, const std::vector<simcore::Diagnostics>& rows,
                 simlab::CsvDialect dialect = simlab::CsvDialect::Plain);
// The run's table and charts as an .xlsx workbook (simlab's TimeSeriesWriter, as the CLI's --xlsx).
QString writeXlsx(const QString& path, simcore::SceneKind kind, const std::vector<simcore::Diagnostics>& rows);
// The CSV dialect a spreadsheet of this locale opens by a double-click: excel-semicolon where the
// decimal separator is a comma (de, fr, es, ...), plain elsewhere.
simlab::CsvDialect defaultCsvDialect(const QLocale& locale);
QString writeImage(const QString& path, const QImage& image);
// The plots stacked vertically; the format follows the suffix (.png, .svg, .pdf).
QString writePlots(const QString& path, const std::vector<QCustomPlot*>& plots,
                   const std::vector<PlotSpec>& specs, int width = 900, int heightEach = 300);

}  // namespace elui
