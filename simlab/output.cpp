#include "simlab/output.h"

#include <sys/stat.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <unistd.h>

namespace simlab {

using simcore::Diagnostics;
using simcore::SceneKind;
using simcore::Simulation;
using simcore::hasGas;
using simcore::layerName;
using simcore::quoteShort;

AtomicFile::AtomicFile(std::string path) : m_path(std::move(path)) {
    if (m_path.empty()) {
        fail("empty file name");
        return;
    }
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(m_path, ec);
    if (fs::exists(status) && !fs::is_regular_file(status)) {
        // A device or pipe (/dev/stdout, /dev/full, a FIFO) cannot be replaced by a rename:
        // write straight to it; errors still surface at flush and are reported.
        m_file = std::fopen(m_path.c_str(), "wb");
        if (!m_file) fail(std::strerror(errno));
        return;
    }
    // Write beside the real file (through a symlink, not over it), then rename into place.
    std::string target = m_path;
    if (fs::is_symlink(fs::symlink_status(m_path, ec))) target = fs::canonical(m_path, ec).string();
    if (ec || target.empty()) target = m_path;
    m_target = target;
    m_tempPath = target + ".tmp-" + std::to_string(::getpid());
    // An unnamed file in the target's folder (O_TMPFILE): if the process is killed before the
    // commit, the kernel drops it and nothing is left behind. It gets its temporary name only
    // at the commit, just before the rename. Filesystems without O_TMPFILE get the named
    // temporary file from the start (removed on any failure we live through).
    const fs::path parent = fs::path(target).parent_path();
    const int fd = ::open(parent.empty() ? "." : parent.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    if (fd >= 0) {
        m_file = ::fdopen(fd, "wb");
        if (!m_file) ::close(fd);
        m_unnamed = m_file != nullptr;
    }
    if (!m_file) m_file = std::fopen(m_tempPath.c_str(), "wb");
    if (!m_file) fail(std::strerror(errno));
}

AtomicFile::~AtomicFile() {
    if (m_file) std::fclose(m_file);
    if (!m_committed && !m_tempPath.empty() && !m_unnamed) std::remove(m_tempPath.c_str());
}

void AtomicFile::fail(const std::string& what) {
    if (m_error.empty()) m_error = "cannot write '" + m_path + "': " + what;
}

bool AtomicFile::write(std::string_view text) {
    if (!ok() || !m_file) return false;
    if (std::fwrite(text.data(), 1, text.size(), m_file) != text.size()) {
        fail(std::strerror(errno));
        return false;
    }
    return true;
}

bool AtomicFile::commit() {
    if (!ok() || !m_file) return false;
    if (std::fflush(m_file) != 0 || std::ferror(m_file) ||
        (!m_tempPath.empty() && ::fsync(::fileno(m_file)) != 0)) {
        fail(std::strerror(errno));
        return false;
    }
    if (m_unnamed) {
        // Give the unnamed file its temporary name (through /proc, which needs no privilege);
        // a stale file of that name from a killed run of the same pid is replaced.
        const std::string self = "/proc/self/fd/" + std::to_string(::fileno(m_file));
        int linked = ::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, m_tempPath.c_str(), AT_SYMLINK_FOLLOW);
        if (linked != 0 && errno == EEXIST && std::remove(m_tempPath.c_str()) == 0)
            linked = ::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, m_tempPath.c_str(), AT_SYMLINK_FOLLOW);
        if (linked != 0) {
            fail(std::strerror(errno));
            return false;
        }
        m_unnamed = false;  // from here on a failure removes the named file
    }
    if (!m_tempPath.empty()) {
        // A replaced file keeps its permissions (a 600 file stays 600) and, where the process
        // may set them (root, or the file's own group), its owner and group.
        struct stat old {};
        if (::stat(m_target.c_str(), &old) == 0 && S_ISREG(old.st_mode)) {
            if (::fchmod(::fileno(m_file), old.st_mode & 07777) != 0) {
                fail(std::strerror(errno));
                return false;
            }
            [[maybe_unused]] const int owned = ::fchown(::fileno(m_file), old.st_uid, old.st_gid);  // EPERM: keep ours
        }
    }
    const int closed = std::fclose(m_file);
    m_file = nullptr;
    if (closed != 0) {
        fail(std::strerror(errno));
        return false;
    }
    if (m_tempPath.empty()) {  // written in place (device or pipe)
        m_committed = true;
        return true;
    }
    if (std::rename(m_tempPath.c_str(), m_target.c_str()) != 0) {
        fail(std::strerror(errno));
        return false;
    }
    m_committed = true;
    return true;
}

std::string formatDouble(double value) {
    if (!std::isfinite(value)) return "0";  // never reached: failures stop before output
    char buffer[64];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return ec == std::errc() ? std::string(buffer, end) : std::string("0");
}

std::vector<CsvColumn> timeSeriesColumns(SceneKind kind, bool solverCounters) {
    using D = Diagnostics;
    std::vector<CsvColumn> c = {
        {"step", [](const D& d) { return static_cast<double>(d.step); }},
        {"t", [](const D& d) { return d.time; }},
        {"dt", [](const D& d) { return d.dt; }},
        {"energy_kinetic", [](const D& d) { return d.kinetic; }},
        {"energy_spring", [](const D& d) { return d.springTotal(); }},
        {"energy_spring_structural", [](const D& d) { return d.spring[0]; }},
    };
    const bool layered = hasGas(kind);
    if (layered) {
        c.push_back({"energy_spring_radius", [](const D& d) { return d.spring[1]; }});
        c.push_back({"energy_spring_shear", [](const D& d) { return d.spring[2]; }});
    }
    c.push_back({"energy_gravity", [](const D& d) { return d.gravity; }});
    if (layered) c.push_back({"energy_gas", [](const D& d) { return d.gas; }});
    c.push_back({"energy_pointer", [](const D& d) { return d.pointer; }});
    // Every scene has the box walls: contact energy (walls + layer barrier) and what contact
    // dissipation and friction removed (both 0 with contact = projection, which books its
    // changes as energy_removed_collisions).
    c.push_back({"energy_contact", [](const D& d) { return d.contact; }});
    c.push_back({"energy_total", [](const D& d) { return d.total(); }});
    c.push_back({"energy_removed", [](const D& d) { return d.removed(); }});
    c.push_back({"energy_removed_damping", [](const D& d) { return d.removedDamping; }});
    c.push_back({"energy_removed_contact", [](const D& d) { return d.removedContact; }});
    c.push_back({"energy_removed_collisions", [](const D& d) { return d.removedCollisions; }});
    c.push_back({"work_pointer", [](const D& d) { return d.workPointer; }});
    c.push_back({"energy_drift", [](const D& d) { return d.energyDrift(); }});
    // Local position error estimate of the last step [m], RMS over particles: rk45's embedded
    // estimate, or step doubling for fixed-step methods (run --error-estimate); -1 = none.
    c.push_back({"error_estimate", [](const D& d) { return d.errorEstimate; }});
    if (layered) {
        c.push_back({"volume_inner", [](const D& d) { return d.volume[0]; }});
        c.push_back({"volume_outer", [](const D& d) { return d.volume[1]; }});
        c.push_back({"pressure_inner", [](const D& d) { return d.pressure[0]; }});
        c.push_back({"pressure_outer", [](const D& d) { return d.pressure[1]; }});
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
        c.push_back({"step_size", [](const D& d) { return d.solver.step; }});
    }
    return c;
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
    using D = simcore::WorldDiagnostics;
    const bool three = world.dimension() == 3;
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
    for (int k = 0; k < world.bodyCount(); ++k) {
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
