#include "simlab/output.h"

#include <sys/stat.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

#include <fcntl.h>
#include <unistd.h>

namespace simlab {

using simcore::Diagnostics;
using simcore::SceneKind;
using simcore::Simulation;
using simcore::hasGas;
using simcore::layerName;
using simcore::quoteShort;

std::optional<int> standardStream(const std::string& path) {
    if (path == "/dev/stdout") return 1;
    if (path == "/dev/stderr") return 2;
    for (std::string_view prefix : {"/dev/fd/", "/proc/self/fd/"}) {
        if (path.rfind(prefix, 0) != 0) continue;
        const std::string_view digits = std::string_view(path).substr(prefix.size());
        int fd = -1;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), fd);
        if (ec != std::errc() || end != digits.data() + digits.size() || fd < 0) return std::nullopt;
        if (::fcntl(fd, F_GETFD) < 0) return std::nullopt;  // not open: an ordinary (failing) path
        return fd;
    }
    return std::nullopt;
}

namespace {

// A temporary name in `folder` that no file has: ".elastic-lab-" and 16 random hex digits
// (30 bytes, so it fits beside a target of any legal name length), never derived from the pid
// (as pid 1 in a container, a pid-derived name is the same in every run).
std::string randomSibling(const std::string& folder) {
    static std::mt19937_64 rng{std::random_device{}() ^ static_cast<std::uint64_t>(::getpid()) << 32};
    char name[40];
    std::snprintf(name, sizeof name, ".elastic-lab-%016llx.tmp", static_cast<unsigned long long>(rng()));
    return ((folder.empty() ? std::filesystem::path(".") : std::filesystem::path(folder)) / name).string();
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : m_path(std::move(path)) {
    if (m_path.empty()) {
        fail("empty file name");
        return;
    }
    // A standard stream (/dev/stdout, /dev/fd/N, /proc/self/fd/N) is written in place through
    // its open descriptor: never followed to the file behind it (`>> log.txt` would be
    // replaced), never truncated.
    if (const auto fd = standardStream(m_path)) {
        const int copy = ::fcntl(*fd, F_DUPFD_CLOEXEC, 3);
        m_file = copy >= 0 ? ::fdopen(copy, "wb") : nullptr;
        if (!m_file) {
            if (copy >= 0) ::close(copy);
            fail(std::strerror(errno));
        }
        return;
    }
    namespace fs = std::filesystem;
    std::error_code ec;
    struct stat st {};
    if (::stat(m_path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        if (!S_ISCHR(st.st_mode)) {  // a FIFO would block, a folder or socket holds no table
            fail(S_ISDIR(st.st_mode) ? "is a folder" : S_ISFIFO(st.st_mode) ? "is a FIFO; an output is a regular file or a device"
                                                                            : "not a regular file or a device");
            return;
        }
        // A device (/dev/null, /dev/full, a terminal) cannot be replaced by a rename: written in
        // place; errors still surface at flush and are reported.
        m_file = std::fopen(m_path.c_str(), "wb");
        if (!m_file) fail(std::strerror(errno));
        return;
    }
    // Write beside the real file (through a symlink, not over it), then rename into place.
    std::string target = m_path;
    if (fs::is_symlink(fs::symlink_status(m_path, ec))) target = fs::canonical(m_path, ec).string();
    if (ec || target.empty()) target = m_path;
    m_target = target;
    m_folder = fs::path(target).parent_path().string();
    // An unnamed file in the target's folder (O_TMPFILE): if the process is killed before the
    // commit, the kernel drops it and nothing is left behind. It gets a temporary name only at
    // the commit, just before the rename. Filesystems without O_TMPFILE get a named temporary
    // file from the start, created with O_EXCL under a fresh random name (removed on any
    // failure we live through).
    const int fd = ::open(m_folder.empty() ? "." : m_folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    if (fd >= 0) {
        m_file = ::fdopen(fd, "wb");
        if (!m_file) ::close(fd);
        m_unnamed = m_file != nullptr;
    }
    for (int attempt = 0; !m_file && attempt < 100; ++attempt) {
        m_tempPath = randomSibling(m_folder);
        const int named = ::open(m_tempPath.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0666);
        if (named < 0) {
            m_tempPath.clear();
            if (errno == EEXIST) continue;
            break;
        }
        m_file = ::fdopen(named, "wb");
        if (!m_file) {
            ::close(named);
            std::remove(m_tempPath.c_str());
            m_tempPath.clear();
            break;
        }
    }
    if (!m_file) fail(std::strerror(errno));
}

AtomicFile::~AtomicFile() {
    if (m_file) std::fclose(m_file);
    if (!m_committed && !m_tempPath.empty()) std::remove(m_tempPath.c_str());
}

void AtomicFile::fail(const std::string& what) {
    if (m_error.empty()) m_error = "cannot write " + quoteShort(m_path, 200) + ": " + what;
}

bool AtomicFile::write(std::string_view text) {
    if (!ok() || !m_file) return false;
    if (std::fwrite(text.data(), 1, text.size(), m_file) != text.size()) {
        fail(std::strerror(errno));
        return false;
    }
    return true;
}

bool AtomicFile::prepare() {
    if (m_prepared) return true;
    if (!ok() || !m_file) return false;
    const bool inPlace = m_target.empty();
    if (std::fflush(m_file) != 0 || std::ferror(m_file) || (!inPlace && ::fsync(::fileno(m_file)) != 0)) {
        fail(std::strerror(errno));
        return false;
    }
    if (!inPlace) {
        // A replaced file keeps its owner and group where the process may set them (root, or
        // its own group), then its mode: in that order, since a change of owner clears the
        // setuid and setgid bits (a 4755 program stays 4755, a 600 file stays 600).
        struct stat old {};
        if (::stat(m_target.c_str(), &old) == 0 && S_ISREG(old.st_mode)) {
            [[maybe_unused]] const int owned = ::fchown(::fileno(m_file), old.st_uid, old.st_gid);  // EPERM: keep ours
            if (::fchmod(::fileno(m_file), old.st_mode & 07777) != 0) {
                fail(std::strerror(errno));
                return false;
            }
        }
        // Give the unnamed file a temporary name (through /proc, which needs no privilege): a
        // fresh random one, again on EEXIST; an existing file is never removed or replaced.
        if (m_unnamed) {
            const std::string self = "/proc/self/fd/" + std::to_string(::fileno(m_file));
            int linked = -1;
            for (int attempt = 0; attempt < 100 && linked != 0; ++attempt) {
                m_tempPath = randomSibling(m_folder);
                linked = ::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, m_tempPath.c_str(), AT_SYMLINK_FOLLOW);
                if (linked != 0 && errno != EEXIST) break;
            }
            if (linked != 0) {
                m_tempPath.clear();
                fail(std::strerror(errno));
                return false;
            }
            m_unnamed = false;  // from here on a failure removes the named file
        }
    }
    const int closed = std::fclose(m_file);
    m_file = nullptr;
    if (closed != 0) {
        fail(std::strerror(errno));
        return false;
    }
    m_prepared = true;
    return true;
}

bool AtomicFile::publish() {
    if (!prepare()) return false;
    if (!m_tempPath.empty() && std::rename(m_tempPath.c_str(), m_target.c_str()) != 0) {
        fail(std::strerror(errno));
        return false;
    }
    m_committed = true;
    return true;
}

bool AtomicFile::commit() { return publish(); }

std::string xmlEscaped(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') out += "\xEF\xBF\xBD";
                else out += c;
        }
    }
    return out;
}

std::optional<std::string> commitAll(const std::vector<AtomicFile*>& files) {
    // Every file complete, synced and named beside its target before the first rename: a
    // failure up to here leaves every existing file as it was (the destructors remove the
    // temporary names).
    for (AtomicFile* file : files)
        if (file && !file->prepare()) return file->error();
    for (AtomicFile* file : files)
        if (file && !file->publish()) return file->error();
    return std::nullopt;
}

std::string formatDouble(double value) {
    // Non-finite values as such (a diverged run's last row, a failed fit), never as 0.
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[64];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return ec == std::errc() ? std::string(buffer, end) : std::string("0");
}

std::vector<CsvColumn> timeSeriesColumns(SceneKind kind, bool solverCounters) {
    using D = Diagnostics;
    // 2D bodies enclose an area [m^2] and their gas pushes per length [N/m].
    const bool flat = kind == SceneKind::Ring2d;
    std::vector<CsvColumn> c = {
        {"step", [](const D& d) { return static_cast<double>(d.step); }},
        {"t", [](const D& d) { return d.time; }, "s"},
        {"dt", [](const D& d) { return d.dt; }, "s"},
        {"energy_kinetic", [](const D& d) { return d.kinetic; }, "J"},
        {"energy_spring", [](const D& d) { return d.springTotal(); }, "J"},
        {"energy_spring_structural", [](const D& d) { return d.spring[0]; }, "J"},
    };
    const bool layered = hasGas(kind);
    if (layered) {
        c.push_back({"energy_spring_radius", [](const D& d) { return d.spring[1]; }, "J"});
        c.push_back({"energy_spring_shear", [](const D& d) { return d.spring[2]; }, "J"});
    }
    c.push_back({"energy_gravity", [](const D& d) { return d.gravity; }, "J"});
    if (layered) c.push_back({"energy_gas", [](const D& d) { return d.gas; }, "J"});
    c.push_back({"energy_pointer", [](const D& d) { return d.pointer; }, "J"});
    // Every scene has the box walls: contact energy (walls + layer barrier) and what contact
    // dissipation and friction removed (both 0 with contact = projection, which books its
    // changes as energy_removed_collisions).
    c.push_back({"energy_contact", [](const D& d) { return d.contact; }, "J"});
    c.push_back({"energy_total", [](const D& d) { return d.total(); }, "J"});
    c.push_back({"energy_removed", [](const D& d) { return d.removed(); }, "J"});
    c.push_back({"energy_removed_damping", [](const D& d) { return d.removedDamping; }, "J"});
    c.push_back({"energy_removed_contact", [](const D& d) { return d.removedContact; }, "J"});
    c.push_back({"energy_removed_collisions", [](const D& d) { return d.removedCollisions; }, "J"});
    c.push_back({"work_pointer", [](const D& d) { return d.workPointer; }, "J"});
    c.push_back({"energy_drift", [](const D& d) { return d.energyDrift(); }, "J"});
    // Local position error estimate of the last step [m], RMS over particles: rk45's embedded
    // estimate, or step doubling for fixed-step methods (run --error-estimate); -1 = none.
    c.push_back({"error_estimate", [](const D& d) { return d.errorEstimate; }, "m"});
    if (layered) {
        const std::string volume = flat ? "m²" : "m³", pressure = flat ? "N/m" : "Pa";
        c.push_back({"volume_inner", [](const D& d) { return d.volume[0]; }, volume});
        c.push_back({"volume_outer", [](const D& d) { return d.volume[1]; }, volume});
        c.push_back({"pressure_inner", [](const D& d) { return d.pressure[0]; }, pressure});
        c.push_back({"pressure_outer", [](const D& d) { return d.pressure[1]; }, pressure});
    }
    if (solverCounters) {
        auto count = [](auto value) { return [value](const D& d) { return static_cast<double>(value(d)); }; };
        c.push_back({"force_evals", count([](const D& d) { return d.forceEvaluations; })});
        c.push_back({"solver_steps", count([](const D& d) { return d.solver.steps; })});
        c.push_back({"rhs_evals", count([](const D& d) { return d.solver.rhsEvaluations; })});
        c.push_back({"jac_products", count([](const D& d) { return d.solver.jacobianProducts; })});
        c.push_back({"linear_iterations", count([](const D& d) { return d.solver.linearIterations; })});
        c.push_back({"precond_iterations", count([](const D& d) { return d.solver.preconditionerIterations; })});
        c.push_back({"nonlinear_iterations", count([](const D& d) { return d.solver.nonlinearIterations; })});
        c.push_back({"error_test_failures", count([](const D& d) { return d.solver.errorTestFailures; })});
        c.push_back({"convergence_failures", count([](const D& d) { return d.solver.convergenceFailures; })});
        c.push_back({"reinits", count([](const D& d) { return d.solver.reinitialisations; })});
        c.push_back({"order", count([](const D& d) { return d.solver.order; })});
        c.push_back({"step_size", [](const D& d) { return d.solver.step; }, "s"});
    }
    return c;
}

std::vector<ChartSpec> timeSeriesCharts(SceneKind kind) {
    std::vector<ChartSpec> charts = {{"Energy", "energy [J]", {"energy_kinetic", "energy_spring", "energy_gravity"}}};
    if (hasGas(kind)) charts.front().columns.push_back("energy_gas");
    charts.front().columns.push_back("energy_total");
    if (hasGas(kind)) {
        const bool flat = kind == SceneKind::Ring2d;
        charts.push_back({flat ? "Area" : "Volume", flat ? "area [m²]" : "volume [m³]", {"volume_inner", "volume_outer"}});
        charts.push_back({"Pressure", flat ? "pressure [N/m]" : "pressure [Pa]", {"pressure_inner", "pressure_outer"}});
    }
    return charts;
}

std::optional<CsvDialect> csvDialectNamed(std::string_view name) {
    if (name == "plain") return CsvDialect::Plain;
    if (name == "excel-semicolon") return CsvDialect::ExcelSemicolon;
    return std::nullopt;
}

std::string unknownCsvDialectMessage(std::string_view name) {
    return "csv dialect " + quoteShort(name) + " is unknown; one of " + std::string(kCsvDialectNames);
}

std::string_view csvDialectName(CsvDialect dialect) {
    return dialect == CsvDialect::ExcelSemicolon ? "excel-semicolon" : "plain";
}

std::string inDialect(std::string plain, CsvDialect dialect, bool fileStart) {
    if (dialect == CsvDialect::Plain) return plain;
    std::string out = fileStart ? "\xEF\xBB\xBF" : "";  // UTF-8 byte-order mark
    out.reserve(out.size() + plain.size() + plain.size() / 16);
    for (const char ch : plain) {
        if (ch == ',') out += ';';
        else if (ch == '.') out += ',';
        else if (ch == '\n') out += "\r\n";
        else out += ch;
    }
    return out;
}

std::string headerWithUnit(const CsvColumn& column) {
    return column.unit.empty() ? column.name : column.name + " [" + column.unit + "]";
}

namespace {

// A CSV header and row from columns of any diagnostics (one body's or a world's).
template <class Column>
std::string headerOf(const std::vector<Column>& columns) {
    std::string line;
    for (const Column& c : columns) {
        if (!line.empty()) line += ',';
        line += c.name;
    }
    return line + '\n';
}

template <class Column, class D>
std::string rowOf(const std::vector<Column>& columns, const D& d) {
    std::string line;
    for (const Column& c : columns) {
        if (!line.empty()) line += ',';
        line += formatDouble(c.value(d));
    }
    return line + '\n';
}

}  // namespace

std::string csvHeader(const std::vector<CsvColumn>& columns) { return headerOf(columns); }

std::string csvRow(const std::vector<CsvColumn>& columns, const Diagnostics& d) { return rowOf(columns, d); }

std::string stateTable(const Simulation& sim) {
    std::string text = "index,layer,x,y,z,vx,vy,vz\n";
    const auto x = sim.positions();
    const auto v = sim.velocities();
    const auto& layers = sim.topology().layer;
    for (int i = 0; i < sim.particleCount(); ++i) {
        text += std::to_string(i);
        text += ',';
        text += layerName(layers[static_cast<std::size_t>(i)]);
        for (int k = 0; k < 3; ++k) (text += ',') += formatDouble(x(k, i));
        for (int k = 0; k < 3; ++k) (text += ',') += formatDouble(v(k, i));
        text += '\n';
    }
    return text;
}

namespace {

// What a path names: an existing file's (device, inode), or for a file still to be created the
// (device, inode) of its folder and its name.
struct FileIdentity {
    dev_t device = 0;
    ino_t inode = 0;
    std::string newName;  // empty: an existing file
    bool operator==(const FileIdentity&) const = default;
};

std::optional<FileIdentity> identify(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) return FileIdentity{st.st_dev, st.st_ino, {}};
    const std::filesystem::path p(path);
    const std::filesystem::path folder = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
    if (::stat(folder.c_str(), &st) != 0) return std::nullopt;  // the write reports the missing folder
    return FileIdentity{st.st_dev, st.st_ino, p.filename().string()};
}

}  // namespace

std::optional<std::string> fileClash(const std::vector<std::pair<std::string, std::string>>& inputsThenOutputs) {
    std::vector<std::pair<std::string, FileIdentity>> seen;  // option, identity
    for (const auto& [option, path] : inputsThenOutputs) {
        if (path.empty()) continue;
        const auto id = identify(path);
        if (!id) continue;
        for (const auto& [other, otherId] : seen)
            if (otherId == *id)
                return "--" + option + " " + quoteShort(path, 200) + " is the same file as --" + other +
                       "; every output must be a file of its own, apart from the inputs";
        seen.emplace_back(option, *id);
    }
    return std::nullopt;
}

std::vector<WorldCsvColumn> worldColumns(const simcore::World& world) {
    return worldColumns(world.dimension(), world.bodyCount());
}

std::vector<WorldCsvColumn> worldColumns(int dimension, int bodyCount) {
    using D = simcore::WorldDiagnostics;
    const bool three = dimension == 3;
    std::vector<WorldCsvColumn> c = {
        {"step", [](const D& d) { return static_cast<double>(d.step); }},
        {"t", [](const D& d) { return d.time; }},
        {"dt", [](const D& d) { return d.dt; }},
        {"energy_kinetic", [](const D& d) { return d.kinetic; }},
        {"energy_spring", [](const D& d) { return d.springTotal(); }},
        {"energy_gravity", [](const D& d) { return d.gravity; }},
        {"energy_gas", [](const D& d) { return d.gas; }},
        {"energy_contact", [](const D& d) { return d.contact; }},
        {"energy_contact_bodies", [](const D& d) { return d.contactPairs; }},
        {"energy_total", [](const D& d) { return d.total(); }},
        {"energy_removed", [](const D& d) { return d.removed(); }},
        {"energy_removed_damping", [](const D& d) { return d.removedDamping; }},
        {"energy_removed_contact", [](const D& d) { return d.removedContact; }},
        {"energy_drift", [](const D& d) { return d.energyDrift(); }},
        {"error_estimate", [](const D& d) { return d.errorEstimate; }},
    };
    const std::array<const char*, 3> axes = {"x", "y", "z"};
    for (int k = 0; k < bodyCount; ++k) {
        const auto b = static_cast<std::size_t>(k);
        const std::string n = "_" + std::to_string(k + 1);
        for (std::size_t slot = 0; slot < 2; ++slot) {
            const std::string layer = slot == 0 ? "inner" : "outer";
            c.push_back({"volume_" + layer + n, [b, slot](const D& d) { return d.bodies[b].volume[slot]; }});
        }
        for (std::size_t slot = 0; slot < 2; ++slot) {
            const std::string layer = slot == 0 ? "inner" : "outer";
            c.push_back({"pressure_" + layer + n, [b, slot](const D& d) { return d.bodies[b].pressure[slot]; }});
        }
        for (int a = 0; a < (three ? 3 : 2); ++a)
            c.push_back({std::string("com_") + axes[static_cast<std::size_t>(a)] + n,
                         [b, a](const D& d) { return d.bodies[b].com[a]; }});
        for (int a = 0; a < (three ? 3 : 2); ++a)
            c.push_back({std::string("velocity_") + axes[static_cast<std::size_t>(a)] + n,
                         [b, a](const D& d) { return d.bodies[b].velocity[a]; }});
    }
    for (int a = 0; a < (three ? 3 : 2); ++a)
        c.push_back({std::string("momentum_") + axes[static_cast<std::size_t>(a)], [a](const D& d) { return d.momentum[a]; }});
    for (int a = three ? 0 : 2; a < 3; ++a)
        c.push_back({std::string("angular_momentum_") + axes[static_cast<std::size_t>(a)],
                     [a](const D& d) { return d.angularMomentum[a]; }});
    c.push_back({"min_gap", [](const D& d) { return d.minGap; }});
    return c;
}

std::string csvHeader(const std::vector<WorldCsvColumn>& columns) { return headerOf(columns); }

std::string csvRow(const std::vector<WorldCsvColumn>& columns, const simcore::WorldDiagnostics& d) { return rowOf(columns, d); }

std::string stateTable(const simcore::World& world) {
    std::string text = "index,body,layer,x,y,z,vx,vy,vz\n";
    for (int k = 0; k < world.bodyCount(); ++k) {
        const auto x = world.positions(k);
        const auto v = world.velocities(k);
        const auto& layers = world.body(k).topology.layer;
        for (int i = 0; i < world.bodyParticles(k); ++i) {
            text += std::to_string(i);
            text += ',';
            text += std::to_string(k + 1);
            text += ',';
            text += layerName(layers[static_cast<std::size_t>(i)]);
            for (int a = 0; a < 3; ++a) (text += ',') += formatDouble(x(a, i));
            for (int a = 0; a < 3; ++a) (text += ',') += formatDouble(v(a, i));
            text += '\n';
        }
    }
    return text;
}

}  // namespace simlab
