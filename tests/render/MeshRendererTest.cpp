// Pictures of examples/scene.vox on lavapipe with the validation layer (synchronisation checks
// included) on: the object is in the picture, in its materials' colours, and the same every time.
#include "voxc/check/Check.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/render/MeshRenderer.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace voxc {
namespace {

VulkanContext& validatedLavapipe() {
    static VulkanContext context(ContextOptions{.device = "lavapipe", .validation = true});
    return context;
}

struct Scene {
    Program program;
    Mesh mesh;
    ChunkLayout layout;
};

const Scene& scene() {
    static const Scene result = [] {
        CheckResult checked = checkFile(fmt::format("{}/examples/scene.vox", VOXC_SOURCE_DIR));
        EXPECT_TRUE(checked.program.has_value());
        Program program = std::move(*checked.program);
        VulkanExecutor executor(validatedLavapipe(), compileProgram(program, {}));
        const RunResult run = executor.run();
        Mesh mesh = meshMarchingCubes(run.grid, {});
        return Scene{std::move(program), std::move(mesh), run.grid.layout()};
    }();
    return result;
}

rendering::Bounds meshBounds(const Mesh& mesh) {
    rendering::Bounds bounds{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    for (const glm::vec3& p : mesh.positions) {
        bounds.min = glm::min(bounds.min, p);
        bounds.max = glm::max(bounds.max, p);
    }
    return bounds;
}

rendering::Picture draw(const std::string& camera, rendering::ImageSize size, const rendering::LineSet& lines = {}) {
    MeshRenderer renderer(validatedLavapipe(), size);
    renderer.setScene(scene().mesh, scene().program.materials, lines);
    return renderer.draw(rendering::parseCamera(camera, meshBounds(scene().mesh), float(size.width) / float(size.height)));
}

float decodeSrgb(uint8_t byte) {
    const float v = float(byte) / 255.0f;
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

const std::array<uint8_t, 3> kBackgroundPixel = [] {
    std::array<uint8_t, 3> pixel;
    for (int c = 0; c < 3; ++c) {
        pixel[c] = uint8_t(std::lround(rendering::encodeSrgb(rendering::kBackground[c]) * 255.0f));
    }
    return pixel;
}();

bool isBackground(const rendering::Picture& picture, size_t pixel) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(int(picture.rgb[pixel * 3 + c]) - int(kBackgroundPixel[c])) > 1) return false;
    return true;
}

double objectFraction(const rendering::Picture& picture) {
    const size_t pixels = size_t(picture.width) * picture.height;
    size_t object = 0;
    for (size_t p = 0; p < pixels; ++p) object += !isBackground(picture, p);
    return double(object) / double(pixels);
}

// Pixels whose linear colour is the material's scaled by one light factor (within 3%).
double materialFraction(const rendering::Picture& picture, glm::vec3 colour) {
    const size_t pixels = size_t(picture.width) * picture.height;
    size_t matches = 0;
    for (size_t p = 0; p < pixels; ++p) {
        const glm::vec3 linear{decodeSrgb(picture.rgb[p * 3]), decodeSrgb(picture.rgb[p * 3 + 1]),
                               decodeSrgb(picture.rgb[p * 3 + 2])};
        const float scale = glm::dot(linear, colour) / glm::dot(colour, colour);
        if (scale > 0.2f && glm::length(linear - scale * colour) < 0.03f * glm::length(linear)) ++matches;
    }
    return double(matches) / double(pixels);
}

const glm::vec3& materialColour(const std::string& name) {
    for (const Material& material : scene().program.materials)
        if (material.name == name) return material.color;
    ADD_FAILURE() << "scene.vox has no material " << name;
    static const glm::vec3 none{0.0f};
    return none;
}

void expectNoValidationMessages() {
    for (const ValidationMessage& message : validatedLavapipe().validationMessages()) ADD_FAILURE() << message.text;
}

TEST(MeshRenderer, PictureOfTheRequestedSizeShowsTheObjectInItsMaterials) {
    const rendering::Picture picture = draw("iso", {320, 180});
    ASSERT_EQ(picture.width, 320u);
    ASSERT_EQ(picture.height, 180u);
    ASSERT_EQ(picture.rgb.size(), size_t(320) * 180 * 3);
    const double object = objectFraction(picture);
    EXPECT_GT(object, 0.12) << "the framed object covers too little of the picture";
    EXPECT_LT(object, 0.9) << "the framed object leaves no background";
    EXPECT_GT(materialFraction(picture, materialColour("grass")), 0.05) << "grass is the ground's top";
    EXPECT_GT(materialFraction(picture, materialColour("sandstone")), 0.005) << "the arch is sandstone";
    expectNoValidationMessages();
}

TEST(MeshRenderer, SameSceneSameBits) {
    const rendering::Picture first = draw("iso", {256, 256});
    const rendering::Picture second = draw("iso", {256, 256});
    EXPECT_TRUE(first.rgb == second.rgb);
    expectNoValidationMessages();
}

TEST(MeshRenderer, TopAndSideCamerasDiffer) {
    const rendering::Picture top = draw("top", {200, 200});
    const rendering::Picture side = draw("side", {200, 200});
    size_t differing = 0;
    for (size_t p = 0; p < size_t(200) * 200; ++p)
        differing += top.rgb[p * 3] != side.rgb[p * 3] || top.rgb[p * 3 + 1] != side.rgb[p * 3 + 1] ||
                     top.rgb[p * 3 + 2] != side.rgb[p * 3 + 2];
    EXPECT_GT(differing, size_t(200) * 200 / 4);
    // From the top the ground is grass; from the side the cut face is bedrock and dirt.
    EXPECT_GT(materialFraction(top, materialColour("grass")), 3 * materialFraction(side, materialColour("grass")));
    expectNoValidationMessages();
}

TEST(MeshRenderer, LinesAreDrawnOverTheFaces) {
    const rendering::Picture plain = draw("iso", {200, 150});
    const rendering::Picture borders = draw("iso", {200, 150}, rendering::chunkBorderLines(scene().layout, {1, 0, 0}));
    EXPECT_GT(materialFraction(borders, {1, 0, 0}), 0.005);
    EXPECT_EQ(materialFraction(plain, {1, 0, 0}), 0.0);
    const rendering::LineSet wireframe = rendering::wireframeLines(scene().mesh, {0, 0, 0});
    EXPECT_EQ(wireframe.points.size() % 2, 0u);
    EXPECT_GT(wireframe.points.size() / 2, scene().mesh.triangles.size() / 3); // a closed mesh has 3/2 edges per triangle
    expectNoValidationMessages();
}

TEST(MeshRenderer, OneRendererDrawsFrameAfterFrameAndSceneAfterScene) {
    // Frame-to-frame hazards on the shared targets are what synchronisation validation would see.
    MeshRenderer renderer(validatedLavapipe(), {160, 90});
    const rendering::Camera camera = rendering::parseCamera("iso", meshBounds(scene().mesh), 160.0f / 90.0f);
    renderer.setScene(scene().mesh, scene().program.materials);
    const rendering::Picture first = renderer.draw(camera);
    renderer.setScene(scene().mesh, scene().program.materials, rendering::wireframeLines(scene().mesh, {0, 0, 0}));
    const rendering::Picture wired = renderer.draw(camera);
    renderer.setScene(scene().mesh, scene().program.materials);
    const rendering::Picture again = renderer.draw(camera);
    EXPECT_TRUE(first.rgb == again.rgb);
    EXPECT_FALSE(first.rgb == wired.rgb);
    expectNoValidationMessages();
}

TEST(MeshRenderer, AnEmptySceneIsAllBackground) {
    MeshRenderer renderer(validatedLavapipe(), {64, 32});
    renderer.setScene(Mesh{}, {});
    const rendering::Picture picture = renderer.draw(rendering::parseCamera("iso", {{0, 0, 0}, {8, 8, 8}}, 2.0f));
    EXPECT_EQ(objectFraction(picture), 0.0);
    expectNoValidationMessages();
}

TEST(ChunkBorderLines, TwelveEdgesPerChunkInsideTheGrid) {
    const ChunkLayout layout = ChunkLayout::make({-4, 0, 0}, {40, 16, 16}, 16); // straddles x chunks -16, 0, 16
    const rendering::LineSet lines = rendering::chunkBorderLines(layout, {1, 1, 1});
    EXPECT_EQ(lines.points.size(), size_t(layout.chunkTotal()) * 12 * 2);
    for (const glm::vec3& p : lines.points) {
        EXPECT_GE(p.x, -4.0f);
        EXPECT_LE(p.x, 35.0f);
        EXPECT_LE(p.y, 15.0f);
    }
}

} // namespace
} // namespace voxc
