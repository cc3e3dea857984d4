#pragma once
// Where `voxc render` looks from: a preset around the object's bounding box, or an explicit eye
// and target, as the CLI spells them. World coordinates are voxels, y up.
#include <glm/glm.hpp>

#include <cstdint>
#include <string_view>

namespace voxc::rendering {

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};

struct Camera {
    glm::vec3 eye{0.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 35.0f;
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;
};

struct ImageSize {
    uint32_t width = 0;
    uint32_t height = 0;
};

inline constexpr uint32_t kMaxImageSide = 8192;

// "iso" (from above one corner), "top" (straight down, +x right, -z up the image), "side" (from +z
// along -z, y up), or "X,Y,Z:TX,TY,TZ" (eye and target). Presets frame `bounds` whole at `aspect`
// (width / height); near and far planes always enclose `bounds`. UserError naming the spec and
// the accepted forms otherwise (unknown preset, not six finite numbers, eye equal to target).
Camera parseCamera(std::string_view spec, const Bounds& bounds, float aspect);

// Near and far planes around the sphere that holds `bounds`, seen from `camera.eye` (the presets
// and explicit cameras of parseCamera get them so; `voxc view` again after each edit or move).
void enclose(Camera& camera, const Bounds& bounds);

// "WIDTHxHEIGHT", e.g. "1280x720", each side 1..kMaxImageSide; UserError otherwise.
ImageSize parseImageSize(std::string_view spec);

// Projection (Vulkan clip space: depth 0..1, y down) times view.
glm::mat4 viewProjection(const Camera& camera, float aspect);

} // namespace voxc::rendering
