#pragma once
// Output: the CSV time series and state tables, written atomically.
//
// A file is written to a temporary sibling and renamed over the target only when complete
// (POSIX rename is atomic): a failed or interrupted write leaves any existing file untouched
// and no partial file behind. The sibling is an unnamed O_TMPFILE file until the commit, so
// even a killed process (SIGKILL, power loss before the commit) leaves nothing behind. A target that is not a regular file (a device such as
// /dev/stdout or /dev/full, a pipe) is written in place, since it cannot be renamed over.

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
    // Flushes, syncs and renames into place. False (with error()) on any failure.
    bool commit();

private:
    void fail(const std::string& what);
    std::string m_path;
    std::string m_target;    // the file renamed over (m_path, or what its symlink points to)
    std::string m_tempPath;  // empty when writing in place to a device or pipe
    bool m_unnamed = false;  // writing an O_TMPFILE file that has no name yet
    std::FILE* m_file = nullptr;
    std::string m_error;
    bool m_committed = false;
};

// Outputs never overwrite an input or each other (issue 18): the files named, as (option, path)
// pairs with inputs first and empty paths skipped, compared by identity, not by spelling (device
// and inode of an existing file, or of the folder a new one goes in and its name, so links, "./"
// and ".." count). Returns the message naming both options for the first clash.
std::optional<std::string> fileClash(const std::vector<std::pair<std::string, std::string>>& inputsThenOutputs);

// One CSV column: its header name and how to read it from the diagnostics.
struct CsvColumn {
    std::string name;
    std::function<double(const simcore::Diagnostics&)> value;
};

// The time-series columns of a scene: only what the scene has (no gas columns in 1D). With
// solverCounters (a CVODE integrator: simcore::Diagnostics::hasSolverCounters) the solver's cumulative
// counters follow: force_evals (every force evaluation and every Jacobian-vector product),
// solver_steps, rhs_evals, jac_products, linear_iterations, precond_iterations,
// nonlinear_iterations, error_test_failures, convergence_failures, reinits, order, step_size.
std::vector<CsvColumn> timeSeriesColumns(simcore::SceneKind kind, bool solverCounters = false);
std::string csvHeader(const std::vector<CsvColumn>& columns);
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
std::string csvHeader(const std::vector<WorldCsvColumn>& columns);
std::string csvRow(const std::vector<WorldCsvColumn>& columns, const simcore::WorldDiagnostics& d);
// index,body,layer,x,y,z,vx,vy,vz: one row per particle, the body numbered from 1 and the
// index the particle's within its body.
std::string stateTable(const simcore::World& world);

}  // namespace simlab
