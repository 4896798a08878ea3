#include "simcore/params.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace simcore {

namespace {

// The thesis's defaults (§7.2.1) where it gives one; docs/model.md for the rest.
// clang-format off
constexpr std::array kTable = {
    //        key             unit     default  min    max     >min   int    scenes         group
    ParamSpec{Param::Ks, "ks",           "N/m",   800.0,   0.0,   1e9,    false, false, kBitsAll,      ParamGroup::Springs, Param::Count,
              "structural spring stiffness KS, per spring (scaling=physical: at the reference resolution; a 2D chain keeps "
              "k L0, a 3D membrane keeps k)"},
    ParamSpec{Param::Kd, "kd",           "N*s/m", 15.0,    0.0,   1e7,    false, false, kBitsAll,      ParamGroup::Springs, Param::Count,
              "structural spring damping KD, per spring; scales like KS"},
    ParamSpec{Param::Rks, "rks",          "N/m",   700.0,   0.0,   1e9,    false, false, kBitsLayered,  ParamGroup::Springs, Param::Count,
              "radius and shear spring stiffness RKS, per spring (scaling=physical: at the reference resolution; "
              "in parallel, k times count stays fixed)"},
    ParamSpec{Param::Rkd, "rkd",          "N*s/m", 50.0,    0.0,   1e7,    false, false, kBitsLayered,  ParamGroup::Springs, Param::Count,
              "radius and shear spring damping RKD, per spring; scales like RKS"},
    ParamSpec{Param::Pressure, "pressure",     "J",     20.0,    0.0,   1e7,    false, false, kBitsLayered,  ParamGroup::Gas, Param::Count,
              "gas constant nRT of each closed layer (PRESSURE): P = nRT / V"},
    ParamSpec{Param::PressureInner, "pressure_inner","J",    20.0,    0.0,   1e7,    false, false, kBitsLayered,  ParamGroup::Gas, Param::Pressure,
              "nRT of the gas enclosed by the inner layer (defaults to pressure)"},
    ParamSpec{Param::PressureOuter, "pressure_outer","J",    20.0,    0.0,   1e7,    false, false, kBitsLayered,  ParamGroup::Gas, Param::Pressure,
              "nRT of the gas enclosed by the outer layer (defaults to pressure)"},
    ParamSpec{Param::Mass, "mass",         "kg",    1.0,     0.0,   1e6,    true,  false, kBitsAll,      ParamGroup::Mass, Param::Count,
              "particle mass MASS (scaling=physical: at the reference resolution; each layer keeps its total)"},
    ParamSpec{Param::MassInner, "mass_inner",   "kg",    1.0,     0.0,   1e6,    true,  false, kBitsLayered,  ParamGroup::Mass, Param::Mass,
              "inner-layer particle mass (defaults to mass; scaled like mass): real inertia, not scaled gravity"},
    ParamSpec{Param::MassOuter, "mass_outer",   "kg",    1.0,     0.0,   1e6,    true,  false, kBitsLayered,  ParamGroup::Mass, Param::Mass,
              "outer-layer particle mass (defaults to mass; scaled like mass)"},
    ParamSpec{Param::Gravity, "gravity",      "m/s^2", 9.81,    0.0,   1e4,    false, false, kBitsAll,      ParamGroup::Environment, Param::Count,
              "gravitational acceleration, pointing along -y"},
    ParamSpec{Param::Box, "box",          "m",     2.5,     0.0,   1e6,    true,  false, kBitsAll,      ParamGroup::Environment, Param::Count,
              "half-size of the collision box (floor, ceiling, walls), centred on the body's start"},
    ParamSpec{Param::Contact, "contact",      "",      0.0,     0.0,   1.0,    false, true,  kBitsAll,      ParamGroup::Contact, Param::Count,
              "contact model: 0 = force (smooth penalty force inside the ODE, in the energy ledger), "
              "1 = projection (the thesis program: put back and reflect after the step)",
              0, 0.0, "force|projection"},
    ParamSpec{Param::Restitution, "restitution",  "",      0.5,     0.0,   1.0,    false, false, kBitsAll,      ParamGroup::Contact, Param::Count,
              "coefficient of restitution e at the box walls: a particle hitting at contact_speed rebounds "
              "at e times its speed (projection: v_n becomes -e*v_n)"},
    ParamSpec{Param::ContactStiffness, "contact_stiffness","N/m^3", 2e7, 0.0,   1e15,   true,  false, kBitsAll,      ParamGroup::Contact, Param::Count,
              "k of the contact potential U = k d^4/4 per particle at a wall (d: penetration) and of the layer "
              "barrier (scaling=physical: at the reference resolution, scaled like mass)"},
    ParamSpec{Param::ContactSpeed, "contact_speed","m/s",   3.0,     0.0,   1e4,    true,  false, kBitsAll,      ParamGroup::Contact, Param::Count,
              "impact speed at which the contact damping gives exactly the restitution e"},
    ParamSpec{Param::Friction, "friction",     "",      0.0,     0.0,   1.0,    false, false, kBitsAll,      ParamGroup::Contact, Param::Count,
              "wall friction: Coulomb coefficient mu (force); tangential velocity fraction removed (projection)"},
    ParamSpec{Param::FrictionSpeed, "friction_speed","m/s",  0.5,     0.0,   1e3,    true,  false, kBitsAll,      ParamGroup::Contact, Param::Count,
              "slip speed below which Coulomb friction is smoothed (regularised) [force contact]"},
    ParamSpec{Param::Mks, "mks",          "N/m",   150.0,   0.0,   1e9,    false, false, kBitsAll,      ParamGroup::Pointer, Param::Count,
              "mouse spring stiffness (MKS)"},
    ParamSpec{Param::Mkd, "mkd",          "N*s/m", 25.0,    0.0,   1e7,    false, false, kBitsAll,      ParamGroup::Pointer, Param::Count,
              "mouse spring damping (MKD)"},
    ParamSpec{Param::MouseRest, "mouse_rest",   "m",     0.0,     0.0,   1e3,    false, false, kBitsAll,      ParamGroup::Pointer, Param::Count,
              "rest length of the mouse spring"},
    ParamSpec{Param::Dt, "dt",           "s",     0.003,   0.0,   1.0,    true,  false, kBitsAll,      ParamGroup::Time, Param::Count,
              "time step DT of fixed-step integrators (initial step of adaptive ones)"},
    ParamSpec{Param::Substeps, "substeps",     "",      8.0,     1.0,   1000.0, false, true,  kBitsAll,      ParamGroup::Time, Param::Count,
              "xpbd: substeps per step DT, one constraint iteration each (Macklin et al. 2019, small steps)"},
    ParamSpec{Param::Scaling, "scaling",      "",      0.0,     0.0,   1.0,    false, true,  kBitsLayered,  ParamGroup::Shape, Param::Count,
              "what mass, ks, kd, rks, rkd and contact_stiffness mean when the mesh is refined: 0 = physical (the "
              "values hold at the scene's default resolution and the body keeps its totals and material constants), "
              "1 = thesis (per particle and per spring at every resolution)",
              0, 0.0, "physical|thesis"},
    ParamSpec{Param::Particles, "particles",    "",      12.0,    3.0,   100000, false, true,  kBitRing2d,    ParamGroup::Shape, Param::Count,
              "particles per layer of the 2D ring"},
    ParamSpec{Param::Subdivisions, "subdivisions", "",      2.0,     0.0,   7.0,    false, true,  kBitSphere3d,  ParamGroup::Shape, Param::Count,
              "subdivision level L of the octahedron sphere: 4*4^L+2 particles per layer"},
    ParamSpec{Param::Slices, "slices",       "",      8.0,    3.0,   1024,   false, true,  kBitLatLong,   ParamGroup::Shape, Param::Count,
              "meridians of the lat/long sphere"},
    ParamSpec{Param::Stacks, "stacks",       "",      4.0,     2.0,   512,    false, true,  kBitLatLong,   ParamGroup::Shape, Param::Count,
              "latitude bands of the lat/long sphere (pole to pole)"},
    ParamSpec{Param::RadiusInner, "radius_inner", "m",     1.5,     0.0,   1e3,    true,  false, kBitsLayered,  ParamGroup::Shape, Param::Count,
              "rest radius of the inner layer (must be below radius_outer)"},
    ParamSpec{Param::RadiusOuter, "radius_outer", "m",     2.0,     0.0,   1e3,    true,  false, kBitsLayered,  ParamGroup::Shape, Param::Count,
              "rest radius of the outer layer"},
    ParamSpec{Param::Length, "length",       "m",     1.0,     0.0,   1e3,    true,  false, kBitSpring1d,  ParamGroup::Shape, Param::Count,
              "rest length of the 1D spring"},
    ParamSpec{Param::InitialLength, "initial_length","m",    1.5,     0.0,   1e3,    true,  false, kBitSpring1d,  ParamGroup::Shape, Param::Count,
              "distance between the two particles at the start (the spring hangs along -y)"},
    ParamSpec{Param::FixedEnd, "fixed_end",    "",      1.0,     0.0,   1.0,    false, true,  kBitSpring1d,  ParamGroup::Shape, Param::Count,
              "1: the top particle is fixed in space (thesis fig. 7); 0: both particles move"},
    ParamSpec{Param::Perturb, "perturb",      "m",     0.0,     0.0,   1e3,    false, false, kBitsAll,      ParamGroup::Start, Param::Count,
              "amplitude of a seeded random displacement of the start positions (breaks symmetry)"},
    ParamSpec{Param::Seed, "seed",         "",      1.0,     0.0,   4294967295.0, false, true, kBitsAll, ParamGroup::Start, Param::Count,
              "seed of the start perturbation"},
};
// clang-format on

// The enum and the table list the parameters in the same order: Param indexes the table.
constexpr bool tableMatchesEnum() {
    if (kTable.size() != kParamCount) return false;
    for (std::size_t i = 0; i < kTable.size(); ++i)
        if (static_cast<std::size_t>(kTable[i].id) != i) return false;
    return true;
}
static_assert(tableMatchesEnum(), "params.cpp: kTable and enum Param (params.h) must list the same keys in order");

}  // namespace

unsigned sceneBit(SceneKind kind) {
    switch (kind) {
        case SceneKind::Spring1d: return kBitSpring1d;
        case SceneKind::Ring2d: return kBitRing2d;
        case SceneKind::Sphere3d: return kBitSphere3d;
        case SceneKind::Sphere3dLatLong: return kBitLatLong;
    }
    return 0;
}

double ParamSpec::defaultFor(SceneKind kind) const {
    return (overrideScenes & sceneBit(kind)) ? overrideValue : defaultValue;
}

static std::string formatNumber(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

std::string ParamSpec::rangeText() const {
    std::string text = minExclusive ? "(" : "[";
    text += formatNumber(minValue) + ", " + formatNumber(maxValue) + "]";
    if (integer) text += " integer";
    if (!choices.empty()) {
        text += " (";
        for (int k = 0; !choiceName(k).empty(); ++k) text += (k ? ", " : "") + std::to_string(k) + " = " + choiceName(k);
        text += ")";
    }
    return text;
}

std::string ParamSpec::choiceName(double value) const {
    int index = 0;
    std::string_view rest = choices;
    while (!rest.empty()) {
        const auto bar = rest.find('|');
        const std::string_view name = rest.substr(0, bar);
        if (index == value) return std::string(name);
        if (bar == std::string_view::npos) break;
        rest = rest.substr(bar + 1);
        ++index;
    }
    return {};
}

int ParamSpec::choiceIndex(std::string_view name) const {
    int index = 0;
    std::string_view rest = choices;
    while (!rest.empty()) {
        const auto bar = rest.find('|');
        if (rest.substr(0, bar) == name) return index;
        if (bar == std::string_view::npos) break;
        rest = rest.substr(bar + 1);
        ++index;
    }
    return -1;
}

std::optional<double> parseValue(const ParamSpec& spec, std::string_view text) {
    if (const int index = spec.choiceIndex(text); index >= 0 && !text.empty()) return index;
    return parseNumber(text);
}

std::span<const ParamSpec> parameterTable() { return kTable; }

const ParamSpec& paramSpec(Param id) { return kTable[static_cast<std::size_t>(id)]; }

const ParamSpec* findParam(std::string_view key) {
    for (const ParamSpec& spec : kTable)
        if (spec.key == key) return &spec;
    return nullptr;
}

std::vector<const ParamSpec*> parametersFor(SceneKind kind) {
    std::vector<const ParamSpec*> out;
    for (const ParamSpec& spec : kTable)
        if (spec.scenes & sceneBit(kind)) out.push_back(&spec);
    return out;
}

std::optional<std::string> validateValue(const ParamSpec& spec, double value) {
    const std::string key(spec.key);
    const std::string unit = spec.unit.empty() ? "" : " " + std::string(spec.unit);
    if (!std::isfinite(value))
        return key + ": not a finite number; allowed " + spec.rangeText() + unit;
    const bool belowMin = spec.minExclusive ? value <= spec.minValue : value < spec.minValue;
    if (belowMin || value > spec.maxValue)
        return key + " = " + formatNumber(value) + " is out of range; allowed " + spec.rangeText() +
               unit;
    if (spec.integer && value != std::floor(value))
        return key + " = " + formatNumber(value) + " must be a whole number; allowed " +
               spec.rangeText();
    return std::nullopt;
}

std::string quoteShort(std::string_view text, std::size_t limit) {
    std::string out = "'";
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (i == limit) {
            out += "...' (" + std::to_string(text.size()) + " bytes)";
            return out;
        }
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7f && c != '\\' && c != '\'') {
            out += static_cast<char>(c);
        } else {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
            out += escaped;
        }
    }
    return out + "'";
}

std::optional<double> parseNumber(std::string_view text) {
    if (text.empty()) return std::nullopt;
    double value = 0.0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
    return value;
}

bool ParameterSet::has(Param id) const { return (paramSpec(id).scenes & sceneBit(m_kind)) != 0; }

std::optional<std::string> ParameterSet::set(Param id, double value) {
    if (!has(id)) return set(paramSpec(id).key, value);  // the boundary's message, with the list
    if (auto error = validateValue(paramSpec(id), value)) return error;
    m_values[index(id)] = value;
    m_explicit[index(id)] = true;
    return std::nullopt;
}

std::optional<std::string> ParameterSet::set(std::string_view key, double value) {
    const ParamSpec* spec = findParam(key);
    if (!spec || !has(spec->id)) {
        std::string allowed;
        for (const ParamSpec* s : parametersFor(m_kind)) {
            if (!allowed.empty()) allowed += ' ';
            allowed += s->key;
        }
        return "unknown parameter " + quoteShort(key) + " for this scene; allowed: " + allowed;
    }
    return set(spec->id, value);
}

std::optional<std::string> ParameterSet::setFromText(std::string_view key, std::string_view text) {
    const ParamSpec* spec = findParam(key);
    const auto value = spec ? parseValue(*spec, text) : parseNumber(text);
    if (!value) {
        std::string allowed = spec ? "; allowed " + spec->rangeText() : "";
        const std::string name = spec ? std::string(key) : quoteShort(key);
        return name + ": " + quoteShort(text) + " is not a finite number" + allowed;
    }
    return set(key, *value);
}

std::optional<std::string> ParameterSet::assign(std::string_view assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0)
        return "expected key=value, got '" + std::string(assignment) + "'";
    return setFromText(assignment.substr(0, eq), assignment.substr(eq + 1));
}

double ParameterSet::get(Param id) const {
    if (m_explicit[index(id)]) return m_values[index(id)];
    const ParamSpec& spec = paramSpec(id);
    if (spec.inherits != Param::Count) return get(spec.inherits);
    return spec.defaultFor(m_kind);
}

std::vector<std::pair<Param, double>> ParameterSet::explicitValues() const {
    std::vector<std::pair<Param, double>> out;
    for (std::size_t i = 0; i < kParamCount; ++i)
        if (m_explicit[i]) out.emplace_back(static_cast<Param>(i), m_values[i]);
    return out;
}

Params resolve(const ParameterSet& set) {
    auto v = [&](Param id) { return set.get(id); };
    auto whole = [&](Param id) { return set.getInt(id); };
    Params p;
    p.forces.ks = v(Param::Ks);
    p.forces.kd = v(Param::Kd);
    p.forces.rks = v(Param::Rks);
    p.forces.rkd = v(Param::Rkd);
    p.forces.gasConstant = {v(Param::PressureInner), v(Param::PressureOuter)};
    p.forces.mks = v(Param::Mks);
    p.forces.mkd = v(Param::Mkd);
    p.forces.mouseRest = v(Param::MouseRest);

    p.world.gravity = v(Param::Gravity);
    p.world.box = v(Param::Box);
    p.world.contact = v(Param::Contact) == 1.0 ? ContactModel::Projection : ContactModel::Force;
    p.world.restitution = v(Param::Restitution);
    p.world.contactStiffness = v(Param::ContactStiffness);
    p.world.contactSpeed = v(Param::ContactSpeed);
    p.world.friction = v(Param::Friction);
    p.world.frictionSpeed = v(Param::FrictionSpeed);

    p.time.dt = v(Param::Dt);
    p.time.substeps = whole(Param::Substeps);

    p.shape.scaling = v(Param::Scaling) == 1.0 ? Scaling::Thesis : Scaling::Physical;
    p.shape.mass = v(Param::Mass);
    p.shape.massInner = v(Param::MassInner);
    p.shape.massOuter = v(Param::MassOuter);
    p.shape.particles = whole(Param::Particles);
    p.shape.subdivisions = whole(Param::Subdivisions);
    p.shape.slices = whole(Param::Slices);
    p.shape.stacks = whole(Param::Stacks);
    p.shape.radiusInner = v(Param::RadiusInner);
    p.shape.radiusOuter = v(Param::RadiusOuter);
    p.shape.length = v(Param::Length);
    p.shape.initialLength = v(Param::InitialLength);
    p.shape.fixedEnd = whole(Param::FixedEnd) != 0;

    p.start.perturb = v(Param::Perturb);
    p.start.seed = static_cast<std::uint64_t>(v(Param::Seed));
    return p;
}

NameList parseNameList(std::string_view option, std::string_view text) {
    NameList list;
    const std::string flag = "--" + std::string(option);
    std::vector<std::string> items;
    std::string item;
    std::stringstream ss{std::string(text)};
    while (std::getline(ss, item, ',')) items.push_back(item);
    if (!text.empty() && text.back() == ',') items.emplace_back();
    if (items.empty()) {
        list.error = flag + " needs a comma-separated list, got nothing";
        return list;
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (items[i].empty()) {
            list.error = flag + " " + quoteShort(text) + ": item " + std::to_string(i + 1) + " is empty";
            return list;
        }
        for (std::size_t j = 0; j < i; ++j)
            if (items[j] == items[i]) {
                list.error = flag + ": " + quoteShort(items[i]) + " is listed twice";
                return list;
            }
    }
    list.items = std::move(items);
    return list;
}

NumberList parseNumberList(std::string_view option, std::string_view text) {
    NumberList list;
    const NameList names = parseNameList(option, text);
    if (!names.error.empty()) {
        list.error = names.error;
        return list;
    }
    const std::string flag = "--" + std::string(option);
    for (const std::string& item : names.items) {
        const auto v = parseNumber(item);
        if (!v) {
            list.error = flag + ": " + quoteShort(item) + " is not a finite number";
            return list;
        }
        if (std::find(list.items.begin(), list.items.end(), *v) != list.items.end()) {
            list.error = flag + ": " + quoteShort(item) + " is listed twice";
            return list;
        }
        list.items.push_back(*v);
    }
    return list;
}

}  // namespace simcore
