#include "voxc/check/Check.h"

#include "voxc/core/Errors.h"

#include <cctype>
#include <fmt/format.h>

namespace voxc {

namespace {

using namespace lsystem;

// fmt's shortest form reads back to the same double and lexes as a NUMBER (1e+30 included).
std::string number(double v) { return fmt::format("{}", v); }
std::string vec(glm::dvec3 v) { return fmt::format("[{}, {}, {}]", number(v.x), number(v.y), number(v.z)); }

std::string quoted(const std::string& text) {
    if (text.find_first_of("\"\r\n") != std::string::npos)
        throw UserError(fmt::format("the string '{}' holds a quote or a line break and cannot be written in .vox", text));
    return fmt::format("\"{}\"", text);
}

void alternatives(std::string& out, const char* kind, const std::map<char, std::vector<Alternative>>& table) {
    for (const auto& [symbol, list] : table) {
        if (!std::isalpha(uint8_t(symbol)))
            throw UserError(fmt::format("{} '{}' cannot be written as a block label (only letters can)", kind, symbol));
        out += fmt::format("    {} {} {{\n", kind, symbol);
        for (const Alternative& a : list)
            out += fmt::format("        {} {} {};\n", quoted(a.text), symbolTypeName(a.type), number(a.weight));
        out += "    }\n";
    }
}

} // namespace

std::string formatLsystemBlock(const std::string& name, const Definition& definition, const ConnectParams& connect) {
    const TurtleParams& p = definition.params;
    std::string out = fmt::format("lsystem {} {{\n", name);
    out += fmt::format("    turtle = {};\n", definition.turtle == TurtleKind::Thesis ? "thesis" : "abop");
    out += fmt::format("    selection = {};\n", definition.selection == Selection::Weighted ? "weighted" : "thesis");
    out += fmt::format("    axiom = {};\n    expansions = {};\n    seed = {};\n", quoted(definition.axiom),
                       definition.expansions, definition.seed);
    out += fmt::format("    angle = {};\n    step = {};\n    angle_delta = {};\n    step_delta = {};\n", number(p.angle),
                       number(p.step), number(p.angleDelta), number(p.stepDelta));
    out += fmt::format("    angle_deviation = {};\n    pitch_limit = {};\n", number(p.angleDeviation),
                       number(p.pitchLimit));
    out += fmt::format("    start = {};\n    yaw = {};\n    pitch = {};\n", vec(p.start), number(p.yaw), number(p.pitch));
    alternatives(out, "production", definition.productions);
    alternatives(out, "macro", definition.macros);
    if (const auto& t = definition.target)
        out += fmt::format("    target {{ point = {}; strength = {}; }}\n", vec(t->point), number(t->strength));
    if (const auto& b = definition.balanced) out += fmt::format("    balanced {{ delta = {}; }}\n", number(b->delta));
    if (const auto& c = definition.constrained) {
        if (c->shape == ConstrainedMode::Shape::Box)
            out += fmt::format("    constrain {{ min = {}; max = {}; }}\n", vec(c->min), vec(c->max));
        else
            out += fmt::format("    constrain {{ center = {}; radius = {}; }}\n", vec(c->center), number(c->radius));
    }
    out += fmt::format("    connect {{ chance = {}; max_distance = {}; frequency = {}; amplitude = {}; spacing = {}; }}\n",
                       number(connect.chance), number(connect.maxDistance), number(connect.frequency),
                       number(connect.amplitude), number(connect.spacing));
    out += "}\n";
    return out;
}

} // namespace voxc
