// The curves stage on the CPU (docs/curves.md, "The stage"): the spec's planes test (A4.5)
// through the whole pipeline and the mesher, the stage acting on its box only by its mode, and
// the example's cliff meshing watertight with the materials of its curves.
#include "CheckedProgram.h"
#include "Programs.h"

#include "voxc/check/Check.h"
#include "voxc/codegen/KernelPackage.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/mesh/Mesh.h"
#include "voxc/program/Semantics.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Region.h"
#include "voxc/stages/Solve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace voxc {
namespace {

Program checked(const std::string& text) {
    Program program = test::checkedProgram("curves.vox", text, test::Allowed::None);
    stages::solveBlocks(program);
    return program;
}

Program checkedFile(const std::string& path, const stages::SolveOptions& options = {}) {
    CheckResult result = checkFile(path);
    if (!result.program) throw std::runtime_error(result.rendered());
    Program program = std::move(*result.program);
    stages::solveBlocks(program, options);
    return program;
}

Mesh meshOf(const Program& program, const DenseGrid& grid) {
    const World& w = program.world;
    return meshMarchingCubes(ChunkedGrid::fromDense(grid, ChunkLayout::make(w.origin, w.size, w.chunkSize)), {});
}

// A4.5: one straight seed curve, the surface grown from it is its plane: every marching-cubes
// vertex lies within 1e-3 voxel of it, away from the box faces (where clamp-to-edge smoothing
// bends a linear field).
TEST(curvestage_Planes, MeshVerticesLieOnThePlane) {
    const glm::ivec3 size{32, 24, 32};
    for (const glm::dvec3 n : {glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(1, 2, 0.5))}) {
        SCOPED_TRACE(fmt::format("normal ({}, {}, {})", n.x, n.y, n.z));
        const glm::dvec3 q(15.5, 11.3, 16.25);
        const Program program = checked(test::planeProgram(n, q, size));
        const Mesh mesh = meshOf(program, interpret(program));
        size_t inner = 0;
        double worst = 0.0;
        for (const glm::vec3& v : mesh.positions) {
            const glm::dvec3 p(v);
            if (glm::any(glm::lessThan(p, glm::dvec3(1.5))) || glm::any(glm::greaterThan(p, glm::dvec3(size) - 2.5)))
                continue;
            ++inner;
            worst = std::max(worst, std::fabs(glm::dot(n, p - q)));
        }
        EXPECT_GT(inner, 500u);
        EXPECT_LE(worst, 1e-3);
    }
}

// Outside its box a stage leaves every voxel as it was; inside, each mode is combineField of
// the solved table, whose values were checked once (the table is the solve's).
TEST(curvestage_Modes, CombineInsideTheBoxOnly) {
    const Program base = checked(test::ridgeProgram("set", ""));
    const SolveTable& table = *base.curves.at(0).table;
    ASSERT_FALSE(table.material.empty());
    Program startOnly = base;
    startOnly.pipeline.resize(1);
    const DenseGrid before = interpret(startOnly);
    for (const char* modeName : {"set", "union", "subtract", "intersect"}) {
        SCOPED_TRACE(modeName);
        const Program program = checked(test::ridgeProgram(modeName, ""));
        const FieldMode mode = program.pipeline.back().mode;
        const DenseGrid after = interpret(program);
        size_t changed = 0;
        for (int z = 0; z < 29; ++z)
            for (int y = 0; y < 21; ++y)
                for (int x = 0; x < 37; ++x) {
                    const glm::ivec3 p{x, y, z}, cell = p - table.min;
                    const VoxelState was{before.at(p), before.materialAt(p)};
                    VoxelState expected = was;
                    if (glm::all(glm::greaterThanEqual(cell, glm::ivec3(0))) && glm::all(glm::lessThan(cell, table.size))) {
                        const size_t i = size_t(cell.x) + size_t(table.size.x) * (size_t(cell.y) + size_t(table.size.y) * size_t(cell.z));
                        // The modes' meaning, written out: max, min with 1 - f, min; material where it wins.
                        const float f = table.density[i];
                        const float d = was.density;
                        const float result = mode == FieldMode::Set        ? f
                                             : mode == FieldMode::Union    ? std::max(d, f)
                                             : mode == FieldMode::Subtract ? std::min(d, 1.0f - f)
                                                                           : std::min(d, f);
                        expected.density = result;
                        const bool wins = mode == FieldMode::Set || result != d;
                        if (wins && result >= 0.5f) expected.material = table.material[i];
                    }
                    changed += after.at(p) != was.density || after.materialAt(p) != was.material;
                    ASSERT_EQ(after.at(p), expected.density) << x << "," << y << "," << z;
                    ASSERT_EQ(after.materialAt(p), expected.material) << x << "," << y << "," << z;
                }
        EXPECT_GT(changed, 100u);
    }
}

// The plan tiles the grid: the slabs outside the box and the pieces inside where the union
// provably changes nothing (the table is air there and no density is below 0) are not
// dispatched; the rest are, and they cover the box's cells exactly once.
TEST(curvestage_Plan, SkipsTheBoxPiecesThatChangeNothing) {
    Program program = checked(test::ridgeProgram("union", ""));
    program.world.chunkSize = 8;
    const SolveTable& table = *program.curves.at(0).table;
    const KernelPackage package = compileProgram(program, {});
    const StagePlan& plan = package.stages.back();
    EXPECT_EQ(plan.kind, "curves");
    uint64_t dispatched = 0, skippedInside = 0, covered = 0;
    for (const FieldBox& box : plan.gridBoxes) {
        const glm::ivec3 extent = box.max - box.min;
        const uint64_t cells = uint64_t(extent.x) * uint64_t(extent.y) * uint64_t(extent.z);
        covered += cells;
        const bool inside = glm::all(glm::greaterThanEqual(box.min, table.min)) &&
                            glm::all(glm::lessThanEqual(box.max, table.min + table.size));
        if (!box.unchanged) {
            EXPECT_TRUE(inside);
            dispatched += cells;
        } else if (inside) {
            skippedInside += cells;
        }
    }
    EXPECT_EQ(covered, uint64_t(37 * 21 * 29));
    EXPECT_EQ(dispatched + skippedInside, table.cellCount());
    EXPECT_GT(skippedInside, 0u);
    EXPECT_GT(dispatched, 0u);
}

// The example: a non-empty watertight mesh, and the solid voxels carry the three materials of
// its curves (sand, sandstone, grass) and nothing else.
TEST(curvestage_Example, CliffMeshesWatertightWithTheCurvesMaterials) {
    const Program program = checkedFile(std::string(VOXC_SOURCE_DIR) + "/examples/curves_cliff.vox");
    const DenseGrid grid = interpret(program);
    const Mesh mesh = meshOf(program, grid);
    EXPECT_GT(mesh.triangles.size(), 3000u);
    EXPECT_TRUE(analyzeTopology(mesh).watertight());
    std::array<size_t, 256> solid{};
    for (size_t i = 0; i < grid.data().size(); ++i)
        if (grid.data()[i] >= 0.5f) ++solid[grid.materials()[i]];
    EXPECT_EQ(solid[0], 0u);
    for (const char* name : {"sand", "sandstone", "grass"}) {
        const auto material = std::find_if(program.materials.begin(), program.materials.end(),
                                           [&](const Material& m) { return m.name == name; });
        ASSERT_NE(material, program.materials.end());
        EXPECT_GT(solid[material->id], 1000u) << name;
    }
    // Tolerances (docs/curves.md): normals 1e-4, parameters 1e-4 * the largest amplitude (1.5 here).
    const std::vector<SolveSummary>& solves = program.curves.at(0).table->solves;
    ASSERT_EQ(solves.size(), 2u);
    EXPECT_EQ(solves[0].name, "normals");
    EXPECT_LE(solves[0].residuals.back(), 1e-4f);
    EXPECT_LE(solves[1].residuals.back(), 1.5e-4f);
    for (const SolveSummary& solve : solves) {
        EXPECT_GT(solve.cycles(), 0) << solve.name;
        // Spec A4.7: each V-cycle after the first two cuts the max residual at least 2x.
        for (size_t c = 3; c < solve.residuals.size(); ++c)
            EXPECT_LE(solve.residuals[c], 0.5f * solve.residuals[c - 1]) << solve.name << " cycle " << c;
    }
}

// The noise displacement runs only where it can change the density (Scene.cpp, DisplacementBand);
// a solve keeping the channels evaluates it at every cell. The densities and materials must be the
// same bits, the band must have left cells out (displacement != 0 where the density saturated),
// and the kept channels must give the density by its formula.
TEST(curvestage_Example, DisplacementBandGivesTheFullEvaluationsBits) {
    const std::string path = std::string(VOXC_SOURCE_DIR) + "/examples/curves_cliff.vox";
    const Program banded = checkedFile(path), everywhere = checkedFile(path, {.keepChannels = true});
    const SolveTable& a = banded.curves.at(0).solved();
    const SolveTable& b = everywhere.curves.at(0).solved();
    EXPECT_TRUE(a.channels.empty());
    ASSERT_EQ(a.density.size(), b.density.size());
    EXPECT_EQ(0, std::memcmp(a.density.data(), b.density.data(), a.density.size() * sizeof(float)));
    EXPECT_EQ(a.material, b.material);
    const auto channel = [&](const char* name) -> const std::vector<float>& {
        for (const auto& [key, values] : b.channels)
            if (key == name) return values;
        throw std::runtime_error(std::string("no channel ") + name);
    };
    const std::vector<float>& smoothed = channel("smoothed");
    const std::vector<float>& displacement = channel("displacement");
    size_t saturatedAndDisplaced = 0;
    for (size_t i = 0; i < b.density.size(); ++i) {
        const float d = smoothed[i] - displacement[i];
        const float density = d < INFINITY ? std::clamp(0.5f - d / 2.0f, 0.0f, 1.0f) : 0.0f;
        ASSERT_EQ(std::bit_cast<uint32_t>(density), std::bit_cast<uint32_t>(b.density[i])) << i;
        if ((density == 0.0f || density == 1.0f) && displacement[i] != 0.0f) ++saturatedAndDisplaced;
    }
    EXPECT_GT(saturatedAndDisplaced, b.density.size() / 4);
}

// Checking a file never solves its curves (docs/curves.md, "The stage"): the check keeps the
// voxelised scene and answers every question the check asks (work, materials, the box) from it;
// only stages::solveBlocks makes a table. The box is the largest a file may declare (256x128x256,
// Limits::maxSolveCells), whose solve takes tens of seconds.
TEST(curvestage_Check, LeavesTheSolveToTheRun) {
    const Program program = test::checkedProgram("big.vox", R"(
world { size = [256, 128, 256]; }
material rock { id = 1; }
curves big {
  box = [[0, 0, 0], [255, 127, 255]];
  curve edge {
    points = [[40, 60, 40], [100, 64, 90], [160, 58, 150], [220, 62, 210]];
    constraint { t = 0; material = rock; }
    constraint { t = 1; }
  }
}
pipeline { start; union big; }
)",
                                                 test::Allowed::None);
    const CurvesBlock& block = program.curves.at(0);
    EXPECT_EQ(block.table, nullptr);
    ASSERT_NE(block.scene, nullptr);
    EXPECT_EQ(block.cellCount(), uint64_t(256) * 128 * 256);
    EXPECT_TRUE(block.writesMaterials);
    EXPECT_EQ(block.materials, std::vector<uint8_t>{1});
    EXPECT_TRUE(program.usesMaterials());
    EXPECT_THROW(block.solved(), InternalError);
}

// A run solves each block once: a second solveBlocks keeps the table, and compileProgram and
// interpret, given a program nobody solved, solve it themselves (on the host) to the same bits.
TEST(curvestage_Solve, OnceAndTheSameWhoeverSolves) {
    Program unsolved = test::checkedProgram("curves.vox", test::ridgeProgram("union", ""), test::Allowed::None);
    ASSERT_EQ(unsolved.curves.at(0).table, nullptr);
    Program program = unsolved;
    stages::solveBlocks(program);
    const std::shared_ptr<const SolveTable> table = program.curves.at(0).table;
    ASSERT_NE(table, nullptr);
    stages::solveBlocks(program);
    EXPECT_EQ(program.curves.at(0).table, table);
    const DenseGrid a = interpret(program), b = interpret(unsolved);
    EXPECT_EQ(0, std::memcmp(a.data().data(), b.data().data(), a.data().size() * sizeof(float)));
    EXPECT_EQ(a.materials(), b.materials());
    EXPECT_EQ(unsolved.curves.at(0).table, nullptr); // interpret solved a copy
    EXPECT_EQ(compileProgram(program).solveTables.back(), table); // the package uploads the run's table
}

// A region's program may be made before or after the solve: either way its table is the whole
// box's solve cropped to the region, and the region computes the whole grid's voxels there.
TEST(curvestage_Solve, RegionBeforeOrAfterTheSolve) {
    const Program unsolved = test::checkedProgram("curves.vox", test::ridgeProgram("union", ""), test::Allowed::None);
    Program whole = unsolved;
    stages::solveBlocks(whole);
    const stages::GridBox box{{5, 3, 9}, {30, 21, 20}};
    const Program after = stages::regionProgram(whole, box);
    Program before = stages::regionProgram(unsolved, box);
    stages::solveBlocks(before);
    const SolveTable &x = after.curves.at(0).solved(), &y = before.curves.at(0).solved();
    EXPECT_EQ(x.min, y.min);
    EXPECT_EQ(x.size, y.size);
    EXPECT_EQ(after.curves.at(0).min, x.min);
    EXPECT_EQ(after.curves.at(0).size, x.size);
    EXPECT_EQ(0, std::memcmp(x.density.data(), y.density.data(), x.density.size() * sizeof(float)));
    EXPECT_EQ(x.material, y.material);
    const DenseGrid region = interpret(before), expected = stages::cropGrid(interpret(whole), box);
    EXPECT_EQ(0, std::memcmp(region.data().data(), expected.data().data(), region.data().size() * sizeof(float)));
    EXPECT_EQ(region.materials(), expected.materials());
}

} // namespace
} // namespace voxc
