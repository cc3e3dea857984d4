// `voxc render`'s light measured in the voxels (ambient occlusion, sun visibility) on grids whose
// answer is known, and cut-aways: their spellings, the voxels they remove, and a picture of a
// sealed cave that shows the cave's walls only once the rock in front of it is cut away.
#include "voxc/core/Errors.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/render/CutAway.h"
#include "voxc/render/Lighting.h"
#include "voxc/render/MeshRenderer.h"
#include "voxc/vulkan/Context.h"

#include <functional>
#include <gtest/gtest.h>

namespace voxc {
namespace {

constexpr int kSide = 40;

ChunkedGrid gridOf(const std::function<uint8_t(glm::ivec3)>& materialAt) {
    DenseGrid dense({kSide, kSide, kSide});
    for (int z = 0; z < kSide; ++z)
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x) {
                const uint8_t material = materialAt({x, y, z});
                dense.at({x, y, z}) = material ? 1.0f : 0.0f;
                dense.materialAt({x, y, z}) = material;
            }
    return ChunkedGrid::fromDense(dense, ChunkLayout::make({0, 0, 0}, dense.size(), 16));
}

// The vertex nearest to `at`.
size_t vertexNear(const Mesh& mesh, glm::vec3 at) {
    size_t best = 0;
    for (size_t v = 1; v < mesh.positions.size(); ++v)
        if (glm::distance(mesh.positions[v], at) < glm::distance(mesh.positions[best], at)) best = v;
    return best;
}

struct Lit {
    Mesh mesh;
    rendering::VertexLight light;
};

Lit lightUp(const ChunkedGrid& grid, rendering::LightingOptions options = {}) {
    Lit lit{meshMarchingCubes(grid, {}), {}};
    lit.light = rendering::lightVertices(lit.mesh, grid.toDense(), grid.layout().gridOrigin, options);
    return lit;
}

TEST(Lighting, AnOpenFloorIsFullyLit) {
    const Lit lit = lightUp(gridOf([](glm::ivec3 p) { return uint8_t(p.y < 8); }));
    const size_t middle = vertexNear(lit.mesh, {20, 7.5f, 20});
    EXPECT_FLOAT_EQ(lit.light.ambient[middle], 1.0f);
    EXPECT_FLOAT_EQ(lit.light.sun[middle], 1.0f);
}

TEST(Lighting, ACornerIsOccludedAndFarFromItIsNot) {
    // A floor below y = 8 and a wall from x = 24 on.
    const Lit lit = lightUp(gridOf([](glm::ivec3 p) { return uint8_t(p.y < 8 || p.x >= 24); }));
    const size_t corner = vertexNear(lit.mesh, {23, 7.5f, 20});
    const size_t open = vertexNear(lit.mesh, {4, 7.5f, 20});
    EXPECT_LT(lit.light.ambient[corner], 0.85f);
    EXPECT_GT(lit.light.ambient[corner], 0.3f);
    EXPECT_GT(lit.light.ambient[open], lit.light.ambient[corner]);
}

TEST(Lighting, AnOverhangCastsItsShadowOnTheFloorBelow) {
    // A slab from y = 20 to 23 over x < 16, above a floor below y = 8; light straight down.
    const Lit lit = lightUp(gridOf([](glm::ivec3 p) { return uint8_t(p.y < 8 || (p.y >= 20 && p.y < 24 && p.x < 16)); }));
    EXPECT_FLOAT_EQ(lit.light.sun[vertexNear(lit.mesh, {8, 7.5f, 20})], 0.0f);
    EXPECT_FLOAT_EQ(lit.light.sun[vertexNear(lit.mesh, {30, 7.5f, 20})], 1.0f);
    EXPECT_FLOAT_EQ(lit.light.sun[vertexNear(lit.mesh, {8, 23.5f, 20})], 1.0f) << "the slab's top is in the sun";
}

TEST(Lighting, ATermThatIsOffIsOneEverywhere) {
    const ChunkedGrid grid = gridOf([](glm::ivec3 p) { return uint8_t(p.y < 8 || (p.y >= 20 && p.y < 24 && p.x < 16)); });
    const Lit lit = lightUp(grid, {.ambientOcclusion = false, .shadows = false});
    ASSERT_FALSE(lit.mesh.positions.empty());
    for (size_t v = 0; v < lit.mesh.positions.size(); ++v) {
        EXPECT_EQ(lit.light.ambient[v], 1.0f);
        EXPECT_EQ(lit.light.sun[v], 1.0f);
    }
}

TEST(CutAway, Spellings) {
    const rendering::CutAway right = rendering::parseCutAway("x>10");
    EXPECT_EQ(right.min.x, 11);
    EXPECT_LT(right.min.y, -100000);
    EXPECT_GT(right.max.x, 100000);
    const rendering::CutAway below = rendering::parseCutAway("y<-3");
    EXPECT_EQ(below.max.y, -3);
    const rendering::CutAway box = rendering::parseCutAway("1,2,3:4,5,6");
    EXPECT_EQ(box.min, glm::ivec3(1, 2, 3));
    EXPECT_EQ(box.max, glm::ivec3(4, 5, 6));
    for (const char* bad : {"", "w>3", "x>", "x>1.5", "x=4", "1,2:3,4", "1,2,3:1,5,6", "1,2,3,4:5,6,7", "x>99999999"})
        EXPECT_THROW(rendering::parseCutAway(bad), UserError) << bad;
}

TEST(CutAway, RemovesExactlyItsVoxels) {
    ChunkedGrid grid = gridOf([](glm::ivec3) { return uint8_t(1); });
    EXPECT_EQ(rendering::applyCutAway(grid, rendering::parseCutAway("z>29")), size_t(kSide) * kSide * 10);
    EXPECT_EQ(grid.at({5, 5, 29}), 1.0f);
    EXPECT_EQ(grid.at({5, 5, 30}), 0.0f);
    EXPECT_EQ(grid.materialAt({5, 5, 30}), kMaterialNone);
    EXPECT_EQ(rendering::applyCutAway(grid, rendering::parseCutAway("-5,-5,-5:2,2,2")), 8u) << "clipped to the grid";
}

// A block of grey rock (material 1) around a sealed spherical cave whose walls are red rock
// (material 2), seen from +z: how many pixels show the red walls, and their summed red channel.
struct RedPixels {
    size_t count = 0;
    size_t redSum = 0;
    bool operator==(const RedPixels&) const = default;
};

RedPixels redPixels(bool cut, bool light) {
    ChunkedGrid grid = gridOf([](glm::ivec3 p) -> uint8_t {
        if (glm::any(glm::lessThan(p, glm::ivec3(4))) || glm::any(glm::greaterThanEqual(p, glm::ivec3(36)))) return 0;
        const float r = glm::distance(glm::vec3(p), glm::vec3(20.0f));
        return r < 8.0f ? 0 : r < 10.0f ? 2 : 1;
    });
    if (cut) rendering::applyCutAway(grid, rendering::parseCutAway("z>20"));
    const Mesh mesh = meshMarchingCubes(grid, {});
    static VulkanContext context(ContextOptions{.device = "lavapipe", .validation = true});
    const rendering::ImageSize size{96, 96};
    const rendering::Camera camera = rendering::parseCamera("side", rendering::meshBounds(mesh), 1.0f);
    const rendering::VertexLight vertexLight = rendering::lightVertices(
        mesh, grid.toDense(), {0, 0, 0}, {.towardsLight = rendering::towardsLight(camera)});
    MeshRenderer renderer(context, size);
    std::vector<Material> materials(2);
    materials[0].name = "grey", materials[0].id = 1, materials[0].color = {0.5f, 0.5f, 0.5f};
    materials[1].name = "red", materials[1].id = 2, materials[1].color = {0.8f, 0.05f, 0.05f};
    renderer.setScene(mesh, materials, {}, light ? &vertexLight : nullptr);
    const rendering::Picture picture = renderer.draw(camera);
    EXPECT_TRUE(context.validationMessages().empty());
    RedPixels red;
    for (size_t p = 0; p < picture.rgb.size(); p += 3)
        if (picture.rgb[p] > 2 * picture.rgb[p + 1] && picture.rgb[p] > 2 * picture.rgb[p + 2]) {
            ++red.count;
            red.redSum += picture.rgb[p];
        }
    return red;
}

TEST(CutAway, ShowsTheSealedCaveFromOutside) {
    EXPECT_EQ(redPixels(false, true).count, 0u);
    const RedPixels lit = redPixels(true, true);
    EXPECT_GT(lit.count, 200u);
    EXPECT_EQ(lit, redPixels(true, true)) << "the same picture every time";
    // The hollow's inside is occluded and shadowed by its own rim: darker than with plain light.
    const RedPixels plain = redPixels(true, false);
    EXPECT_LT(double(lit.redSum), 0.9 * double(plain.redSum));
}

} // namespace
} // namespace voxc
