#pragma once
// Offscreen pictures of a mesh with a Vulkan graphics pipeline on the generation device
// (VulkanContext; lavapipe works): no window, no swapchain. Faces take their material's colour,
// lit by ambient plus one directional light (shaders render_mesh_vert/frag.glsl), each scaled per
// vertex by the light that reaches it when the caller measured it (voxc/render/Lighting.h); lines
// (wireframe, chunk borders) are drawn unlit over them. The same scene, camera and size give the
// same pixels on the same device and driver.
#include "voxc/grid/Grid.h"
#include "voxc/mesh/Mesh.h"
#include "voxc/program/Program.h"
#include "voxc/render/Camera.h"
#include "voxc/render/Lighting.h"
#include "voxc/vulkan/Context.h"

#include <memory>
#include <span>
#include <vector>

namespace voxc::rendering {

// Line segments in world coordinates: points 2i and 2i+1 join, each with its own colour.
struct LineSet {
    std::vector<glm::vec3> points;
    std::vector<glm::vec3> colours;
    void add(glm::vec3 from, glm::vec3 to, glm::vec3 colour);
};

// The box of the mesh's vertices (min > max when it has none), which presets frame.
Bounds meshBounds(const Mesh& mesh);

// Every edge of the mesh once, in `colour`.
LineSet wireframeLines(const Mesh& mesh, glm::vec3 colour);
// The edges of every chunk's box, clipped to the grid's voxel box (voxel centres, as the mesh).
LineSet chunkBorderLines(const ChunkLayout& layout, glm::vec3 colour);

// An RGB picture, 3 bytes per pixel, rows top to bottom.
struct Picture {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgb;
};

inline constexpr glm::vec3 kBackground{0.55f, 0.62f, 0.70f}; // linear RGB

// The sRGB transfer curve (linear [0, 1] -> encoded [0, 1]) the fragment shader applies; the
// picture is stored encoded, and the background is cleared to its encoded value.
float encodeSrgb(float linear);

// The unit direction towards the directional light for a camera: from above and over the
// viewer's left shoulder, so the faces the camera sees are lit, and faces turned right or down are
// shaded apart from those turned left or up.
glm::vec3 towardsLight(const Camera& camera);

} // namespace voxc::rendering

namespace voxc {

// In namespace voxc beside VulkanExecutor: VulkanContext befriends it for its device handles.
class MeshRenderer {
public:
    // Creates the colour and depth targets and the pipelines. UserError when the device's queue
    // cannot draw (a compute-only queue family).
    MeshRenderer(VulkanContext& context, rendering::ImageSize size);
    ~MeshRenderer();
    MeshRenderer(const MeshRenderer&) = delete;
    MeshRenderer& operator=(const MeshRenderer&) = delete;

    // Uploads the faces (vertex colours from `materials`: id 0 and unknown ids neutral grey) and
    // the lines drawn over them; replaces the previous scene. `light`, when given, scales each
    // vertex's ambient and directional terms (measured for the camera draw() is given).
    void setScene(const Mesh& mesh, std::span<const Material> materials, const rendering::LineSet& lines = {},
                  const rendering::VertexLight* light = nullptr);
    // Draws the scene, waits, and reads the picture back.
    rendering::Picture draw(const rendering::Camera& camera);

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

} // namespace voxc
