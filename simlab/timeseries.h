#pragma once
// The time series of a run, written to the files asked for: a CSV table in a dialect and an
// .xlsx workbook. The CLI's `run --csv/--xlsx`, the Python module's Simulation.run(csv=, xlsx=)
// and the GUI's export all write through TimeSeriesWriter, so the three doors give the same files.
//
// The workbook (libxlsxwriter, Debian libxlsxwriter-dev):
//   sheet "run"     the table: one header row "name [unit]" (bold, frozen), then one row per
//                   record; numbers are native cells (no text to parse, no decimal separator);
//   sheet "charts"  native scatter charts against t: energy (kinetic, spring, gravity, gas,
//                   total), and for the layered scenes volume (area in 2D) and pressure, inner
//                   and outer, each series reading the table's columns (edit a cell, the chart
//                   follows).
// Numbers carry 16 significant digits (libxlsxwriter writes "%.16G"; Excel shows 15): they agree
// with the CSV's shortest round-trip texts to about 1e-16 relative, not always bit for bit.
// A sheet holds at most 1048576 rows: a longer series is refused with a message naming
// --every (CLI) / every= (Python). The workbook is written with libxlsxwriter's constant-memory
// mode (a row goes to a temporary file as it is added), then moved through AtomicFile: a
// failed write leaves any existing file untouched.

#include <memory>
#include <string>
#include <vector>

#include "simlab/output.h"

namespace simlab {

struct TimeSeriesFiles {
    std::string csv;                            // "" = none
    CsvDialect dialect = CsvDialect::Plain;     // of the CSV
    std::string xlsx;                           // "" = none
    bool any() const { return !csv.empty() || !xlsx.empty(); }
};

// The most data rows an .xlsx sheet takes (1048576 rows, one of them the header).
inline constexpr long kXlsxMaxDataRows = 1048575;

class TimeSeriesWriter {
public:
    // Opens every file at once: an unwritable path shows in error() before any run.
    TimeSeriesWriter(simcore::SceneKind kind, std::vector<CsvColumn> columns, TimeSeriesFiles files);
    ~TimeSeriesWriter();
    TimeSeriesWriter(const TimeSeriesWriter&) = delete;
    TimeSeriesWriter& operator=(const TimeSeriesWriter&) = delete;

    bool ok() const { return m_error.empty(); }
    // The first failure, naming the file; empty while all is well.
    const std::string& error() const { return m_error; }
    const std::vector<CsvColumn>& columns() const { return m_columns; }
    long rows() const { return m_rows; }

    // One record (one CSV line, one sheet row).
    void add(const simcore::Diagnostics& d);
    // Finishes and renames every file into place. False (with error()) on any failure, and then
    // no file named is replaced by a partial one.
    bool commit();
    // The two halves of commit, for a command with other outputs (commitAll): finish completes
    // the workbook into its file (nothing renamed); files() are then the files to commit.
    bool finish();
    std::vector<AtomicFile*> files();

private:
    class Xlsx;
    void fail(const std::string& message);
    simcore::SceneKind m_kind;
    std::vector<CsvColumn> m_columns;
    TimeSeriesFiles m_files;
    std::unique_ptr<AtomicFile> m_csv;
    std::unique_ptr<Xlsx> m_xlsx;
    long m_rows = 0;
    std::string m_error;
};

}  // namespace simlab
