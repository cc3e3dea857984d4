// CPU vs GPU for every builtin function: for each record of voxc::functions() and each
// argument-type list its type rule accepts, a compute kernel evaluates record.glsl(...) on
// arguments derived from the invocation index, runs as the start stage of a hand-built
// KernelPackage on Vulkan (lavapipe on CI), and every result component is compared with
// record.eval on the same arguments within record.tolerance. A second pass draws a third of the
// float components from special values (NaN, infinities, signed zeros, the float limits):
// there both sides must agree on NaN and on each infinity (docs/language.md, "Non-finite
// values"), and a bit-exact record bit for bit.
#include "Signatures.h"
#include "TestKernels.h"

#include "voxc/builtins/Ops.h"
#include "voxc/program/Random.h"
#include "voxc/shaders/ShaderSources.h"
#include "voxc/vulkan/Executor.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <fmt/format.h>
#include <iterator>
#include <map>
#include <set>

namespace voxc {
namespace {

// 64 x 64 samples; sample s sits at grid column (s % 64, s / 64) and writes component c at y = c
// with the usual arguments and at y = kSpecialsRow + c with special ones mixed in: one kernel per
// overload serves both tests, so lavapipe compiles each overload once.
constexpr int kSide = 64;
constexpr int kSamples = kSide * kSide;
constexpr int kSpecialsRow = 3;

// How one argument's values are drawn; both sides compute them with the same float operations.
struct Domain {
    enum Kind { Coordinate, Range, IntRange, Seed } kind;
    float lo = 0, hi = 0;
};

// Defaults: float/vector components are coordinates (|x| up to 2, 50, 1000 or 1e4 by sample),
// ints are seeds. Overrides keep arguments where a function is defined and its tolerance holds.
Domain domainFor(std::string_view name, const std::vector<Type>& args, size_t index) {
    const bool fractal = name == "fbm" || name == "ridged" || name == "turbulence";
    if (name == "sqrt") return {Domain::Range, 0.0f, 10000.0f};
    if (name == "length") return {Domain::Range, -100.0f, 100.0f};
    if (name == "pow") return index == 0 ? Domain{Domain::Range, 0.1f, 10.0f} : Domain{Domain::Range, -3.0f, 3.0f};
    if (name == "sin" || name == "cos") return {Domain::Range, -3.14159265f, 3.14159265f};
    if (name.starts_with("sdf_") || name == "density") return {Domain::Range, -50.0f, 50.0f};
    if (fractal && index == 1) return {Domain::IntRange, 1, 16};
    if (fractal && index == 2) return {Domain::Range, 1.5f, 3.0f};
    if (fractal && index == 3) return {Domain::Range, 0.2f, 0.8f};
    if (name == "warp" && index == 1) return {Domain::Range, -4.0f, 4.0f};
    if (name == "warped_fbm" && args.size() == 5 && index >= 1 && index <= 3) return {Domain::Range, 0.0f, 2.0f};
    return args[index] == Type::Int ? Domain{Domain::Seed} : Domain{Domain::Coordinate};
}

uint32_t sampleBits(uint32_t sample, uint32_t arg, uint32_t component) {
    return mix32(mix32(sample * 8u + arg) ^ (component + 0x51u));
}

// The special values' bits: NaN, +inf, -inf, +0, -0, +-FLT_MAX, 1e30, 1, -2.
constexpr uint32_t kSpecialBits[] = {0x7FC00000u, 0x7F800000u, 0xFF800000u, 0x00000000u, 0x80000000u,
                                     0x7F7FFFFFu, 0xFF7FFFFFu, 0x7149F2CAu, 0x3F800000u, 0xC0000000u};
constexpr uint32_t kSpecialCount = std::size(kSpecialBits);

// In the special pass, a component whose draw is 0 mod 3 is a special value (chosen by the
// next bits); the others keep their domain.
bool isSpecial(bool specials, uint32_t sample, uint32_t arg, uint32_t component) {
    return specials && sampleBits(sample, arg, component) % 3u == 0u;
}

float sampleFloat(const Domain& d, uint32_t sample, uint32_t arg, uint32_t component, bool specials) {
    if (isSpecial(specials, sample, arg, component))
        return std::bit_cast<float>(kSpecialBits[(sampleBits(sample, arg, component) >> 2) % kSpecialCount]);
    const float unit = float(sampleBits(sample, arg, component) >> 8) * 5.9604644775390625e-8f;
    if (d.kind == Domain::Coordinate) {
        const float scales[4] = {2.0f, 50.0f, 1000.0f, 10000.0f};
        return (unit * 2.0f - 1.0f) * scales[sample % 4];
    }
    return d.lo + unit * (d.hi - d.lo);
}

int32_t sampleInt(const Domain& d, uint32_t sample, uint32_t arg) {
    const uint32_t bits = sampleBits(sample, arg, 0);
    if (d.kind == Domain::IntRange) return int32_t(d.lo) + int32_t(bits % uint32_t(d.hi - d.lo + 1));
    return sample % 8 == 0 ? 0 : int32_t(bits);
}

// The GLSL of the two functions above.
constexpr const char* kSamplingGlsl = R"(
uint sampleBits(uint s, uint arg, uint component) { return mix32(mix32(s * 8u + arg) ^ (component + 0x51u)); }
float sampleUnit(uint s, uint arg, uint component) {
    precise float r = float(sampleBits(s, arg, component) >> 8) * 5.9604644775390625e-8;
    return r;
}
float sampleCoordinate(uint s, uint arg, uint component) {
    float scales[4] = float[4](2.0, 50.0, 1000.0, 10000.0);
    precise float r = (sampleUnit(s, arg, component) * 2.0 - 1.0) * scales[s % 4u];
    return r;
}
float sampleRange(uint s, uint arg, uint component, float lo, float span) {
    precise float r = lo + sampleUnit(s, arg, component) * span;
    return r;
}
int sampleSeed(uint s, uint arg) { return s % 8u == 0u ? 0 : int(sampleBits(s, arg, 0u)); }
float sampleSpecial(uint s, uint arg, uint component, float usual) {
    uint bits = sampleBits(s, arg, component);
    if (!specials || bits % 3u != 0u) return usual;
    uint special[SPECIAL_COUNT] = uint[SPECIAL_COUNT](SPECIAL_BITS);
    return uintBitsToFloat(special[(bits >> 2) % uint(SPECIAL_COUNT)]);
}
)";

std::string glslComponent(const Domain& d, size_t arg, int component) {
    const std::string where = "s, " + std::to_string(arg) + "u, " + std::to_string(component) + "u";
    if (d.kind == Domain::Coordinate) return "sampleSpecial(" + where + ", sampleCoordinate(" + where + "))";
    return "sampleSpecial(" + where + ", sampleRange(" + where + ", " + glslFloat(d.lo) + ", " + glslFloat(d.hi - d.lo) +
           "))";
}

std::string glslArgument(const Domain& d, Type type, size_t arg) {
    switch (type) {
    case Type::Int:
        if (d.kind == Domain::IntRange)
            return std::to_string(int(d.lo)) + " + int(sampleBits(s, " + std::to_string(arg) + "u, 0u) % " +
                   std::to_string(int(d.hi - d.lo + 1)) + "u)";
        return "sampleSeed(s, " + std::to_string(arg) + "u)";
    case Type::Float: return glslComponent(d, arg, 0);
    case Type::Vec2: return "vec2(" + glslComponent(d, arg, 0) + ", " + glslComponent(d, arg, 1) + ")";
    case Type::Vec3:
        return "vec3(" + glslComponent(d, arg, 0) + ", " + glslComponent(d, arg, 1) + ", " + glslComponent(d, arg, 2) + ")";
    case Type::Bool: return "((sampleBits(s, " + std::to_string(arg) + "u, 0u) & 1u) == 1u)";
    }
    throw std::runtime_error("no sample domain");
}

Value cpuArgument(const Domain& d, Type type, uint32_t sample, uint32_t arg, bool specials) {
    Value v;
    v.type = type;
    if (type == Type::Int) v.i = sampleInt(d, sample, arg);
    if (type == Type::Bool) v.b = (sampleBits(sample, arg, 0) & 1u) == 1u;
    const int n = type == Type::Vec3 ? 3 : type == Type::Vec2 ? 2 : type == Type::Float ? 1 : 0;
    for (int c = 0; c < n; ++c) v.v[c] = sampleFloat(d, sample, arg, uint32_t(c), specials);
    return v;
}

// Results are stored as floats, exactly: a bool as 0 or 1, an int as its low and high 16 bits.
int componentCount(Type t) { return t == Type::Vec3 ? 3 : t == Type::Vec2 || t == Type::Int ? 2 : 1; }

std::string glslResultComponent(Type t, int c) {
    if (t == Type::Bool) return "(r ? 1.0 : 0.0)";
    if (t == Type::Int) return c == 0 ? "float(uint(r) & 0xFFFFu)" : "float(uint(r) >> 16)";
    return t == Type::Float ? "r" : "r[" + std::to_string(c) + "]";
}

float cpuResultComponent(const Value& v, int c) {
    if (v.type == Type::Bool) return v.b ? 1.0f : 0.0f;
    if (v.type == Type::Int) return float(c == 0 ? uint32_t(v.i) & 0xFFFFu : uint32_t(v.i) >> 16);
    return v.v[c];
}

std::string kernelSource(const FunctionInfo& info, const test::Overload& overload) {
    std::string source = "#version 450\nlayout(local_size_x = 8, local_size_y = 1, local_size_z = 8) in;\n";
    std::string bits;
    for (uint32_t b : kSpecialBits) bits += (bits.empty() ? "" : ", ") + std::to_string(b) + "u";
    source += fmt::format("#define SPECIALS_ROW {}\n#define SPECIAL_COUNT {}\n#define SPECIAL_BITS {}\n",
                          kSpecialsRow, kSpecialCount, bits);
    source += shaderSource("common.glsl");
    std::set<std::string_view> included{"random.glsl"}; // the sampling code below needs mix32
    source += shaderSource("random.glsl");
    for (std::string_view library : info.glslLibraries)
        if (included.insert(library).second) source += shaderSource(library);
    source += "bool specials; // set by main: which of the two rows this invocation samples\n";
    source += kSamplingGlsl;
    std::vector<std::string> args;
    std::string body;
    for (size_t i = 0; i < overload.args.size(); ++i) {
        const Type t = overload.args[i];
        body += "    " + std::string(typeName(t)) + " a" + std::to_string(i) + " = " +
                glslArgument(domainFor(info.name, overload.args, i), t, i) + ";\n";
        args.push_back("a" + std::to_string(i));
    }
    body += "    " + std::string(typeName(overload.result)) + " r = " + info.glsl(args, overload.args) + ";\n";
    for (int c = 0; c < componentCount(overload.result); ++c) {
        const std::string value = glslResultComponent(overload.result, c);
        body += "    voxels.density[voxelAddress(ivec3(local.x, local.y + " + std::to_string(c) + ", local.z))] = " + value + ";\n";
    }
    return source + R"(
void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, push.anchorCount.xyz))) return;
    ivec3 local = push.anchorStart.xyz + cell * push.anchorStep.xyz;
    if (local.y != 0 && local.y != SPECIALS_ROW) return;
    specials = local.y == SPECIALS_ROW;
    uint s = uint(local.x + )" + std::to_string(kSide) + R"( * local.z);
)" + body + "}\n";
}

KernelPackage packageFor(const std::string& source) {
    KernelPackage package;
    package.world.size = {kSide, 2 * kSpecialsRow, kSide};
    package.world.origin = {0, 0, 0};
    package.world.chunkSize = 32;
    Kernel kernel;
    kernel.name = "function";
    kernel.origin = "tests/functions/GpuAgreementTest.cpp";
    kernel.glsl = source;
    kernel.spirv = test::compileGlsl(source);
    kernel.localSize[0] = 8;
    kernel.localSize[1] = 1;
    kernel.localSize[2] = 8;
    package.kernels.push_back(kernel);
    StagePlan start;
    start.kind = "start";
    start.gridKernel = 0;
    package.stages.push_back(start);
    return package;
}

VulkanContext& context() {
    static VulkanContext instance;
    return instance;
}

class functions_GpuAgreement : public testing::TestWithParam<std::string_view> {};

// Where the special pass requires agreement: the same NaN-ness, the same infinity, and for a
// bit-exact record the same bits. Finite results of inexact records may differ there, since
// their tolerances hold on the usual domains only, and so may their overflow: a result within a
// few ulp of FLT_MAX (pow(FLT_MAX, 1)) may round to an infinity of the same sign on one side.
bool specialAgrees(float expected, float actual, float tolerance) {
    if (std::isnan(expected) || std::isnan(actual)) return std::isnan(expected) && std::isnan(actual);
    const bool inexact = tolerance > 0.0f;
    if (std::isinf(expected) || std::isinf(actual)) {
        const bool nearLimit = std::fabs(expected) >= 0x1p127f && std::fabs(actual) >= 0x1p127f &&
                               std::signbit(expected) == std::signbit(actual);
        return expected == actual || (inexact && nearLimit);
    }
    return inexact || std::bit_cast<uint32_t>(expected) == std::bit_cast<uint32_t>(actual);
}

// The overload's results on the device, both rows, run once and kept for the other test.
const DenseGrid& deviceResults(const FunctionInfo& info, const test::Overload& overload, const std::string& what) {
    static std::map<std::string, DenseGrid> results;
    auto found = results.find(what);
    if (found == results.end()) {
        VulkanExecutor executor(context(), packageFor(kernelSource(info, overload)));
        found = results.emplace(what, executor.run().grid.toDense()).first;
    }
    return found->second;
}

// Runs every overload of the record on the device and compares each sample with record.eval.
void expectAgreement(const FunctionInfo& info, bool specials) {
    const std::vector<test::Overload> overloads = test::acceptedOverloads(info);
    ASSERT_FALSE(overloads.empty());
    for (const test::Overload& overload : overloads) {
        const std::string what = test::describe(info, overload.args);
        const DenseGrid& gpu = deviceResults(info, overload, what);
        const int row = specials ? kSpecialsRow : 0;
        float maxDifference = 0.0f;
        int failures = 0;
        for (uint32_t s = 0; s < uint32_t(kSamples); ++s) {
            std::vector<Value> args;
            for (size_t i = 0; i < overload.args.size(); ++i)
                args.push_back(
                    cpuArgument(domainFor(info.name, overload.args, i), overload.args[i], s, uint32_t(i), specials));
            const Value cpu = info.eval(args);
            ASSERT_EQ(cpu.type, overload.result) << what;
            for (int c = 0; c < componentCount(overload.result); ++c) {
                const float expected = cpuResultComponent(cpu, c);
                const float actual = gpu.at({int(s) % kSide, row + c, int(s) / kSide});
                if (!specials) { ASSERT_TRUE(std::isfinite(expected)) << what << " sample " << s; }
                const float difference = std::fabs(actual - expected);
                if (!specials) maxDifference = std::max(maxDifference, difference);
                const bool agrees = specials ? specialAgrees(expected, actual, info.tolerance)
                                             : difference <= info.tolerance;
                if (!agrees && failures++ < 5) {
                    std::string argText;
                    for (const Value& a : args)
                        argText += fmt::format(" ({}, {}, {} | {})", a.v.x, a.v.y, a.v.z, a.i);
                    ADD_FAILURE() << what << " sample " << s << " component " << c << ": GPU " << actual << ", CPU "
                                  << expected << ", difference " << difference << " > tolerance " << info.tolerance
                                  << "; args" << argText;
                }
            }
        }
        EXPECT_EQ(failures, 0) << what;
        if (!specials)
            std::cout << "[ max |GPU - CPU| ] " << what << ": " << maxDifference << " (tolerance " << info.tolerance
                      << ")\n";
    }
}

// One test per record (named by the record), each covering all of its overloads.

TEST_P(functions_GpuAgreement, EveryOverloadMatchesTheInterpreterWithinTolerance) {
    const FunctionInfo* info = findFunction(GetParam());
    ASSERT_NE(info, nullptr);
    expectAgreement(*info, false);
}

TEST_P(functions_GpuAgreement, NonFiniteAndSpecialArgumentsAgree) {
    const FunctionInfo* info = findFunction(GetParam());
    ASSERT_NE(info, nullptr);
    expectAgreement(*info, true);
}

std::vector<std::string_view> allNames() {
    std::vector<std::string_view> names;
    for (const FunctionInfo& f : functions()) names.push_back(f.name);
    return names;
}

INSTANTIATE_TEST_SUITE_P(, functions_GpuAgreement, testing::ValuesIn(allNames()),
                         [](const testing::TestParamInfo<std::string_view>& p) { return std::string(p.param); });

} // namespace
} // namespace voxc
