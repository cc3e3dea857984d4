#include "voxc/render/Lighting.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <thread>

namespace voxc::rendering {

namespace {

constexpr int kRayCount = 64; // over the whole sphere; about half fall in a vertex's hemisphere

// Directions spread evenly over the sphere (a Fibonacci lattice): fixed, so every run and
// every machine casts the same rays.
std::array<glm::vec3, kRayCount> sphereDirections() {
    std::array<glm::vec3, kRayCount> directions;
    const float golden = 2.39996323f; // pi * (3 - sqrt 5)
    for (int i = 0; i < kRayCount; ++i) {
        const float y = 1.0f - (2.0f * float(i) + 1.0f) / float(kRayCount);
        const float r = std::sqrt(std::max(0.0f, 1.0f - y * y));
        directions[i] = {r * std::cos(golden * float(i)), y, r * std::sin(golden * float(i))};
    }
    return directions;
}

struct SolidTest {
    const DenseGrid& grid;
    glm::ivec3 origin;
    float iso;

    bool operator()(glm::vec3 world) const {
        const glm::ivec3 v = glm::ivec3(glm::floor(world + 0.5f)) - origin;
        if (!grid.inside(v)) return false;
        const float density = grid.at(v);
        return std::isfinite(density) && density > iso;
    }
};

// How far along `direction` the ray from `from` stays inside the grid's box grown by one voxel
// (beyond it every voxel is air); 0 when it never enters.
float exitDistance(glm::vec3 from, glm::vec3 direction, glm::vec3 lo, glm::vec3 hi) {
    float exit = INFINITY;
    for (int axis = 0; axis < 3; ++axis) {
        if (direction[axis] > 0.0f) exit = std::min(exit, (hi[axis] - from[axis]) / direction[axis]);
        else if (direction[axis] < 0.0f) exit = std::min(exit, (lo[axis] - from[axis]) / direction[axis]);
    }
    return std::max(exit, 0.0f);
}

} // namespace

VertexLight lightVertices(const Mesh& mesh, const DenseGrid& grid, glm::ivec3 gridOrigin, const LightingOptions& options) {
    const size_t count = mesh.positions.size();
    VertexLight light{std::vector<float>(count, 1.0f), std::vector<float>(count, 1.0f)};
    if (!options.ambientOcclusion && !options.shadows) return light;
    const std::array<glm::vec3, kRayCount> directions = sphereDirections();
    const SolidTest solid{grid, gridOrigin, options.iso};
    const glm::vec3 lo = glm::vec3(gridOrigin) - 1.0f, hi = glm::vec3(gridOrigin + grid.size());

    auto lightRange = [&](size_t first, size_t last) {
        for (size_t v = first; v < last; ++v) {
            const glm::vec3 p = mesh.positions[v], n = mesh.normals[v];
            // Rays start half a voxel out, in the air beside the surface, not in the rock under it.
            const glm::vec3 start = p + 0.5f * n;
            if (options.ambientOcclusion) {
                float open = 0.0f, total = 0.0f;
                for (const glm::vec3& d : directions) {
                    const float weight = glm::dot(d, n);
                    if (weight <= 0.0f) continue;
                    total += weight;
                    bool blocked = false;
                    for (float t = 1.0f; t <= kOcclusionReach && !blocked; t += 1.0f) blocked = solid(start + t * d);
                    if (!blocked) open += weight;
                }
                light.ambient[v] = total > 0.0f ? open / total : 1.0f;
            }
            if (options.shadows) {
                const glm::vec3 d = options.towardsLight;
                const float reach = exitDistance(start, d, lo, hi);
                bool blocked = false;
                for (float t = 1.0f; t <= reach && !blocked; t += 1.0f) blocked = solid(start + t * d);
                light.sun[v] = blocked ? 0.0f : 1.0f;
            }
        }
    };
    const size_t threads = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 16);
    const size_t per = (count + threads - 1) / threads;
    std::vector<std::jthread> workers;
    for (size_t first = per; first < count; first += per) workers.emplace_back(lightRange, first, std::min(count, first + per));
    lightRange(0, std::min(count, per));
    return light;
}

} // namespace voxc::rendering
