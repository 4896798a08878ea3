// `sweep`: a parameter grid (simlab/sweep.h), one CSV row per point, restartable.
//
// Rows go to a journal, OUT.partial, as each point ends (one write per row, so a kill -9 leaves
// at most a torn last line, which --resume drops). Its first line is the sweep's fingerprint
// (the spec, the shard and the lab's version): --resume refuses a journal of another sweep.
// When every point of the shard is done, OUT is written atomically in grid order and the
// journal removed. `--csv -` streams the rows to standard output in grid order (no journal).
//
// Ctrl+C and SIGTERM (issue 31) cancel the point running (its row is not kept: a point cut
// short is not a result) and stop: the journal keeps every whole row, OUT is not written (an
// existing OUT keeps its bytes), and the message says how to go on (--resume); exit 130 / 143.
// With --csv - the rows already streamed stay; none is cut.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>

#include "app/cli/cli.h"
#include "elastic_lab_version.h"
#include "simlab/output.h"
#include "simlab/sweep.h"

namespace cli {

namespace {

struct SweepArgs {
    SceneArgs scene;
    std::vector<std::string> grid;
    std::optional<std::string> metrics, shard;
    double duration = 1.0;
    double maxSteps = simlab::kSweepDefaultMaxSteps;
    std::string csv;
    bool resume = false, quiet = false;
    simcore::IntegratorOptions integrator;
    // After check():
    simlab::SweepSpec spec;
    std::pair<int, int> shardOf{0, 1};
};

// KEY=v1,v2,... or KEY=lin:A:B:N, KEY=log:A:B:N, KEY=decades:A:B:K.
void addGridAxis(simlab::SweepSpec& spec, const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw UsageError("--grid: expected KEY=v1,v2,... (or KEY=lin:A:B:N, log:A:B:N, decades:A:B:K), got " +
                         simcore::quoteShort(text));
    const std::string key = text.substr(0, eq), values = text.substr(eq + 1);
    const simcore::ParamSpec* p = simcore::findParam(key);
    if (!p || !spec.params.has(p->id)) {
        simcore::ParameterSet probe = spec.params;
        throw UsageError("--grid " + probe.set(key, 0.0).value_or(key + " is not a parameter of this scene"));
    }
    std::vector<double> axis;
    for (const char* kind : {"lin:", "log:", "decades:"}) {
        if (!values.starts_with(kind)) continue;
        std::vector<double> abn;
        std::string rest = values.substr(std::string(kind).size());
        for (std::size_t start = 0;;) {
            const auto colon = rest.find(':', start);
            const auto v = simcore::parseNumber(rest.substr(start, colon == std::string::npos ? colon : colon - start));
            if (!v) throw UsageError("--grid " + key + ": " + simcore::quoteShort(values) + " is not A:B:N with numbers");
            abn.push_back(*v);
            if (colon == std::string::npos) break;
            start = colon + 1;
        }
        if (abn.size() != 3) throw UsageError("--grid " + key + ": " + simcore::quoteShort(values) + " is not A:B:N");
        const std::string name = std::string(kind) == "lin:" ? "linear" : std::string(kind).substr(0, std::string(kind).size() - 1);
        simlab::SweepRange range = simlab::sweepRange(name, abn[0], abn[1], abn[2]);
        if (!range.error.empty()) throw UsageError("--grid " + key + ": " + range.error);
        axis = std::move(range.values);
    }
    if (axis.empty())
        for (const std::string& item : nameList("grid " + key, values)) {
            const auto v = simcore::parseValue(*p, item);
            if (!v) {
                simcore::ParameterSet probe = spec.params;
                throw UsageError("--grid " + probe.setFromText(key, item).value_or(key + ": bad value " + simcore::quoteShort(item)));
            }
            axis.push_back(*v);
        }
    spec.keys.push_back(key);
    spec.axes.push_back(std::move(axis));
}

void checkSweep(SweepArgs& args) {
    if (args.csv.empty()) throw UsageError("--csv is required: the file the rows go to, or - for standard output");
    if (args.resume && args.csv == "-") throw UsageError("--resume needs a file for --csv (the journal lives beside it)");
    if (args.csv != "-") checkFiles({{"scene", sceneFileOf(args.scene)}}, {{"csv", args.csv}});
    const SceneSetup setup = sceneSetup(args.scene);
    simlab::SweepSpec& spec = args.spec;
    spec.sceneName = setup.sceneName;
    spec.params = setup.params;
    spec.integrator = setup.integrator;
    spec.options = args.integrator;
    spec.state = setup.state;
    spec.duration = args.duration;
    spec.maxSteps = args.maxSteps;
    for (const std::string& g : args.grid) addGridAxis(spec, g);
    if (args.metrics) spec.metrics = nameList("metrics", *args.metrics);
    simlab::checkSweep(spec);
    if (args.shard) args.shardOf = parseShard(*args.shard);
}

// FNV-1a, 64 bits: the journal's fingerprint of a sweep.
std::string fingerprint(const std::string& text) {
    std::uint64_t h = 1469598103934665603ULL;
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ULL;
    char out[24];
    std::snprintf(out, sizeof out, "%016" PRIx64, h);
    return out;
}

// The progress line on stderr: rewritten in place on a terminal, else a line per tenth.
class Progress {
public:
    Progress(long total, bool quiet) : m_total(total), m_quiet(quiet), m_tty(isatty(2) != 0) {}
    void done(const simlab::SweepRow& row) {
        ++m_done;
        m_failed += row.status == "failed";
        m_over += row.status == "over budget";
        if (m_quiet) return;
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
        const long tenth = m_total ? m_done * 10 / m_total : 10;
        if (!m_tty && tenth == m_lastTenth && m_done != m_total) return;
        m_lastTenth = tenth;
        std::fprintf(stderr, "%ssweep: %ld/%ld points, %ld failed, %ld over budget, %.1f s, about %.0f s left%s",
                     m_tty ? "\r" : "", m_done, m_total, m_failed, m_over, wall,
                     m_done ? wall / static_cast<double>(m_done) * static_cast<double>(m_total - m_done) : 0.0,
                     m_tty && m_done != m_total ? "  " : "\n");
        std::fflush(stderr);
    }

    // Before a message: ends a line left open on a terminal.
    void interrupt() {
        if (m_tty && !m_quiet && m_done > 0 && m_done != m_total) std::fputc('\n', stderr);
    }

private:
    long m_total, m_done = 0, m_failed = 0, m_over = 0, m_lastTenth = -1;
    bool m_quiet, m_tty;
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

bool writeAll(int fd, const std::string& text) {
    std::size_t off = 0;
    while (off < text.size()) {
        const ssize_t n = ::write(fd, text.data() + off, text.size() - off);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        off += static_cast<std::size_t>(n);
    }
    return true;
}

// Test hook: ELASTIC_LAB_TEST_SWEEP_STOP_AFTER=K stops the process (SIGSTOP) after K new rows,
// so that a test can kill or interrupt the sweep at a point it chooses instead of racing it.
void testStopHook(long computed) {
    static const char* stopAfter = std::getenv("ELASTIC_LAB_TEST_SWEEP_STOP_AFTER");
    if (stopAfter && computed == std::atol(stopAfter)) ::raise(SIGSTOP);
}

// The end of a sweep stopped by a signal: what was kept and how to go on; 128 + the signal.
int stopped(const StopSignals& signals, long done, long total, const std::string& journal) {
    std::fprintf(stderr, "sweep stopped by %s after %ld of %ld points; ", StopSignals::name(signals.caught()), done, total);
    if (journal.empty())
        std::fprintf(stderr, "the rows above are whole\n");
    else
        std::fprintf(stderr, "the journal %s holds them: run the same command with --resume to go on\n",
                     simcore::quoteShort(journal, 200).c_str());
    return 128 + signals.caught();
}

// `--csv -`: the rows streamed in grid order, nothing to resume.
int streamSweep(const simlab::SweepSpec& spec, long begin, long end, const std::string& header, bool quiet) {
    const StopSignals signals;
    Progress progress(end - begin, quiet);
    std::fputs(header.c_str(), stdout);
    for (long i = begin; i < end; ++i) {
        const simlab::SweepRow row = simlab::runSweepPoint(spec, i, signals.flag());
        if (signals.caught()) {
            progress.interrupt();
            return stopped(signals, i - begin, end - begin, {});
        }
        std::fputs(simlab::sweepCsvRow(spec, row).c_str(), stdout);
        std::fflush(stdout);
        progress.done(row);
        testStopHook(i + 1 - begin);
    }
    return kExitOk;
}

// --resume: the rows of this shard a journal already holds (into `rows`), and how many of its
// bytes hold whole lines of them after `head` (0 without a journal). A journal of another
// sweep is refused.
long readJournal(const std::string& journalPath, const std::string& head, long begin, long end,
                 std::map<long, std::string>& rows) {
    std::ifstream in(journalPath, std::ios::binary);
    if (!in) return 0;
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!text.starts_with(head))
        throw UsageError("--resume: " + simcore::quoteShort(journalPath, 200) +
                         " was written by another sweep (scene, grid, duration, metrics, options, shard or "
                         "version differ); delete it or run without --resume");
    long keep = static_cast<long>(head.size());
    for (std::size_t at = static_cast<std::size_t>(keep);;) {
        const auto nl = text.find('\n', at);
        if (nl == std::string::npos) break;  // a torn last line (killed while writing it)
        const std::string line = text.substr(at, nl + 1 - at);
        const auto index = simlab::sweepCsvRowIndex(line);
        if (!index || *index < begin || *index >= end) break;  // not a row of ours: drop it and the rest
        rows[*index] = line;
        at = nl + 1;
        keep = static_cast<long>(at);
    }
    return keep;
}

int runSweep(const SweepArgs& args) {
    const simlab::SweepSpec& spec = args.spec;
    const auto [begin, end] = simlab::sweepShard(spec, args.shardOf.first, args.shardOf.second);
    const std::string header = simlab::sweepCsvHeader(spec);
    long total = end - begin;

    if (args.csv == "-") return streamSweep(spec, begin, end, header, args.quiet);

    // The final file is opened first: an unwritable path is bad input before any work.
    simlab::AtomicFile out(args.csv);
    if (!out.ok()) throw UsageError(out.error());
    const std::string journalPath = args.csv + ".partial";
    const std::string stamp = "# elastic-lab sweep " +
                              fingerprint(simlab::sweepSpecText(spec) + " shard " + std::to_string(args.shardOf.first) + "/" +
                                          std::to_string(args.shardOf.second) + " " + elastic_lab::kVersion) + "\n";
    std::map<long, std::string> rows;  // index -> CSV line
    // Bytes of the journal that hold whole lines.
    const long keep = args.resume ? readJournal(journalPath, stamp + header, begin, end, rows) : 0;
    const int fd = ::open(journalPath.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0 || ::ftruncate(fd, keep) != 0 || ::lseek(fd, 0, SEEK_END) < 0 ||
        (keep == 0 && !writeAll(fd, stamp + header))) {
        if (fd >= 0) ::close(fd);
        throw UsageError("cannot write the journal " + simcore::quoteShort(journalPath, 200) + ": " + std::strerror(errno));
    }
    if (args.resume && !args.quiet)
        std::fprintf(stderr, "sweep: resuming, %zu of %ld points already done\n", rows.size(), total);

    long computed = 0;
    const StopSignals signals;
    Progress progress(total - static_cast<long>(rows.size()), args.quiet);
    for (long i = begin; i < end; ++i) {
        if (rows.count(i)) continue;
        const simlab::SweepRow row = simlab::runSweepPoint(spec, i, signals.flag());
        if (signals.caught()) {  // the point was cut short (or not started): not a row
            ::close(fd);
            progress.interrupt();
            return stopped(signals, static_cast<long>(rows.size()), total, journalPath);
        }
        const std::string line = simlab::sweepCsvRow(spec, row);
        if (!writeAll(fd, line)) {
            ::close(fd);
            std::fprintf(stderr, "error: cannot write the journal %s: %s\n", simcore::quoteShort(journalPath, 200).c_str(),
                         std::strerror(errno));
            return kExitBadInput;
        }
        rows[i] = line;
        progress.done(row);
        testStopHook(++computed);
    }
    ::close(fd);
    out.write(header);
    for (const auto& [index, line] : rows) out.write(line);
    if (!out.commit()) {
        std::fprintf(stderr, "error: %s\n", out.error().c_str());
        return kExitBadInput;
    }
    ::unlink(journalPath.c_str());
    return kExitOk;
}

}  // namespace

Command addSweepCommand(CLI::App& app) {
    auto args = std::make_shared<SweepArgs>();
    CLI::App* sub = app.add_subcommand(
        "sweep", "run a parameter grid: one CSV row per point (parameters, status, metrics); restartable with --resume, "
                 "split with --shard");
    addSceneOptions(*sub, args->scene);
    sub->add_option("--grid", args->grid, "a swept parameter and its values (repeatable; the first varies slowest): "
                                          "KEY=v1,v2,..., KEY=lin:A:B:N, KEY=log:A:B:N or KEY=decades:A:B:K")
        ->type_name("KEY=VALUES")
        ->allow_extra_args(false);
    sub->add_option("--duration", args->duration, "simulated time per point [s]")
        ->type_name("T")
        ->check(finiteIn(0.0, 1e7, true))
        ->capture_default_str();
    sub->add_option("--csv", args->csv, "the rows, in grid order (- for standard output)")->type_name("FILE|-");
    sub->add_option("--metrics", args->metrics, "the metric columns (default: every one the scene has; "
                                                "docs/sweeps.md lists them)")
        ->type_name("LIST");
    sub->add_option("--max-steps", args->maxSteps, "a point needing more steps is 'over budget' (not run, or stopped)")
        ->type_name("N")
        ->check(finiteIn(1.0, simlab::kMaxSteps, false))
        ->default_str("1e8");
    sub->add_option("--shard", args->shard, "run only block K of N of the grid (an array job); the shards' rows "
                                            "concatenate into the whole sweep's")
        ->type_name("K/N");
    sub->add_flag("--resume", args->resume, "go on from OUT.partial, the journal a killed sweep left: only the missing "
                                            "points are run");
    sub->add_flag("--quiet", args->quiet, "no progress line on standard error");
    addIntegratorOptions(*sub, args->integrator);
    return {sub, [args] { checkSweep(*args); }, [args] { return runSweep(*args); }};
}

}  // namespace cli
