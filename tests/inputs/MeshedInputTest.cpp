// A mesh block's solid, meshed again by voxc's mesher, lies where the original surface was: every
// vertex of the marching-cubes mesh of `clamp(0.5 - NAME(wp), 0, 1)` is within one voxel of the
// analytic sphere and box the input meshes approximate (docs/language.md, "Meshes").
#include "InputFiles.h"

#include "voxc/check/Check.h"
#include "voxc/grid/Grid.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/stages/Pipeline.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <functional>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <unistd.h>

namespace voxc {
namespace meshed_input_test {

namespace fs = std::filesystem;

// The mesh of the voxels the block `mesh rock { file = FILE; KEYS }` makes solid (distance < 0.5
// voxel inside the surface reads as density above 0.5), in world coordinates.
Mesh remeshedInput(const std::string& file, const std::string& keys, const std::string& bytes) {
    const fs::path dir = fs::temp_directory_path() / fmt::format("voxc_meshed_input_test_{}", ::getpid());
    fs::create_directories(dir);
    test::writeBytes(dir / file, bytes);
    const std::string text = fmt::format(R"(world {{ size = [40, 36, 38]; origin = [-3, 2, 1]; }}
mesh rock {{ file = "{}"; {} }}
field solid = clamp(0.5 - rock(wp), 0, 1);
pipeline {{ start; set solid; }}
)",
                                         file, keys);
    const CheckResult result = checkSource(SourceFile((dir / "m.vox").string(), text));
    fs::remove_all(dir);
    if (!result.program) throw std::runtime_error(result.rendered());
    const World& w = result.program->world;
    return meshMarchingCubes(ChunkedGrid::fromDense(interpret(*result.program),
                                                    ChunkLayout::make(w.origin, w.size, w.chunkSize)),
                             {});
}

// The largest distance of a vertex from the analytic surface, in voxels.
double farthestVertex(const Mesh& mesh, const std::function<double(glm::dvec3)>& distance) {
    double worst = 0.0;
    for (const glm::vec3& p : mesh.positions) worst = std::max(worst, std::abs(distance(glm::dvec3(p))));
    return worst;
}

TEST(MeshedInput, SphereIsWithinOneVoxel) {
    const glm::dvec3 centre(17.2, 19.7, 18.4);
    const Mesh mesh = remeshedInput("ball.glb", "translate = [17.2, 19.7, 18.4]; scale = 9.5;",
                                    test::glb(test::icosphere(1.0f, 3)));
    ASSERT_GT(mesh.positions.size(), 1000u);
    EXPECT_LE(farthestVertex(mesh, [&](glm::dvec3 p) { return glm::length(p - centre) - 9.5; }), 1.0);
}

TEST(MeshedInput, RotatedBoxIsWithinOneVoxel) {
    const glm::dvec3 centre(16.5, 18.0, 20.0);
    const double a = glm::radians(30.0);
    const Mesh mesh = remeshedInput("box.ply", "translate = [16.5, 18, 20]; rotate = [0, 30, 0]; band = 3;",
                                    test::ply(test::box({-6, -4, -5}, {6, 4, 5})));
    ASSERT_GT(mesh.positions.size(), 500u);
    EXPECT_LE(farthestVertex(mesh,
                             [&](glm::dvec3 p) {
                                 const glm::dvec3 q = p - centre;
                                 const glm::dvec3 local(std::cos(a) * q.x - std::sin(a) * q.z, q.y,
                                                        std::sin(a) * q.x + std::cos(a) * q.z);
                                 const glm::dvec3 e = glm::abs(local) - glm::dvec3(6, 4, 5);
                                 return glm::length(glm::max(e, 0.0)) + std::min(std::max({e.x, e.y, e.z}), 0.0);
                             }),
              1.0);
}

} // namespace meshed_input_test
} // namespace voxc
