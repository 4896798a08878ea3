#include "ui/world_export.h"

#include <QCoreApplication>
#include <QFileDialog>

#include "ui/export.h"
#include "ui/simulation_controller.h"

namespace elui {

QString writeWorldCsv(const QString& path, SimulationController& controller, int* rows) {
    const QByteArray csv = controller.worldCsv();
    if (csv.isEmpty()) return QCoreApplication::translate("WorldExport", "No run of several bodies to export");
    if (rows) *rows = int(csv.count('\n')) - 1;  // the header is not a row
    return writeFile(path, csv);
}

WorldExportResult exportWorldCsv(QWidget* parent, SimulationController& controller) {
    QString path = QFileDialog::getSaveFileName(parent, QCoreApplication::translate("WorldExport", "Export data"), QStringLiteral("elastic-lab-world.csv"),
                                                QCoreApplication::translate("WorldExport", "CSV of several bodies, comma and decimal point (*.csv)"));
    if (path.isEmpty()) return {};
    int rows = 0;
    WorldExportResult result;
    result.error = writeWorldCsv(path, controller, &rows);
    if (result.error.isEmpty()) result.done = QCoreApplication::translate("WorldExport", "Wrote %1 rows of the world to %2").arg(rows).arg(path);
    return result;
}

}  // namespace elui
