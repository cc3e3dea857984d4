// Heightmaps and meshes as inputs of a curves block (docs/curves.md, "Heightmaps and meshes as
// inputs"; Becher et al. §3.3): the dead zone drops exactly the lower-priority input's cells
// within its radius of a higher-priority one's (against a brute-force Chebyshev oracle), the
// solved surface follows a flat imported ground far from a curve and the curve near it, and the
// keys' errors are located.
#include "InputFiles.h"

#include "voxc/check/Check.h"
#include "voxc/generators/curves/Voxelize.h"
#include "voxc/stages/Pipeline.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace voxc {
namespace curves_inputs_test {

namespace fs = std::filesystem;
using curves::Box;
using curves::Constraints;
using curves::InputSurface;

fs::path scratch() {
    const fs::path dir = fs::temp_directory_path() / fmt::format("voxc_curves_inputs_test_{}", ::getpid());
    fs::create_directories(dir);
    return dir;
}

// A flat seed ribbon along x at height y, centred on z, three voxels either side (the default
// bitangents), over the whole box.
curves::FeatureCurve flatCurve(double y, double z, double xLo, double xHi) {
    curves::FeatureCurve c;
    for (int i = 0; i < 4; ++i) c.points.push_back({xLo + (xHi - xLo) * i / 3.0, y, z});
    for (double t : {0.0, 1.0}) {
        curves::ConstraintPoint p;
        p.t = t;
        c.constraints.push_back(p);
    }
    return c;
}

std::shared_ptr<const InputSurface> flatHeightmap(const Box& box, double height) {
    auto surface = std::make_shared<InputSurface>();
    surface->kind = InputSurface::Kind::Heightmap;
    surface->name = "flat";
    surface->heights.assign(size_t(box.size.x + 2) * size_t(box.size.z + 2), height);
    return surface;
}

// The 12 triangles of an axis-aligned box, counter-clockwise seen from outside.
std::shared_ptr<const InputSurface> boxMesh(glm::dvec3 lo, glm::dvec3 hi) {
    const test::Shape shape = test::box(glm::vec3(lo), glm::vec3(hi));
    auto surface = std::make_shared<InputSurface>();
    surface->kind = InputSurface::Kind::Mesh;
    surface->name = "block";
    for (const glm::uvec3& t : shape.triangles)
        surface->triangles.push_back(
            {glm::dvec3(shape.points[t.x]), glm::dvec3(shape.points[t.y]), glm::dvec3(shape.points[t.z])});
    return surface;
}

std::vector<glm::ivec3> hitCells(const Constraints& cs) {
    std::vector<glm::ivec3> out;
    for (int z = 0; z < cs.box.size.z; ++z)
        for (int y = 0; y < cs.box.size.y; ++y)
            for (int x = 0; x < cs.box.size.x; ++x)
                if (cs.flags[cs.box.index(x, y, z)] & curves::kInParams) out.push_back({x, y, z});
    return out;
}

int chebyshev(glm::ivec3 a, glm::ivec3 b) {
    const glm::ivec3 d = glm::abs(a - b);
    return std::max({d.x, d.y, d.z});
}

bool nearAny(glm::ivec3 cell, const std::vector<glm::ivec3>& others, int radius) {
    return std::any_of(others.begin(), others.end(), [&](glm::ivec3 o) { return chebyshev(cell, o) <= radius; });
}

// Every cell of `part` carries in `whole` exactly the values it has when voxelised alone.
void expectSameValues(const Constraints& whole, const Constraints& part, const std::vector<glm::ivec3>& cells) {
    for (glm::ivec3 c : cells) {
        const size_t i = whole.box.index(c.x, c.y, c.z);
        ASSERT_EQ(whole.flags[i], part.flags[i]);
        EXPECT_EQ(whole.normalY.values[i], part.normalY.values[i]);
        EXPECT_EQ(whole.surface.values[i], part.surface.values[i]);
        EXPECT_EQ(whole.amplitude.values[i], part.amplitude.values[i]);
        EXPECT_EQ(whole.material[i], part.material[i]);
    }
}

// Curves over meshes over heightmaps: at every dead-zone radius, the constrained cells are the
// curve's, the mesh's farther than the radius from every curve cell, and the heightmap's farther
// than it from both of those; each keeps the values it has alone.
TEST(CurvesInputs, DeadZoneDropsExactlyTheLowerPriorityCellsWithinItsRadius) {
    const Box box{{0, 0, 0}, {32, 16, 32}};
    const curves::Limits limits;
    const auto seedValue = curves::SeedValue::PlaneDistance;
    const std::vector<curves::FeatureCurve> road = {flatCurve(7.2, 12.0, -4.0, 36.0)};
    const auto ground = flatHeightmap(box, 5.3);
    const auto block = boxMesh({18.4, 2.6, 10.4}, {25.6, 9.4, 17.6}); // the road crosses it
    const Constraints curveOnly = curves::voxelize(road, box, seedValue, limits);
    const Constraints meshOnly = curves::voxelize({}, box, seedValue, limits, {block});
    const Constraints groundOnly = curves::voxelize({}, box, seedValue, limits, {ground});
    const std::vector<glm::ivec3> curveCells = hitCells(curveOnly), meshCells = hitCells(meshOnly),
                                  groundCells = hitCells(groundOnly);
    ASSERT_FALSE(curveCells.empty());
    ASSERT_FALSE(meshCells.empty());
    ASSERT_EQ(groundCells.size(), size_t(32 * 32)); // the plane y = 5.3 meets the y = 5 layer only
    for (int radius : {0, 1, 2, 3, 6}) {
        curves::InputOptions options;
        options.deadZone = radius;
        // Listed heightmap first: the priority is by kind, not by order.
        const Constraints all = curves::voxelize(road, box, seedValue, limits, {ground, block}, options);
        std::vector<glm::ivec3> keptMesh, keptGround;
        for (glm::ivec3 c : meshCells)
            if (!nearAny(c, curveCells, radius)) keptMesh.push_back(c);
        std::vector<glm::ivec3> higher = curveCells;
        higher.insert(higher.end(), keptMesh.begin(), keptMesh.end());
        for (glm::ivec3 c : groundCells)
            if (!nearAny(c, higher, radius)) keptGround.push_back(c);
        std::set<std::array<int, 3>> expected;
        for (const std::vector<glm::ivec3>* cells :
             std::initializer_list<const std::vector<glm::ivec3>*>{&curveCells, &keptMesh, &keptGround})
            for (glm::ivec3 c : *cells) expected.insert({c.x, c.y, c.z});
        std::set<std::array<int, 3>> got;
        for (glm::ivec3 c : hitCells(all)) got.insert({c.x, c.y, c.z});
        EXPECT_EQ(got, expected) << "dead zone " << radius;
        expectSameValues(all, curveOnly, curveCells);
        expectSameValues(all, meshOnly, keptMesh);
        expectSameValues(all, groundOnly, keptGround);
        // The curve lies two layers above the ground: radius 0 and 1 drop none of the ground's
        // cells near it, radius 2 and more a band around it.
        const size_t droppedGround = groundCells.size() - keptGround.size();
        const size_t nearBlock = size_t(std::count_if(groundCells.begin(), groundCells.end(), [&](glm::ivec3 c) {
            return nearAny(c, keptMesh, radius);
        }));
        if (radius < 2) EXPECT_EQ(droppedGround, nearBlock) << "dead zone " << radius;
        else EXPECT_GT(droppedGround, nearBlock) << "dead zone " << radius;
        // The road runs through the block: some of its cells always go, all of them at 6.
        EXPECT_LT(keptMesh.size(), meshCells.size());
        if (radius < 6) EXPECT_GT(keptMesh.size(), 0u) << "dead zone " << radius;
        else EXPECT_TRUE(keptMesh.empty());
    }
}

TEST(CurvesInputs, InputCellsCountAgainstTheConstrainedCellLimit) {
    const Box box{{0, 0, 0}, {64, 8, 64}};
    curves::Limits limits;
    limits.maxConstrainedCells = 4000;
    EXPECT_THROW(curves::voxelize({}, box, curves::SeedValue::PlaneDistance, limits, {flatHeightmap(box, 3.3)}),
                 curves::LimitError);
}

constexpr int kSize = 40, kHeight = 24;

// A flat imported ground at y = 12.25 (a constant 16-bit PNG) and a seed curve at y = 4.25 along
// x through z = 20: a trench. With the dead zone past the eight voxels between them the ground's
// cells above the curve are dropped and the trench is open; without, the ground closes over it.
std::string trenchProgram(const std::string& extraKeys) {
    return fmt::format(R"(world {{ size = [{0}, {1}, {0}]; origin = [-7, 3, 5]; }}
heightmap flat {{ file = "flat.png"; size = [{0}, {0}]; origin = [-7, 5]; height = [3, 19.5]; values = [0, 58]; }}
curves trench {{
  box = [[0, 0, 0], [{2}, {3}, {2}]];
  inputs = [flat];
  {4}
  curve floor {{
    points = [[-4, 4.25, 20], [10, 4.25, 20], [30, 4.25, 20], [44, 4.25, 20]];
    constraint {{ t = 0; }}
    constraint {{ t = 1; }}
  }}
}}
pipeline {{ start; set trench; }}
)",
                       kSize, kHeight, kSize - 1, kHeight - 1, extraKeys);
}

// Each column's density sum less the half voxel of the ramp: the surface's height there.
double surfaceAt(const DenseGrid& grid, int x, int z) {
    double sum = 0.0;
    for (int y = 0; y < kHeight; ++y) sum += grid.at({x, y, z});
    return sum - 0.5;
}

DenseGrid runTrench(const fs::path& dir, const std::string& keys) {
    const CheckResult result = checkSource(SourceFile((dir / "trench.vox").string(), trenchProgram(keys)), Limits{});
    EXPECT_TRUE(result.program.has_value()) << result.rendered();
    if (!result.program) return DenseGrid({1, 1, 1});
    return interpret(*result.program);
}

TEST(CurvesInputs, TheSurfaceFollowsTheHeightmapFarFromTheCurveAndTheCurveNearIt) {
    const fs::path dir = scratch();
    // Every pixel 32: 3 + 32/58 * 16.5 = 12.1034... world y, 9.1034... grid-local.
    test::writeBytes(dir / "flat.png", test::greyPng(kSize, kSize, std::vector<uint16_t>(kSize * kSize, 32), 8));
    const double ground = 3.0 + 32.0 / 58.0 * 16.5 - 3.0;
    const DenseGrid open = runTrench(dir, "dead_zone = 8;");
    const DenseGrid closed = runTrench(dir, "dead_zone = 0;");
    double worstFar = 0.0, worstNear = 0.0;
    for (int x = 0; x < kSize; ++x)
        for (int z = 0; z < kSize; ++z) {
            if (std::abs(z - 20) >= 16) worstFar = std::max(worstFar, std::abs(surfaceAt(open, x, z) - ground));
            if (std::abs(z - 20) <= 1) {
                worstNear = std::max(worstNear, std::abs(surfaceAt(open, x, z) - 4.25));
                // Closed over: the same floor with the ground's slab above it.
                EXPECT_GT(surfaceAt(closed, x, z), 4.25 + 2.0) << x << ", " << z;
            }
        }
    EXPECT_LE(worstFar, 0.25);
    EXPECT_LE(worstNear, 0.5);
}

TEST(CurvesInputs, KeyErrorsAreLocated) {
    const fs::path dir = scratch();
    test::writeBytes(dir / "flat.png", test::greyPng(4, 4, std::vector<uint16_t>(16, 7), 8));
    const std::string text = R"(world { size = [16, 16, 16]; }
heightmap flat { file = "flat.png"; height = [0, 4]; }
field rock = 1;
curves a {
  box = [[0, 0, 0], [15, 15, 15]];
  inputs = [flta, rock, a];
  dead_zone = 65;
}
pipeline { start; set rock; }
)";
    const CheckResult result = checkSource(SourceFile((dir / "errors.vox").string(), text), Limits{});
    ASSERT_EQ(result.diagnostics.size(), 4u) << result.rendered();
    const auto expect = [&](size_t i, const char* code, uint32_t line, uint32_t column, const char* words) {
        EXPECT_EQ(result.diagnostics[i].code, code) << result.rendered();
        EXPECT_EQ(result.diagnostics[i].loc.line, line);
        EXPECT_EQ(result.diagnostics[i].loc.column, column);
        EXPECT_NE(result.diagnostics[i].message.find(words), std::string::npos) << result.diagnostics[i].message;
    };
    expect(0, "E0002", 6, 13, "did you mean 'flat'");
    expect(1, "E0010", 6, 19, "'rock' is a field");
    expect(2, "E0010", 6, 25, "'a' is a curves block");
    expect(3, "E0007", 7, 15, "dead_zone");
}

} // namespace curves_inputs_test
} // namespace voxc
