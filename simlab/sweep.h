#pragma once
// Parameter sweeps: one scene, a few of its parameters varied over a grid (the Cartesian product
// of a list of values per key, or explicit points such as random samples), each point run for
// the same duration in a fresh simulation and reduced to one row of metrics.
//
// A point is a pure function of the spec and its index: the same row (wall time aside) whichever
// process, machine or order runs it. So the CLI's `sweep` (shards, --resume) and Python's
// elasticlab.sweep (any executor, Dask) both enumerate points here and call runSweepPoint; the
// spec travels between processes as text (sweepSpecText / parseSweepSpec), which embeds the
// scene file format for the base scene.
//
// Status of a row: "ok"; "failed" (the simulation failed: blow-up, a layer turned inside out;
// the reason says what, when); "over budget" (the run would take, or took, more than maxSteps
// steps). Metrics of a row that did not finish are those of the part that ran (NaN where that
// part has none).

#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "simcore/integrators.h"
#include "simcore/params.h"
#include "simlab/scenefile.h"

namespace simlab {

// The most points one sweep may hold, and the most steps one point may take by default.
inline constexpr double kMaxSweepPoints = 1e7;
inline constexpr double kSweepDefaultMaxSteps = 1e8;

struct SweepSpec {
    std::string sceneName;                    // built-in scene name
    simcore::ParameterSet params;             // the base: a scene file's values, then fixed keys
    std::string integrator = "rk4";
    simcore::IntegratorOptions options;
    std::optional<SceneFile::State> state;    // a scene file's saved state (every point starts there)
    std::vector<std::string> keys;            // the varied parameters, in column order
    std::vector<std::vector<double>> axes;    // product mode: the values of each key (first key slowest)
    std::vector<std::vector<double>> points;  // explicit mode (when not empty): one value per key per point
    double duration = 1.0;                    // simulated time per point [s]
    std::vector<std::string> metrics;         // empty: every metric the scene has
    double maxSteps = kSweepDefaultMaxSteps;  // a point needing more steps is "over budget"
};

// Every metric of a scene, in column order (only what the scene has: no volumes in 1D).
//   volume_{inner,outer}_{final,min,max}, pressure_{inner,outer}_{final,min,max}   [area m^2 in 2D,
//                   volume m^3 in 3D; pressure N/m in 2D, N/m^2 in 3D], over every step
//   energy_kinetic_final, energy_total_final, energy_drift_final [J], energy_drift_max [J] (largest |drift|)
//   bounce_time [s], bounce_height [m]: the first bounce on the floor: the first step at which the
//                   centre of mass moves up again after a particle touched the floor, and the
//                   highest the centre of mass then rises above the floor (its apex; NaN when the
//                   run ends before it, or without a bounce)
//   strain_max      largest |L/L0 - 1| of any spring over every step
//   t_end [s], steps, force_evals, wall_seconds [s]
std::vector<std::string> sweepMetricNames(simcore::SceneKind kind);

// The one check of a sweep request (the CLI and Python call it before anything runs): the
// scene's keys, every value of every axis through the parameter table, every point's shape with
// the integrator, duration, metrics, the number of points. On success, empty metrics become the
// scene's full list. Returns the message (the CLI's, Python's ValueError) or nothing.
std::optional<std::string> validateSweep(SweepSpec& spec);

// Ranges of values (the CLI's lin:A:B:N, log:A:B:N, decades:A:B:K; Python's linear, log,
// decades), computed here so that both doors give the same bits:
//   linear   N values from A to B evenly spaced, both ends included (N >= 2; N = 1: A)
//   log      N values from A to B evenly spaced in log (A, B > 0), both ends exact
//   decades  K values per decade from A while <= B (A, B > 0): A * 10^(i/K); A*10^j exact
struct SweepRange {
    std::vector<double> values;
    std::string error;  // set when the range is not allowed
};
SweepRange sweepRange(std::string_view kind, double a, double b, double n);

long sweepPointCount(const SweepSpec& spec);
// The values of point `index` (0-based, grid order: the first key varies slowest).
std::vector<double> sweepPoint(const SweepSpec& spec, long index);
// The points [begin, end) shard K (0-based) of N runs: contiguous blocks in grid order.
std::pair<long, long> sweepShard(const SweepSpec& spec, int shardIndex, int shardCount);

struct SweepRow {
    long index = 0;
    std::vector<double> values;   // one per key
    std::string status = "ok";    // ok | failed | over budget
    std::string reason;           // empty when ok
    std::vector<double> metrics;  // one per spec.metrics
};

// Runs point `index` from the start (a fresh simulation). Stops early when *cancel turns true
// (the row then says so: status "failed", reason "cancelled").
SweepRow runSweepPoint(const SweepSpec& spec, long index, const std::atomic<bool>* cancel = nullptr);

// The columns of every row: index, the keys, integrator, status, reason, the metrics, version.
std::vector<std::string> sweepColumns(const SweepSpec& spec);
// A value of key `key` as the CSV and the DataFrame show it: a choice by its name, else a number.
std::string sweepValueText(const std::string& key, double value);
std::string sweepCsvHeader(const SweepSpec& spec);
std::string sweepCsvRow(const SweepSpec& spec, const SweepRow& row);
// The first field of a CSV row written by sweepCsvRow (its index), or nothing.
std::optional<long> sweepCsvRowIndex(const std::string& line);

// The spec as JSON text and back (exact: numbers in shortest round-trip form). The base scene is
// a scene file (scenefile.h) inside it.
std::string sweepSpecText(const SweepSpec& spec);
struct SweepSpecResult {
    std::optional<SweepSpec> spec;
    std::string error;
};
SweepSpecResult parseSweepSpec(const std::string& text);

}  // namespace simlab
