// Bounds on one generated kernel (docs/language.md, "Limits"): the loop iterations one invocation
// of a stamp or speleothem kernel may take (lavapipe silently leaves every loop of an invocation
// group after 65,535 iterations) and the field code a sweep's stamp kernel holds. Each is E0012
// with the number at the place that decides it; a program exactly at a limit checks, one past it
// does not.
#include "CheckTestUtil.h"

#include <gtest/gtest.h>

#include <regex>
#include <string>

namespace voxc {
namespace kernel_bounds_test {

using test::codes;

CheckResult checkWith(const std::string& text, const Limits& limits = Limits()) {
    return checkSource(SourceFile("test.vox", text), limits);
}

// The number N of "... may loop N times" in the first diagnostic.
int64_t loopsSaid(const CheckResult& result) {
    std::smatch match;
    const std::string message = result.diagnostics.at(0).message;
    if (!std::regex_search(message, match, std::regex("may loop ([0-9]+) times"))) return -1;
    return std::stoll(match[1]);
}

// With maxKernelLoopIterations at `loops` the text checks; one below, it is the same E0012 with
// the same count.
void expectRefusedOnlyBelowItsCount(const std::string& text, int64_t loops) {
    Limits limits;
    limits.maxKernelLoopIterations = loops;
    EXPECT_FALSE(checkWith(text, limits).hasErrors());
    limits.maxKernelLoopIterations = loops - 1;
    const CheckResult past = checkWith(text, limits);
    ASSERT_EQ(codes(past), std::vector<std::string>{"E0012"});
    EXPECT_EQ(loopsSaid(past), loops);
}

// A dense network (steps of 0.5, centres a quarter voxel apart: 82 loop iterations per lookup in
// its fullest cell) stamped by a 1x1x1 rule whose reach holds it, the anchors `stride` apart:
// up to 896 firings cover a voxel at stride [8, 6, 6].
std::string denseStamp(const std::string& step, const std::string& stride, const std::string& symmetry = "") {
    return "world { size = [64, 48, 64]; seed = 3; }\n"
           "start { fill { value = 1; } }\n"
           "lsystem net {\n"
           "  axiom = \"Z\";\n"
           "  expansions = 3; angle = 45; step = " + step + ";\n"
           "  production Z { \"FZ[RFZ]FZ[LFZ[RF]]\"; }\n"
           "}\n"
           "feature tunnels = lsystem_cave { lsystem = net; radius = 3; spacing = 0.25; clearance = 1; }\n"
           "grammar dig {\n"
           "  bounds = [[0, 0, 0], [64, 48, 64]];\n"
           "  stride = " + stride + ";\n" + symmetry +
           "  rule r {\n"
           "    size = [1, 1, 1];\n"
           "    probability = 0.01;\n"
           "    symbol { [PRES] }\n"
           "    transform { [NOP] }\n"
           "    stamp tunnels { mode = subtract; reach = [28, 20, 21]; }\n"
           "  }\n"
           "}\n"
           "pipeline { start; dig; }\n";
}

TEST(check_KernelBounds, AStampPassThatCouldLoopPastTheLimitIsRefusedAtTheReach) {
    const std::string text = denseStamp("0.5", "[8, 6, 6]");
    const CheckResult refused = checkWith(text);
    ASSERT_EQ(codes(refused), std::vector<std::string>{"E0012"}) << refused.rendered();
    EXPECT_EQ(refused.diagnostics[0].loc.line, 17u);
    EXPECT_EQ(refused.diagnostics[0].loc.column, 46u);
    EXPECT_NE(refused.diagnostics[0].message.find("more than the limit of 65535 a kernel may loop"), std::string::npos)
        << refused.diagnostics[0].message;
    const int64_t loops = loopsSaid(refused);
    ASSERT_GT(loops, 65535) << refused.diagnostics[0].message;

    // At the limit it checks; one past, the same error with the same count.
    expectRefusedOnlyBelowItsCount(text, loops);

    // Anchors spaced further apart cover a voxel fewer times: the same carve checks.
    const CheckResult spaced = checkWith(denseStamp("0.5", "[16, 12, 12]"));
    EXPECT_FALSE(spaced.hasErrors()) << spaced.rendered();
}

// A symmetry variant shares its rule's stamp code (stamp.glsl reads the variant from a table), so
// `symmetry = all` loops no more per firing than the written rule alone.
TEST(check_KernelBounds, SymmetryVariantsShareTheirStampsLoops) {
    const CheckResult plain = checkWith(denseStamp("0.5", "[8, 6, 6]"));
    const CheckResult all = checkWith(denseStamp("0.5", "[8, 6, 6]", "  symmetry = all;\n"));
    ASSERT_EQ(codes(all), std::vector<std::string>{"E0012"}) << all.rendered();
    // Each variant's reach is its axes' turn of [28, 20, 21]: the largest cover a voxel more often.
    EXPECT_GE(loopsSaid(all), loopsSaid(plain));
    EXPECT_LT(loopsSaid(all), 2 * loopsSaid(plain));
}

// A hoodoo (four source columns) in a 256-voxel-high grid keeping a dense carve clear: each voxel
// it grows is tested against lists of hundreds of centres and segments.
std::string denseKeepClear(const std::string& height, const std::string& keepClear) {
    return "world { size = [48, " + height + ", 48]; seed = 3; }\n"
           "start { fill { value = 1; } }\n"
           "lsystem net {\n"
           "  axiom = \"Z\";\n"
           "  expansions = 4; angle = 45; step = 0.5; start = [24, 20, 24];\n"
           "  production Z { \"FZ[RFZ]FZ[LFZ[RF]]\"; }\n"
           "}\n"
           "feature tunnels = lsystem_cave { lsystem = net; radius = 8; spacing = 0.25; clearance = 1; }\n"
           "feature drips = speleothems { kind = hoodoo;" + keepClear + " }\n"
           "pipeline { start; subtract tunnels; drips; }\n";
}

TEST(check_KernelBounds, ASpeleothemKernelThatCouldLoopPastTheLimitIsRefusedAtTheFeature) {
    const std::string text = denseKeepClear("256", " keep_clear = tunnels;");
    const CheckResult refused = checkWith(text);
    ASSERT_EQ(codes(refused), std::vector<std::string>{"E0012"}) << refused.rendered();
    EXPECT_EQ(refused.diagnostics[0].loc.line, 9u);
    EXPECT_EQ(refused.diagnostics[0].loc.column, 9u);
    EXPECT_NE(refused.diagnostics[0].message.find("speleothems 'drips': a column of its grow kernel"), std::string::npos);
    const int64_t loops = loopsSaid(refused);
    ASSERT_GT(loops, 65535) << refused.diagnostics[0].message;

    expectRefusedOnlyBelowItsCount(text, loops);

    // Without keep_clear the column's loops stay far under the limit at any height; a lower grid
    // tests fewer voxels against the lists.
    EXPECT_FALSE(checkWith(denseKeepClear("512", ""), Limits()).hasErrors());
    const CheckResult lower = checkWith(denseKeepClear("40", " keep_clear = tunnels;"));
    EXPECT_FALSE(lower.hasErrors()) << lower.rendered();
}

// Two rules of one window size stamp two fields: the sweep's stamp kernel holds both fields'
// code. Exactly at maxKernelFieldNodes it checks; one node less, E0012 at the stamp that passes.
TEST(check_KernelBounds, AStampKernelHoldsAtMostTheFieldNodesOfTheLimit) {
    const std::string text =
        "world { size = [32, 32, 32]; }\n"
        "field ball = density(length(vec3(x, y, z) - vec3(1, 1, 1)) - 2, 1);\n"
        "field ridge = density(y - 2 + 0.5 * perlin3(vec3(x, y, z) * 0.3, 4) + sin(x * 0.2), 1);\n"
        "grammar g {\n"
        "  stride = [4, 4, 4];\n"
        "  symmetry = all;\n"
        "  rule a {\n"
        "    size = [2, 1, 1];\n"
        "    symbol { [PRES, ABS] }\n"
        "    transform { [NOP, NOP] }\n"
        "    stamp ball { mode = union; reach = 2; }\n"
        "  }\n"
        "  rule b {\n"
        "    size = [2, 1, 1];\n"
        "    symbol { [ABS, PRES] }\n"
        "    transform { [NOP, NOP] }\n"
        "    stamp ridge { mode = union; reach = 2; }\n"
        "  }\n"
        "}\n";
    const CheckResult checked = checkWith(text);
    ASSERT_FALSE(checked.hasErrors()) << checked.rendered();
    int64_t nodes = 0;
    for (const Field& field : checked.program->fields) nodes += int64_t(field.nodes.size());
    ASSERT_GT(nodes, 10);

    // The 48 variants of each rule share its stamp's code: the kernel holds each field once.
    Limits limits;
    limits.maxKernelFieldNodes = nodes;
    EXPECT_FALSE(checkWith(text, limits).hasErrors());
    limits.maxKernelFieldNodes = nodes - 1;
    const CheckResult past = checkWith(text, limits);
    ASSERT_EQ(codes(past), std::vector<std::string>{"E0012"}) << past.rendered();
    EXPECT_EQ(past.diagnostics[0].loc.line, 17u); // rule b's stamp, the one that passes
    EXPECT_EQ(past.diagnostics[0].loc.column, 11u);
    EXPECT_NE(past.diagnostics[0].message.find(std::to_string(nodes) + " field nodes with this stamp of 'ridge'"),
              std::string::npos)
        << past.diagnostics[0].message;
}

} // namespace kernel_bounds_test
} // namespace voxc
