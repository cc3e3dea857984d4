#pragma once
// Dey's parametric terrain features (thesis ch. 4), written `feature name = generator { ... }`,
// one registry record per generator: its keys (type, range, the thesis's sampling step, default)
// and a build function that expands the checked parameters into an ordinary field of registry
// builtins. Curves and particle paths are computed here, on the CPU, at check time, so the
// interpreter and every GPU backend run a feature like any other field. The checker
// (compiler/check/src/CheckFeatures.cpp) reads the keys against these records and reports every
// problem at its place in the source; docs/language.md ("Features") defines each generator.
#include "voxc/program/Field.h"

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace voxc::dey {

enum class GeneratorKeyType : uint8_t { Number, Integer, Vec3 };

struct GeneratorKey {
    std::string_view name;
    GeneratorKeyType type;
    double min; // inclusive bounds on the value, or on each Vec3 component
    double max;
    double step;                 // the thesis's sampling interval from min; 0 = any value (W0205 otherwise)
    std::array<double, 3> value; // the default (the thesis's, Tables 4.4-4.6)
    bool required = false;
    bool override = false; // no default: when written, replaces a shared key for one end (arch)
};

// Checked values by key name; every non-override key has its default when not written.
class GeneratorParams {
public:
    void set(std::string_view key, std::array<double, 3> value) { values_[std::string(key)] = value; }
    bool has(std::string_view key) const { return values_.find(key) != values_.end(); }
    double number(std::string_view key) const;
    glm::dvec3 vec(std::string_view key) const;

private:
    std::map<std::string, std::array<double, 3>, std::less<>> values_;
};

// A key whose value is unusable together with the others, e.g. an arch with start == end.
struct GeneratorProblem {
    std::string key;
    std::string message;
};

struct GeneratorInfo {
    std::string_view name;
    std::span<const GeneratorKey> keys;
    std::optional<GeneratorProblem> (*validate)(const GeneratorParams& params);
    // The feature's density (1 rock, 0 air) from checked parameters: nodes and Float root; the
    // caller names the field and gives its nodes their source location.
    Field (*build)(const GeneratorParams& params, uint32_t seed);
};

std::span<const GeneratorInfo> generators();
const GeneratorInfo* findGenerator(std::string_view name);

} // namespace voxc::dey
