#pragma once
// A world's time series from the window (File > Export Data with a scene of several bodies):
// the same columns and numbers as elastic-lab-cli run --csv writes for the world
// (simlab::worldColumns: the world's energies and ledger, per body volume, pressure, centre of
// mass and its velocity with the body number as suffix, momentum, min_gap). Plain CSV only, as
// the CLI: a world refuses the semicolon dialect and the workbook there too.

#include <QString>

class QWidget;

namespace elui {

class SimulationController;

// Writes the world's run so far to `path` (atomically, as every export). Returns the error
// naming the file, or empty; `rows` gets the number of rows written.
QString writeWorldCsv(const QString& path, SimulationController& controller, int* rows = nullptr);

struct WorldExportResult {
    QString error;   // shown as a warning
    QString done;    // for the status bar; both empty: cancelled
};
// Asks for the file (CSV only) and writes it.
WorldExportResult exportWorldCsv(QWidget* parent, SimulationController& controller);

}  // namespace elui
