#pragma once
// Output: the CSV time series and state tables, written atomically.
//
// A file is written to a temporary sibling and renamed over the target only when complete
// (POSIX rename is atomic): a failed or interrupted write leaves any existing file untouched
// and no partial file behind. The sibling is an unnamed O_TMPFILE file until the commit, so
// even a killed process (SIGKILL, power loss before the commit) leaves nothing behind; at the
// commit it gets a random name (never pid-derived, never one that exists, 30 bytes whatever
// the target's length). A standard stream (/dev/stdout, /dev/fd/N) and a character device
// (/dev/full, a terminal) are written in place; a FIFO, socket or folder is refused.

#include <cstdio>
#include <functional>
#include <optional>
#include <utility>
#include <string>
#include <string_view>
#include <vector>

#include "simcore/simulation.h"
#include "simcore/world.h"

namespace simlab {

class AtomicFile {
public:
    explicit AtomicFile(std::string path);
    ~AtomicFile();  // discards the temporary file unless committed
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    bool ok() const { return m_error.empty(); }
    const std::string& error() const { return m_error; }
    const std::string& path() const { return m_path; }
    bool write(std::string_view text);
    // Flushes, syncs and renames into place. False (with error()) on any failure. A command
    // with several outputs commits them together (commitAll).
    bool commit();
    // The two halves of commit: prepare flushes, syncs, sets owner then mode and gives the
    // file its temporary name beside the target; publish renames it over the target.
    bool prepare();
    bool publish();

private:
    void fail(const std::string& what);
    std::string m_path;
    std::string m_target;    // the file renamed over (m_path, or what its symlink points to); empty: in place
    std::string m_folder;    // the target's folder
    std::string m_tempPath;  // the named temporary file, once it has a name
    bool m_unnamed = false;  // writing an O_TMPFILE file that has no name yet
    bool m_prepared = false;
    std::FILE* m_file = nullptr;
    std::string m_error;
    bool m_committed = false;
};

// All or none: every file is prepared (complete, synced, named beside its target) before the
// first is renamed into place, so a failure of any (a full disk, /dev/full) leaves every
// existing file byte-identical. Null entries are skipped. Returns the first failure's message.
std::optional<std::string> commitAll(const std::vector<AtomicFile*>& files);

// Text for XML (SVG titles, labels, legends): & < > " ' as entities, control bytes XML does not
// allow (all below 0x20 but tab, newline, return) as U+FFFD. A title with "&" or "<" broke the
// plot before.
std::string xmlEscaped(std::string_view text);

// A path that names an open standard stream or descriptor (/dev/stdout, /dev/stderr,
// /dev/fd/N, /proc/self/fd/N): its descriptor, written in place; otherwise nullopt.
std::optional<int> standardStream(const std::string& path);

// Outputs never overwrite an input or each other (issue 18): the files named, as (option, path)
// pairs with inputs first and empty paths skipped, compared by identity, not by spelling (device
// and inode of an existing file, or of the folder a new one goes in and its name, so links, "./"
// and ".." count). Returns the message naming both options for the first clash.
std::optional<std::string> fileClash(const std::vector<std::pair<std::string, std::string>>& inputsThenOutputs);

// One CSV column: its header name, how to read it from the diagnostics, and its SI unit ("" for
// counts and orders; the .xlsx header shows it as "name [unit]", the CSV header never does).
struct CsvColumn {
    std::string name;
    std::function<double(const simcore::Diagnostics&)> value;
    std::string unit = {};
};

// How a CSV file is spelled (docs/teachers.md, "Spreadsheets"):
//   plain            comma, decimal point, LF, no byte-order mark: the documented format every
//                    script reads (the default);
//   excel-semicolon  semicolon, decimal comma, CRLF and a UTF-8 byte-order mark: what a spreadsheet
//                    in a locale with a decimal comma (German, French, Spanish, ...) opens with a
//                    double-click into columns of numbers. The values are the same shortest
//                    round-trip texts, only '.' is written ','.
enum class CsvDialect { Plain, ExcelSemicolon };
inline constexpr std::string_view kCsvDialectNames = "plain, excel-semicolon";
std::optional<CsvDialect> csvDialectNamed(std::string_view name);
// "csv dialect 'NAME' is unknown; one of plain, excel-semicolon" (CLI and Python say the same).
std::string unknownCsvDialectMessage(std::string_view name);
std::string_view csvDialectName(CsvDialect dialect);
// A plain-dialect CSV text (whole lines, numbers and bare words only) as `dialect` spells it;
// fileStart: the text opens the file (gets the byte-order mark).
std::string inDialect(std::string plain, CsvDialect dialect, bool fileStart);

// The time-series columns of a scene: only what the scene has (no gas columns in 1D). With
// solverCounters (a CVODE integrator: simcore::Diagnostics::hasSolverCounters) the solver's cumulative
// counters follow: force_evals (every force evaluation and every Jacobian-vector product),
// solver_steps, rhs_evals, jac_products, linear_iterations, precond_iterations,
// nonlinear_iterations, error_test_failures, convergence_failures, reinits, order, step_size.
std::vector<CsvColumn> timeSeriesColumns(simcore::SceneKind kind, bool solverCounters = false);
// The time series' columns plotted against t in an .xlsx workbook's charts (energy, volume,
// pressure), with the axis's title; only what the scene has (a 1D scene has no gas).
struct ChartSpec {
    std::string title, axis;
    std::vector<std::string> columns;
};
std::vector<ChartSpec> timeSeriesCharts(simcore::SceneKind kind);
std::string csvHeader(const std::vector<CsvColumn>& columns);
// "name [unit]", or the name alone for a column without a unit.
std::string headerWithUnit(const CsvColumn& column);
std::string csvRow(const std::vector<CsvColumn>& columns, const simcore::Diagnostics& d);
// Shortest text that reads back to the same double.
std::string formatDouble(double value);

// index,layer,x,y,z,vx,vy,vz: one row per particle.
std::string stateTable(const simcore::Simulation& sim);

// The time series of a world of several bodies (simcore/world.h): step, t, dt, the energies of
// the whole world and its ledger, the error estimate; then per body N (from 1) volume_inner_N,
// volume_outer_N, pressure_inner_N, pressure_outer_N, com_x_N, com_y_N[, com_z_N],
// velocity_x_N, velocity_y_N[, velocity_z_N] (the centre of mass and its velocity; z only in
// 3D); then momentum_x, momentum_y[, momentum_z], angular_momentum_z (3D: _x, _y, _z) and
// min_gap, the smallest distance between two bodies' outer surfaces or two non-adjacent
// elements of one [m] (exact up to simcore::World::gapRange()).
struct WorldCsvColumn {
    std::string name;
    std::function<double(const simcore::WorldDiagnostics&)> value;
};
std::vector<WorldCsvColumn> worldColumns(const simcore::World& world);
// The same for a world of `bodyCount` bodies in `dimension` (2 or 3) dimensions.
std::vector<WorldCsvColumn> worldColumns(int dimension, int bodyCount);
std::string csvHeader(const std::vector<WorldCsvColumn>& columns);
std::string csvRow(const std::vector<WorldCsvColumn>& columns, const simcore::WorldDiagnostics& d);
// index,body,layer,x,y,z,vx,vy,vz: one row per particle, the body numbered from 1 and the
// index the particle's within its body.
std::string stateTable(const simcore::World& world);

}  // namespace simlab
