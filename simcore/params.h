#pragma once
// The parameter table: every tunable of every scene, as data.
//
// One table feeds validation (CLI --set, scene files, GUI fields), the CLI's `params`
// listing, the GUI's parameter dock and the docs. A key that a scene does not have is
// refused for that scene: a 1D spring has no pressure, no radius springs, no layers.
//
// Names are text only at the boundaries (command line, scene files, the GUI's fields, Python):
// there a key is looked up once (findParam) and becomes a Param. Inside, a value is read as
// `set.get(Param::Dt)`, or, resolved once into typed groups, as `resolve(set).time.dt`; a
// mistyped name does not compile.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace simcore {

enum class SceneKind { Spring1d, Ring2d, Sphere3d, Sphere3dLatLong };

// Bit set of scene kinds a parameter applies to.
enum SceneBits : unsigned {
    kBitSpring1d = 1u << 0,
    kBitRing2d = 1u << 1,
    kBitSphere3d = 1u << 2,
    kBitLatLong = 1u << 3,
    kBitsLayered = kBitRing2d | kBitSphere3d | kBitLatLong,
    kBits3d = kBitSphere3d | kBitLatLong,
    kBitsAll = kBitSpring1d | kBitsLayered,
};

unsigned sceneBit(SceneKind kind);

enum class ParamGroup { Springs, Gas, Mass, Environment, Contact, Pointer, Time, Shape, Start };

// Every parameter, in the table's order (params.cpp checks the two agree at compile time).
enum class Param : std::uint8_t {
    Ks, Kd, Rks, Rkd,                                   // springs
    Pressure, PressureInner, PressureOuter,             // gas
    Mass, MassInner, MassOuter,                         // mass
    Gravity, Box,                                       // environment
    Contact, Restitution, ContactStiffness, ContactSpeed, Friction, FrictionSpeed,  // contact
    Mks, Mkd, MouseRest,                                // pointer
    Dt, Substeps,                                       // time
    Scaling, Particles, Subdivisions, Slices, Stacks, RadiusInner, RadiusOuter, Length,
    InitialLength, FixedEnd,                            // shape
    Perturb, Seed,                                      // start
    Count                                               // not a parameter: the number of them
};
inline constexpr std::size_t kParamCount = static_cast<std::size_t>(Param::Count);

struct ParamSpec {
    Param id;
    std::string_view key;
    std::string_view unit;          // SI unit, "" when dimensionless
    double defaultValue;
    double minValue;
    double maxValue;
    bool minExclusive;              // true: value must be > minValue
    bool integer;                   // whole numbers only
    unsigned scenes;                // SceneBits where the key exists
    ParamGroup group;
    Param inherits;                 // when not set explicitly, take this one's value (Count: none)
    std::string_view meaning;       // one line, shown in tooltips and `params`
    // Per-scene default overriding defaultValue (0 = none).
    unsigned overrideScenes = 0;
    double overrideValue = 0.0;
    // A choice among names, "a|b|c": value k means the k-th name; text input may give the
    // name instead of the number (e.g. contact=projection). Empty for plain numbers.
    std::string_view choices = {};

    bool isShape() const { return group == ParamGroup::Shape; }
    double defaultFor(SceneKind kind) const;
    std::string rangeText() const;  // e.g. "[0, 1]" or "(0, 10]"
    // The name of choice `value` ("" when there is none), and the index of a name (-1).
    std::string choiceName(double value) const;
    int choiceIndex(std::string_view name) const;
};

// Parses text for a parameter: a number, or for a choice parameter one of its names.
std::optional<double> parseValue(const ParamSpec& spec, std::string_view text);

std::span<const ParamSpec> parameterTable();
const ParamSpec& paramSpec(Param id);
// The boundary's lookup: a key's spec, or nullptr for a name that is not in the table.
const ParamSpec* findParam(std::string_view key);
std::vector<const ParamSpec*> parametersFor(SceneKind kind);

// Checks a value against the spec; the message names the key, what was given and what is allowed.
std::optional<std::string> validateValue(const ParamSpec& spec, double value);

// A value quoted for a message: at most `limit` bytes, non-printable bytes as \xNN, and the
// full length said when cut (a 5 MB bad value is never echoed whole).
std::string quoteShort(std::string_view text, std::size_t limit = 40);

// Parses a number the way every input boundary does: the whole text must be a finite number.
std::optional<double> parseNumber(std::string_view text);

// A comma-separated list given for `option` (CLI and GUI alike): every item present (no "a,,b",
// no trailing comma), none listed twice, numbers finite; otherwise the message naming the
// option and the item.
struct NameList {
    std::vector<std::string> items;
    std::string error;  // empty when the list is good
};
NameList parseNameList(std::string_view option, std::string_view text);
struct NumberList {
    std::vector<double> items;
    std::string error;
};
NumberList parseNumberList(std::string_view option, std::string_view text);

// The values of one scene: the explicitly set ones, the rest resolved from the table.
class ParameterSet {
public:
    explicit ParameterSet(SceneKind kind = SceneKind::Ring2d) : m_kind(kind) {}

    SceneKind kind() const { return m_kind; }
    // Whether this scene has the parameter (a 1D spring has no pressure).
    bool has(Param id) const;

    // Returns an error message (not a parameter of this scene, out of range) or nothing.
    std::optional<std::string> set(Param id, double value);
    // The boundary's forms: a key given as text (unknown keys are refused with the list).
    std::optional<std::string> set(std::string_view key, double value);
    std::optional<std::string> setFromText(std::string_view key, std::string_view text);
    // "key=value"
    std::optional<std::string> assign(std::string_view assignment);

    double get(Param id) const;
    int getInt(Param id) const { return static_cast<int>(get(id)); }
    bool isExplicit(Param id) const { return m_explicit[index(id)]; }
    void clear(Param id) {
        m_explicit[index(id)] = false;
        m_values[index(id)] = 0.0;
    }
    // The explicitly set values, in the table's order.
    std::vector<std::pair<Param, double>> explicitValues() const;

    bool operator==(const ParameterSet&) const = default;

private:
    static std::size_t index(Param id) { return static_cast<std::size_t>(id); }
    SceneKind m_kind;
    std::array<double, kParamCount> m_values{};  // 0 where not explicit
    std::array<bool, kParamCount> m_explicit{};
};

// The values resolved once into typed groups: what the physics reads. Values are the table's
// (per particle and per spring at the reference resolution; scaling.h turns them into the
// body's); keys a scene does not have hold their table defaults.
enum class ContactModel { Force = 0, Projection = 1 };  // the values of `contact`
enum class Scaling { Physical = 0, Thesis = 1 };  // the values of `scaling`

struct Params {
    struct Forces {
        // `ks`/`kd` name only these, the table's keys; a body's per-family values scaled to its
        // resolution are ForceParams::stiffness/damping (forces.h).
        double ks = 0.0, kd = 0.0;             // structural springs [N/m], [N s/m]
        double rks = 0.0, rkd = 0.0;           // radius and shear springs [N/m], [N s/m]
        std::array<double, 2> gasConstant{};   // nRT of the [inner, outer] gas [J]
        double mks = 0.0, mkd = 0.0;           // mouse spring [N/m], [N s/m]
        double mouseRest = 0.0;                // mouse spring rest length [m]
    } forces;
    struct World {
        double gravity = 0.0;                  // [m/s^2], along -y
        double box = 0.0;                      // half-size of the box [m]
        ContactModel contact = ContactModel::Force;
        double restitution = 0.0;
        double contactStiffness = 0.0;         // k of U = k d^4/4 [N/m^3]
        double contactSpeed = 0.0;             // speed at which the damping gives e [m/s]
        double friction = 0.0;                 // Coulomb mu (force); fraction removed (projection)
        double frictionSpeed = 0.0;            // regularisation speed [m/s]
    } world;
    struct Time {
        double dt = 0.0;                       // step of fixed-step integrators [s]
        int substeps = 1;                      // xpbd substeps per step
    } time;
    struct Shape {
        Scaling scaling = Scaling::Physical;
        double mass = 0.0, massInner = 0.0, massOuter = 0.0;  // particle masses [kg]
        int particles = 0;                     // ring2d: per layer
        int subdivisions = 0;                  // sphere3d: level L
        int slices = 0, stacks = 0;            // sphere3d-latlong
        double radiusInner = 0.0, radiusOuter = 0.0;  // [m]
        double length = 0.0, initialLength = 0.0;     // spring1d [m]
        bool fixedEnd = false;                 // spring1d: the top particle is fixed
    } shape;
    struct Start {
        double perturb = 0.0;                  // amplitude of the seeded displacement [m]
        std::uint64_t seed = 0;
    } start;
};

Params resolve(const ParameterSet& set);

}  // namespace simcore
