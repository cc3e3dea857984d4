// Prints the libFuzzer dictionary of the .vox language (docs/fuzzing.md): the syntax's keywords
// and operators, the block kinds, keys and words the checker knows, and every name in the
// builtin registries, so the dictionary follows the registries as they grow.
#include "voxc/builtins/Functions.h"
#include "voxc/builtins/Ops.h"
#include "voxc/builtins/Shapes.h"

#include <cstdio>
#include <set>
#include <string>
#include <string_view>

namespace {

// The grammar's tokens (grammar/Voxc.g4) and the words of docs/language.md that no registry lists.
constexpr std::string_view kLanguageWords[] = {
    "const", "fn", "field", "feature", "let", "in", "->", "&&", "||", "<=", ">=", "==", "!=", "?", ":",
    "//", "/*", "*/", ".", ",", ";", "=", "[", "]", "{", "}", "(", ")", "&", "!", "1e999", "-0.5", "1e-45",
    "world", "grammar", "rule", "symbol", "transform", "start", "pipeline", "material", "layer", "lsystem",
    "size", "origin", "seed", "chunk", "iterations", "weight", "probability", "priority", "stride", "value",
    "bounds", "color", "id", "set", "union", "subtract", "intersect", "paint", "arch", "cave", "overhang",
    "float", "int", "bool", "vec2", "vec3", "x", "y", "z", "xy", "xz", "xyz", "density", "none",
    "symmetry", "rot_y", "square", "all", "rot90y", "rot180y", "mirror_x", "mirror_y", "mirror_diag",
    "where", "box", "mean", "min", "max", "solid_fraction", "material_fraction", "stamp", "reach", "offset", "mode",
    // `where` bounds at the end of the float range (a mean's bound times the box's cells past the
    // largest float is E0007)
    "3.4028235e38", "3e38", "-3.4028235e38", "1e-8",
    // L-systems and their carves: dense networks (short steps, small spacing) fill a cell's lists
    "turtle", "thesis", "abop", "selection", "weighted", "axiom", "expansions", "angle", "angle_delta",
    "angle_deviation", "step", "step_delta", "pitch_limit", "yaw", "pitch", "rules", "production", "macro", "tunnel",
    "room", "lsystem_cave", "radius", "room_radius", "spacing", "clearance", "curl_amplitude", "curl_frequency",
    "y_limit", "simplex_frequency", "simplex_amplitude", "voronoi_frequency", "voronoi_amplitude",
    "modulation_frequency", "min_scale", "max_scale", "0.25", "0.5", "8192",
    // speleothems, with keep_clear reading a carve's lists
    "speleothems", "kind", "stalactite", "stalagmite", "column", "hoodoo", "cluster_frequency", "cluster_low",
    "cluster_high", "spawn_frequency", "spawn_threshold", "growth", "taper", "min_gap", "max_gap", "keep_clear",
    // edits files (`run`/`interp`/`view --edits`, JSON): an edit's keys and ops
    "\"op\"", "\"carve\"", "\"add\"", "\"center\"", "\"radius\"", "\"softness\"", "\"material\"", "1e400",
};

std::string quoted(std::string_view word) {
    std::string out = "\"";
    for (char c : word) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

} // namespace

int main() {
    std::set<std::string> words(std::begin(kLanguageWords), std::end(kLanguageWords));
    for (const voxc::FunctionInfo& function : voxc::functions()) words.emplace(function.name);
    for (const voxc::SymbolOpInfo& op : voxc::symbolOps()) words.emplace(op.name);
    for (const voxc::TransformOpInfo& op : voxc::transformOps()) words.emplace(op.name);
    for (const voxc::MaterialOpInfo& op : voxc::materialOps()) words.emplace(op.name);
    for (const voxc::ShapeInfo& shape : voxc::shapes()) {
        words.emplace(shape.name);
        for (const voxc::KeySpec& key : shape.keys) words.emplace(key.name);
    }
    for (const std::string& word : words) std::printf("%s\n", quoted(word).c_str());
    return 0;
}
