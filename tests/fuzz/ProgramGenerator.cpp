#include "ProgramGenerator.h"

#include "voxc/builtins/Functions.h"
#include "voxc/builtins/Ops.h"
#include "voxc/builtins/Shapes.h"

#include <algorithm>
#include <array>
#include <fmt/format.h>
#include <limits>
#include <map>
#include <string_view>
#include <vector>

namespace voxc::fuzz {

uint64_t Random::next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}
uint32_t Random::below(uint32_t n) { return uint32_t(next() % n); }
int32_t Random::range(int32_t lo, int32_t hi) { return lo + int32_t(below(uint32_t(hi - lo + 1))); }
double Random::real(double lo, double hi) { return lo + (hi - lo) * double(next() >> 11) * 0x1.0p-53; }
bool Random::chance(double p) { return real(0.0, 1.0) < p; }

namespace {

constexpr std::array kTypes = {Type::Float, Type::Int, Type::Bool, Type::Vec2, Type::Vec3};

// sin and cos are the records lavapipe does not reproduce bit for bit (docs/architecture.md,
// "Determinism"); the fuzzer compares bits, so it leaves them out. pow and warped_fbm, whose GLSL
// calls exp2, are not bit-exact on lavapipe either (tests/fuzz/regressions/diff/ has the cases).
bool bitExactOnLavapipe(const FunctionInfo& function) {
    return function.name != "sin" && function.name != "cos" && function.name != "pow" && function.name != "warped_fbm";
}

struct Overload {
    const FunctionInfo* function;
    std::vector<Type> args;
};

// Every (record, argument types) the registry's type rules accept, up to five arguments, by
// result type: the generator knows no signature of its own.
const std::map<Type, std::vector<Overload>>& overloadsByResult() {
    static const std::map<Type, std::vector<Overload>> table = [] {
        std::map<Type, std::vector<Overload>> byResult;
        for (const FunctionInfo& function : functions()) {
            if (!bitExactOnLavapipe(function)) continue;
            for (size_t arity = 0; arity <= 5; ++arity) {
                std::vector<Type> args(arity);
                size_t combinations = 1;
                for (size_t i = 0; i < arity; ++i) combinations *= kTypes.size();
                for (size_t c = 0; c < combinations; ++c) {
                    for (size_t i = 0, rest = c; i < arity; ++i, rest /= kTypes.size()) args[i] = kTypes[rest % kTypes.size()];
                    if (std::optional<Type> result = function.typeRule(args)) byResult[*result].push_back({&function, args});
                }
            }
        }
        return byResult;
    }();
    return table;
}

std::string number(double v) { return fmt::format("{:.4g}", v); }

class Generator {
public:
    explicit Generator(uint64_t seed) : random_(seed) {}
    std::string program();

private:
    std::string expression(Type type, int depth);
    std::string leaf(Type type);
    std::string floatLiteral();
    void materials();
    void world();
    void start();
    void functions();
    void features();
    void fields();
    void grammars();
    void pipeline();
    std::string materialName() { return materials_[random_.below(uint32_t(materials_.size()))]; }
    std::string symbolCell();
    std::string transformCell();

    Random random_;
    std::string out_;
    std::array<int, 3> size_{};
    std::string stampBlock();

    std::vector<std::string> materials_, fields_, grammars_, lets_;
    std::vector<std::string> lsystemCaves_; // the lsystem_cave features among fields_
    std::vector<std::string> denseCaves_;   // dense lsystem_cave pipeline carves among fields_ (never stamped)
    // User functions so far (each takes two floats); inside a body, its parameters replace the
    // inputs, which function bodies may not read.
    std::vector<std::string> functions_;
    bool inFunction_ = false;
};

std::string Generator::floatLiteral() {
    // Zeros of both signs and ones: the operands drivers fold wrongly (docs/fuzzing.md).
    static constexpr std::array<std::string_view, 9> kSpecial = {"0.5", "0.25", "1.5", "0", "-0", "1", "-1", "0.1", "3"};
    if (random_.chance(0.4)) return std::string(kSpecial[random_.below(kSpecial.size())]);
    return number(random_.real(-20.0, 20.0));
}

std::string Generator::leaf(Type type) {
    static constexpr std::array<std::string_view, 6> kInputs = {"x", "y", "z", "wx", "wy", "wz"};
    static constexpr std::array<std::string_view, 6> kSwizzles2 = {"xy", "xz", "zy", "yx", "zx", "yy"};
    static constexpr std::array<std::string_view, 4> kSwizzles3 = {"xyz", "zyx", "xzy", "yyx"};
    if (inFunction_) {
        const char* parameter = random_.chance(0.5) ? "a" : "b";
        switch (type) {
        case Type::Float: return random_.chance(0.6) ? std::string(parameter) : floatLiteral();
        case Type::Int: return std::to_string(random_.range(0, 9));
        case Type::Bool: return fmt::format("{} < {}", parameter, floatLiteral());
        case Type::Vec2: return fmt::format("vec2({}, b)", parameter);
        case Type::Vec3: return fmt::format("vec3(a, {}, {})", parameter, floatLiteral());
        }
    }
    const std::string_view vector = random_.chance(0.5) ? "p" : "wp";
    switch (type) {
    case Type::Float:
        if (!lets_.empty() && random_.chance(0.3)) return lets_[random_.below(uint32_t(lets_.size()))];
        if (random_.chance(0.5)) return std::string(kInputs[random_.below(kInputs.size())]);
        if (random_.chance(0.2)) return fmt::format("{}.{}", vector, "xyz"[random_.below(3)]);
        return floatLiteral();
    case Type::Int: return std::to_string(random_.range(0, 9));
    case Type::Bool: return fmt::format("{} < {}", kInputs[random_.below(kInputs.size())], floatLiteral());
    case Type::Vec2: return fmt::format("{}.{}", vector, kSwizzles2[random_.below(kSwizzles2.size())]);
    case Type::Vec3:
        if (random_.chance(0.5)) return std::string(vector);
        return fmt::format("{}.{}", vector, kSwizzles3[random_.below(kSwizzles3.size())]);
    }
    return "0";
}

std::string Generator::expression(Type type, int depth) {
    if (type == Type::Int || depth <= 0 || random_.chance(0.25)) return leaf(type);
    if (type == Type::Float && lets_.size() < 3 && random_.chance(0.1)) {
        const std::string name = fmt::format("v{}", lets_.size());
        const std::string value = expression(Type::Float, depth - 1);
        lets_.push_back(name);
        std::string body = expression(Type::Float, depth - 1);
        lets_.pop_back();
        return fmt::format("(let {} = {} in {})", name, value, body);
    }
    if (type == Type::Float && !functions_.empty() && random_.chance(0.15)) {
        const std::string& function = functions_[random_.below(uint32_t(functions_.size()))];
        return fmt::format("{}({}, {})", function, expression(Type::Float, depth - 1), expression(Type::Float, depth - 1));
    }
    const auto found = overloadsByResult().find(type);
    if (found == overloadsByResult().end()) return leaf(type);
    const Overload& overload = found->second[random_.below(uint32_t(found->second.size()))];
    std::string call = std::string(overload.function->name) + "(";
    for (size_t i = 0; i < overload.args.size(); ++i)
        call += (i ? ", " : "") + expression(overload.args[i], depth - 1);
    return call + ")";
}

void Generator::materials() {
    const int count = random_.range(0, 3);
    std::vector<int> ids;
    for (int i = 0; i < count; ++i) {
        int id = random_.range(1, 255);
        while (std::find(ids.begin(), ids.end(), id) != ids.end()) id = id % 255 + 1;
        ids.push_back(id);
        materials_.push_back(fmt::format("m{}", i));
        out_ += fmt::format("material m{} {{ id = {}; }}\n", i, id);
    }
}

void Generator::world() {
    for (int& edge : size_) edge = random_.range(2, 14);
    out_ += fmt::format("world {{ size = [{}, {}, {}]; origin = [{}, {}, {}]; chunk = {}; seed = {}; }}\n", size_[0],
                        size_[1], size_[2], random_.range(-40, 40), random_.range(-40, 40), random_.range(-40, 40),
                        random_.chance(0.7) ? 8 : 16, random_.next() % 4294967296ull);
}

void Generator::start() {
    const int count = random_.range(0, 3);
    if (count == 0) return;
    out_ += "start {\n";
    const int edge = *std::max_element(size_.begin(), size_.end());
    for (int i = 0; i < count; ++i) {
        const ShapeInfo& shape = shapes()[random_.below(uint32_t(shapes().size()))];
        out_ += fmt::format("  {} {{", shape.name);
        for (const KeySpec& key : shape.keys) {
            if (!key.required && random_.chance(0.5)) continue;
            // Within the key's range and near the grid, where the shape is visible.
            const double lo = std::max(key.min, -4.0), hi = std::min(key.max, double(edge + 4));
            std::string value;
            switch (key.type) {
            case KeyType::Number: value = number(key.name == "value" ? random_.real(0.0, 1.0) : random_.real(lo, hi)); break;
            case KeyType::Integer: value = std::to_string(random_.range(int32_t(std::ceil(lo)), int32_t(std::floor(hi)))); break;
            case KeyType::Axis: value = std::string(1, "xyz"[random_.below(3)]); break;
            case KeyType::Vec3:
                value = fmt::format("[{}, {}, {}]", number(random_.real(lo, hi)), number(random_.real(lo, hi)),
                                    number(random_.real(lo, hi)));
                break;
            }
            out_ += fmt::format(" {} = {};", key.name, value);
        }
        if (!materials_.empty() && random_.chance(0.5)) out_ += fmt::format(" material = {};", materialName());
        out_ += " }\n";
    }
    out_ += "}\n";
}

// Each function may call the ones before it, so a chain of calls inlines into shared nodes.
void Generator::functions() {
    const int count = random_.range(0, 3);
    for (int i = 0; i < count; ++i) {
        inFunction_ = true;
        const std::string body = expression(Type::Float, random_.range(1, 3));
        inFunction_ = false;
        functions_.push_back(fmt::format("h{}", i));
        out_ += fmt::format("fn h{}(a: float, b: float) -> float = {};\n", i, body);
    }
}

// Dey's generators with a few of their keys (docs/language.md, "Features"), placed on the grid.
void Generator::features() {
    const int count = random_.range(0, 2);
    const auto point = [&] {
        return fmt::format("[{}, {}, {}]", random_.range(0, size_[0]), random_.range(0, size_[1]), random_.range(0, size_[2]));
    };
    for (int i = 0; i < count; ++i) {
        const std::string name = fmt::format("feature{}", i);
        std::string keys;
        if (random_.chance(0.2)) {
            // A tiny network: single moves from the start, each within one voxel of it, and a brush
            // reaching at most 0.55 + 1 voxels beyond, so a stamp of reach 3 holds it at any whole
            // offset in [-1, 1] (docs/language.md, "Stamps").
            static constexpr const char* kMoves[] = {"[F]", "[RF]", "[LF]", "[UF]", "[DF]", "[RRF]"};
            std::string axiom;
            for (int m = random_.range(1, 3); m > 0; --m) axiom += kMoves[random_.below(6)];
            out_ += fmt::format("lsystem net{} {{ axiom = \"{}\"; expansions = 0; step = 1; angle = {}; start = {}; }}\n", i,
                                axiom, random_.range(0, 180), point());
            keys = fmt::format("lsystem_cave {{ lsystem = net{}; radius = 0.5; clearance = 0.5; curl_amplitude = {}; "
                               "min_scale = 2;",
                               i, number(random_.real(0.0, 0.45)));
            lsystemCaves_.push_back(name);
        } else if (random_.chance(0.12)) {
            // A dense network carved as a pipeline stage: short steps and centres a quarter to half
            // a voxel apart put hundreds to thousands of centres in one 8^3 cell's list (lavapipe
            // once left the list loops early past about 1,500; docs/fuzzing.md).
            out_ += fmt::format("lsystem net{} {{ axiom = \"Z\"; expansions = {}; step = {}; angle = {}; start = {}; "
                                "production Z {{ \"FZ[RFZ]FZ[LFZ[RF]]\"; }} }}\n",
                                i, random_.range(2, 4), number(random_.real(0.5, 1.5)), random_.range(20, 90), point());
            keys = fmt::format("lsystem_cave {{ lsystem = net{}; radius = {}; spacing = {}; clearance = {};", i,
                               number(random_.real(1.0, 8.0)), number(random_.real(0.25, 0.5)),
                               number(random_.real(0.5, 1.0)));
            denseCaves_.push_back(name);
        } else
        switch (random_.below(3)) {
        case 0:
            keys = fmt::format("arch {{ start = {}; end = [{}, {}, {}]; radius = {}; iterations = {};", point(),
                               size_[0] + 1, random_.range(0, size_[1]), random_.range(0, size_[2]), random_.range(1, 4),
                               10 * random_.range(1, 3));
            break;
        case 1:
            keys = fmt::format("cave {{ start = {}; direction = [1, {}, 0]; mouth = {}; curl = {}; decay = {};", point(),
                               number(random_.real(-1.0, 1.0)), number(random_.real(1.0, 4.0)),
                               number(random_.real(0.0, 1.0)), number(random_.real(0.0, 1.0)));
            break;
        default:
            keys = fmt::format("overhang {{ min = [0, 0, 0]; max = [{}, {}, {}]; lip_height = {}; base_depth = {};",
                               size_[0], size_[1], size_[2], number(random_.real(0.0, 1.0)), number(random_.real(0.0, 1.0)));
            break;
        }
        const bool lsystemCave = (!lsystemCaves_.empty() && lsystemCaves_.back() == name) ||
                                 (!denseCaves_.empty() && denseCaves_.back() == name); // takes no `rotate`
        if (!lsystemCave && random_.chance(0.3)) keys += fmt::format(" rotate = [0, {}, 0];", random_.range(-90, 90));
        if (!materials_.empty() && random_.chance(0.5)) keys += fmt::format(" material = {};", materialName());
        fields_.push_back(name);
        out_ += fmt::format("feature {} = {} }}\n", name, keys);
    }
}

void Generator::fields() {
    const int count = random_.range(0, 3);
    for (int i = 0; i < count; ++i) {
        fields_.push_back(fmt::format("f{}", i));
        out_ += fmt::format("field f{} = {};\n", i, expression(Type::Float, random_.range(1, 5)));
    }
}

std::string Generator::symbolCell() {
    std::string cell;
    const int terms = random_.range(1, 2);
    for (int t = 0; t < terms; ++t) {
        if (t) cell += " & ";
        if (!materials_.empty() && random_.chance(0.2)) {
            const MaterialOpInfo& op = materialOps()[random_.below(uint32_t(materialOps().size()))];
            cell += fmt::format("{} {}", op.name, materialName());
            continue;
        }
        const SymbolOpInfo& op = symbolOps()[random_.below(uint32_t(symbolOps().size()))];
        cell += op.takesValue ? fmt::format("{} {}", op.name, number(random_.below(5) * 0.25)) : std::string(op.name);
    }
    return cell;
}

std::string Generator::transformCell() {
    const TransformOpInfo& op = transformOps()[random_.below(uint32_t(transformOps().size()))];
    const double value = random_.chance(0.1) ? 0.0 : random_.real(-1.0, 1.0); // ADD 0 turns a -0 density into +0
    std::string cell = op.takesValue ? fmt::format("{} {}", op.name, number(value)) : std::string(op.name);
    if (!materials_.empty() && random_.chance(0.2)) cell += fmt::format(" & MAT {}", materialName());
    return cell;
}

void Generator::grammars() {
    const int count = random_.range(0, 2);
    for (int g = 0; g < count; ++g) {
        grammars_.push_back(fmt::format("g{}", g));
        out_ += fmt::format("grammar g{} {{\n  iterations = {};\n", g, random_.range(1, 4));
        if (random_.chance(0.5)) out_ += "  clamp = [0, 1];\n";
        if (random_.chance(0.3))
            out_ += fmt::format("  stride = [{}, {}, {}];\n", random_.range(1, 2), random_.range(1, 2), random_.range(1, 2));
        if (random_.chance(0.3)) {
            std::array<int, 3> lo{}, hi{};
            for (int a = 0; a < 3; ++a) {
                lo[a] = random_.range(0, (size_[a] - 1) / 2);
                hi[a] = random_.range(lo[a] + 1, size_[a]);
            }
            out_ += fmt::format("  bounds = [[{}, {}, {}], [{}, {}, {}]];\n", lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
        }
        const int rules = random_.range(1, 3);
        for (int r = 0; r < rules; ++r) {
            const std::array<int, 3> window = {random_.range(1, 3), random_.range(1, 3), random_.range(1, 2)};
            out_ += fmt::format("  rule r{} {{\n    size = [{}, {}, {}];\n", r, window[0], window[1], window[2]);
            if (random_.chance(0.3)) out_ += fmt::format("    priority = {};\n", random_.range(-2, 2));
            if (random_.chance(0.3)) out_ += fmt::format("    weight = {};\n", number(random_.real(0.01, 5.0)));
            if (random_.chance(0.3)) out_ += fmt::format("    probability = {};\n", number(random_.real(0.0, 1.0)));
            if (random_.chance(0.25)) {
                // Up to 8 variants a rule: `all` (48) would make kernels the fuzzer's time goes into.
                static constexpr const char* kGroups[] = {"none", "x", "z", "xz", "rot_y", "square", "xyz"};
                out_ += fmt::format("    symmetry = {};\n", kGroups[random_.range(0, 6)]);
            }
            for (const bool symbol : {true, false}) {
                out_ += symbol ? "    symbol {\n" : "    transform {\n";
                for (int z = 0; z < window[2]; ++z) {
                    out_ += "      layer {";
                    for (int y = 0; y < window[1]; ++y) {
                        out_ += " [";
                        for (int x = 0; x < window[0]; ++x) out_ += (x ? ", " : "") + (symbol ? symbolCell() : transformCell());
                        out_ += "]";
                    }
                    out_ += " }\n";
                }
                out_ += "    }\n";
            }
            if (random_.chance(0.25)) {
                // A `where` test over the window or its bottom row (docs/language.md, "Aggregate tests").
                static constexpr const char* kAggregates[] = {"mean", "min", "max", "solid_fraction"};
                const double low = random_.real(-0.2, 0.8);
                const bool fraction = random_.chance(0.25);
                const bool bottomRow = random_.chance(0.5);
                const char* kind = fraction ? "solid_fraction" : kAggregates[random_.range(0, 2)];
                std::string lowText = number(fraction ? std::max(0.0, low) : low),
                            highText = number(fraction ? 1.0 : low + random_.real(0.0, 1.2));
                if (!fraction && random_.chance(0.3)) {
                    // Bounds at the ends of the float range: a mean's bounds times the box's cells
                    // bound its sum and must be floats, so they reach the largest float over the
                    // cells (docs/language.md); min and max reach the largest float itself.
                    const int cells = window[0] * window[2] * (bottomRow ? 1 : window[1]);
                    const double largest = double(std::numeric_limits<float>::max()) / (kind == std::string_view("mean") ? cells : 1);
                    static constexpr double kShares[] = {1.0 - 1e-6, 0.5, 1e-8};
                    const auto extreme = [&] { return fmt::format("{:.6e}", largest * kShares[random_.below(3)]); };
                    if (random_.chance(0.5)) lowText = "-" + extreme();
                    if (random_.chance(0.7)) highText = extreme();
                }
                out_ += fmt::format("    where {{ {}{} = [{}, {}]; }}\n",
                                    bottomRow ? fmt::format("box = [[0, 0, 0], [{}, 1, {}]]; ", window[0], window[2]) : "",
                                    kind, lowText, highText);
            }
            if (!fields_.empty() && random_.chance(0.3)) out_ += stampBlock();
            out_ += "  }\n";
        }
        out_ += "}\n";
    }
}

// A stamp of a field or feature (docs/language.md, "Stamps"): reach at most 3 per axis, so the
// grown windows of one phase cover a voxel at most 7^3 times, under Limits::maxStampOverlap.
std::string Generator::stampBlock() {
    static constexpr std::array<std::string_view, 4> kModes = {"union", "subtract", "set", "intersect"};
    std::vector<std::string> stampable; // a dense network does not fit a stamp's reach of 3
    for (const std::string& f : fields_)
        if (std::find(denseCaves_.begin(), denseCaves_.end(), f) == denseCaves_.end()) stampable.push_back(f);
    if (stampable.empty()) return "";
    const std::string& field = stampable[random_.below(uint32_t(stampable.size()))];
    const bool lsystemCave = std::find(lsystemCaves_.begin(), lsystemCaves_.end(), field) != lsystemCaves_.end();
    std::string keys;
    if (random_.chance(0.8)) keys += fmt::format(" mode = {};", kModes[random_.below(kModes.size())]);
    if (lsystemCave)
        keys += " reach = 3;";
    else if (random_.chance(0.5))
        keys += fmt::format(" reach = {};", random_.range(0, 3));
    else
        keys += fmt::format(" reach = [{}, {}, {}];", random_.range(0, 3), random_.range(0, 3), random_.range(0, 3));
    if (random_.chance(0.5)) {
        const auto offset = [&] {
            return lsystemCave || random_.chance(0.5) ? std::to_string(random_.range(-1, 1)) : number(random_.real(-2.0, 2.0));
        };
        keys += fmt::format(" offset = [{}, {}, {}];", offset(), offset(), offset());
    }
    if (!materials_.empty() && random_.chance(0.4)) keys += fmt::format(" material = {};", materialName());
    return fmt::format("    stamp {} {{{} }}\n", field, keys);
}

// Every field, feature and grammar runs at least once, in random order, plus up to two repeats.
void Generator::pipeline() {
    static constexpr std::array<std::string_view, 4> kModes = {"set", "union", "subtract", "intersect"};
    std::vector<std::string> stages = fields_;
    stages.insert(stages.end(), grammars_.begin(), grammars_.end());
    if (stages.empty()) {
        out_ += "pipeline { start; }\n";
        return;
    }
    for (int extra = random_.range(0, 2); extra > 0; --extra) stages.push_back(stages[random_.below(uint32_t(stages.size()))]);
    for (size_t i = stages.size() - 1; i > 0; --i) std::swap(stages[i], stages[random_.below(uint32_t(i + 1))]);
    out_ += "pipeline { start;";
    for (const std::string& name : stages) {
        if (std::find(grammars_.begin(), grammars_.end(), name) != grammars_.end()) {
            out_ += fmt::format(" {};", name);
        } else if (!materials_.empty() && random_.chance(0.2)) {
            out_ += fmt::format(" paint {} material {};", name, materialName());
        } else {
            out_ += fmt::format(" {} {}", kModes[random_.below(kModes.size())], name);
            if (!materials_.empty() && random_.chance(0.3)) out_ += fmt::format(" material {}", materialName());
            out_ += ";";
        }
    }
    out_ += " }\n";
}

std::string Generator::program() {
    materials();
    world();
    start();
    functions();
    fields();
    features();
    grammars();
    pipeline();
    return out_;
}

} // namespace

std::string generateProgram(uint64_t seed) { return Generator(seed).program(); }

} // namespace voxc::fuzz
