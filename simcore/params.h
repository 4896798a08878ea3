#pragma once
// The parameter table: every tunable of every scene, as data.
//
// One table feeds validation (CLI --set, scene files, GUI fields), the CLI's `params`
// listing, the GUI's parameter dock and the docs. A key that a scene does not have is
// refused for that scene: a 1D spring has no pressure, no radius springs, no layers.

#include <map>
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

struct ParamSpec {
    std::string_view key;
    std::string_view unit;          // SI unit, "" when dimensionless
    double defaultValue;
    double minValue;
    double maxValue;
    bool minExclusive;              // true: value must be > minValue
    bool integer;                   // whole numbers only
    unsigned scenes;                // SceneBits where the key exists
    ParamGroup group;
    std::string_view inherits;      // when not set explicitly, take this key's value
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

    // Returns an error message (key unknown for this scene, bad number, out of range) or nothing.
    std::optional<std::string> set(std::string_view key, double value);
    std::optional<std::string> setFromText(std::string_view key, std::string_view text);
    // "key=value"
    std::optional<std::string> assign(std::string_view assignment);

    double get(std::string_view key) const;
    int getInt(std::string_view key) const { return static_cast<int>(get(key)); }
    bool isExplicit(std::string_view key) const { return m_values.count(std::string(key)) != 0; }
    void clear(std::string_view key) { m_values.erase(std::string(key)); }
    const std::map<std::string, double>& explicitValues() const { return m_values; }

    bool operator==(const ParameterSet&) const = default;

private:
    SceneKind m_kind;
    std::map<std::string, double> m_values;
};

}  // namespace simcore
