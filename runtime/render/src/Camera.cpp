#include "voxc/render/Camera.h"

#include "voxc/core/Errors.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

namespace voxc::rendering {

namespace {

constexpr const char* kCameraForms = "iso, top, side or X,Y,Z:TX,TY,TZ (eye and target, e.g. 200,150,200:48,20,48)";

std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    for (size_t start = 0;;) {
        const size_t end = text.find(separator, start);
        parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
        if (end == std::string_view::npos) return parts;
        start = end + 1;
    }
}

bool parseFloat(std::string_view text, float& value) {
    const char* end = text.data() + text.size();
    const auto [last, error] = std::from_chars(text.data(), end, value);
    return error == std::errc() && last == end && std::isfinite(value);
}

bool parseVec3(std::string_view text, glm::vec3& value) {
    const std::vector<std::string_view> parts = split(text, ',');
    if (parts.size() != 3) return false;
    for (int axis = 0; axis < 3; ++axis)
        if (!parseFloat(parts[axis], value[axis])) return false;
    return true;
}

} // namespace

void enclose(Camera& camera, const Bounds& bounds) {
    const glm::vec3 centre = 0.5f * (bounds.min + bounds.max);
    const float radius = std::max(0.5f * glm::length(bounds.max - bounds.min), 1.0f);
    const float distance = glm::length(centre - camera.eye);
    camera.farPlane = distance + radius * 1.01f;
    camera.nearPlane = std::max(distance - radius * 1.01f, camera.farPlane * 1e-4f);
}

Camera parseCamera(std::string_view spec, const Bounds& bounds, float aspect) {
    Camera camera;
    if (spec.find(':') != std::string_view::npos) {
        const std::vector<std::string_view> halves = split(spec, ':');
        if (halves.size() != 2 || !parseVec3(halves[0], camera.eye) || !parseVec3(halves[1], camera.target))
            throw UserError(fmt::format("--camera {}: expected {}", spec, kCameraForms));
        if (glm::length(camera.target - camera.eye) < 1e-6f)
            throw UserError(fmt::format("--camera {}: the eye and the target are the same point", spec));
        // Looking straight up or down, y cannot be the image's up.
        const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
        if (std::abs(forward.y) > 0.999f) camera.up = {0.0f, 0.0f, -1.0f};
        enclose(camera, bounds);
        return camera;
    }
    glm::vec3 towardsEye;
    if (spec == "iso") {
        towardsEye = glm::normalize(glm::vec3(1.0f, 0.9f, 1.3f));
    } else if (spec == "top") {
        towardsEye = {0.0f, 1.0f, 0.0f};
        camera.up = {0.0f, 0.0f, -1.0f};
    } else if (spec == "side") {
        towardsEye = {0.0f, 0.0f, 1.0f};
    } else {
        throw UserError(fmt::format("--camera {}: expected {}", spec, kCameraForms));
    }
    // The nearest eye on this side of the box from which all eight corners are in the picture:
    // a corner at offset o from the target needs a distance of o.t + |o.right| / tan(half fov x)
    // along t (and the same upwards). Perspective draws the box off-centre around its centre, so
    // the target then moves to the middle of the corners' extent in the picture and the distance
    // is fitted again: the box fills the frame instead of leaving a margin on one side.
    const glm::vec3 right = glm::normalize(glm::cross(camera.up, towardsEye));
    const glm::vec3 up = glm::cross(towardsEye, right);
    const float tanHalfY = std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
    const float tanHalfX = tanHalfY * aspect;
    const auto corner = [&](int c) {
        return glm::vec3{c & 1 ? bounds.max.x : bounds.min.x, c & 2 ? bounds.max.y : bounds.min.y,
                         c & 4 ? bounds.max.z : bounds.min.z};
    };
    glm::vec3 target = 0.5f * (bounds.min + bounds.max);
    float distance = 1.0f;
    for (int fit = 0; fit < 3; ++fit) {
        distance = 1.0f;
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 o = corner(c) - target;
            const float along = glm::dot(o, towardsEye);
            distance = std::max({distance, along + std::abs(glm::dot(o, right)) / tanHalfX,
                                 along + std::abs(glm::dot(o, up)) / tanHalfY});
        }
        if (fit == 2) break;
        glm::vec2 lo(INFINITY), hi(-INFINITY); // the corners in the picture, in units of its half size
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 o = corner(c) - target;
            const float depth = distance - glm::dot(o, towardsEye);
            const glm::vec2 at{glm::dot(o, right) / (depth * tanHalfX), glm::dot(o, up) / (depth * tanHalfY)};
            lo = glm::min(lo, at);
            hi = glm::max(hi, at);
        }
        const glm::vec2 middle = 0.5f * (lo + hi);
        target += distance * (middle.x * tanHalfX * right + middle.y * tanHalfY * up);
    }
    distance *= 1.08f; // a margin
    camera.target = target;
    camera.eye = target + towardsEye * distance;
    enclose(camera, bounds);
    return camera;
}

ImageSize parseImageSize(std::string_view spec) {
    const std::vector<std::string_view> parts = split(spec, 'x');
    ImageSize size;
    const auto side = [](std::string_view text, uint32_t& value) {
        const char* end = text.data() + text.size();
        const auto [last, error] = std::from_chars(text.data(), end, value);
        return !text.empty() && error == std::errc() && last == end && value >= 1 && value <= kMaxImageSide;
    };
    if (parts.size() != 2 || !side(parts[0], size.width) || !side(parts[1], size.height))
        throw UserError(fmt::format("--size {}: expected WIDTHxHEIGHT in pixels, each 1 to {}, e.g. 1280x720", spec,
                                    kMaxImageSide));
    return size;
}

glm::mat4 viewProjection(const Camera& camera, float aspect) {
    glm::mat4 projection =
        glm::perspectiveRH_ZO(glm::radians(camera.fovYDegrees), aspect, camera.nearPlane, camera.farPlane);
    projection[1][1] *= -1.0f; // Vulkan's framebuffer y points down
    return projection * glm::lookAtRH(camera.eye, camera.target, camera.up);
}

} // namespace voxc::rendering
