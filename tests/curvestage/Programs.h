#pragma once
// .vox texts the curves stage tests share.
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace voxc::test {

// One straight seed curve through `q` whose ribbons (8 voxels each side) have the unit normal
// `n`: the surface it pins is the plane n . (p - q) = 0. No noise (amplitude 0), one smoothing pass.
inline std::string planeProgram(glm::dvec3 n, glm::dvec3 q, glm::ivec3 size) {
    const glm::dvec3 t = glm::normalize(glm::dvec3(n.y, -n.x, 0.0)); // perpendicular to n
    const glm::dvec3 right = 8.0 * glm::cross(t, n), left = 8.0 * glm::cross(n, t);
    const auto vec = [](glm::dvec3 v) { return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", v.x, v.y, v.z); };
    std::string points;
    for (double s : {-20.0, -7.0, 7.0, 20.0}) points += (points.empty() ? "" : ", ") + vec(q + s * t);
    const std::string constraint =
        fmt::format("left = {}; right = {};", vec(left), vec(right));
    return fmt::format(R"(
world {{ size = [{}, {}, {}]; }}
curves plane {{
  box = [[0, 0, 0], [{}, {}, {}]];
  curve line {{
    points = [{}];
    constraint {{ t = 0; {} }}
    constraint {{ t = 1; {} }}
  }}
}}
pipeline {{ start; set plane; }}
)",
                       size.x, size.y, size.z, size.x - 1, size.y - 1, size.z - 1, points, constraint, constraint);
}

// Rock below y = 9 (material rock) in an odd-sized grid, and a ridge of moss-covered curves in
// a box that does not reach the grid's edges, combined by `mode`; without `materials`, neither
// the start nor the curves name one.
inline std::string ridgeProgram(const std::string& mode, const std::string& world, bool materials = true) {
    const std::string rock = materials ? "material = rock;" : "", moss = materials ? "material = moss;" : "";
    return fmt::format(R"(
world {{ size = [37, 21, 29]; {} }}
{}
start {{ box {{ min = [0, 0, 0]; max = [37, 9, 29]; {} }} }}
curves ridge {{
  box = [[3, 2, 4], [30, 17, 25]];
  noise_frequency = 0.2;
  curve crest {{
    points = [[6, 12, 6], [14, 14, 10], [22, 11, 18], [28, 13, 23]];
    constraint {{ t = 0; {} amplitude = 1.5; roughness = 0.7; }}
    constraint {{ t = 1; {} amplitude = 0.5; }}
  }}
  curve side {{
    seed = false;
    points = [[6, 6, 20], [12, 6, 20], [18, 6, 20], [24, 6, 20]];
    constraint {{ t = 0; left = [0, 0, 3]; right = [0, 0, -3]; }}
    constraint {{ t = 1; left = [0, 0, 3]; right = [0, 0, -3]; }}
  }}
}}
pipeline {{ start; {} ridge; }}
)",
                       world, materials ? "material rock { id = 1; }\nmaterial moss { id = 2; }" : "", rock, moss, moss,
                       mode);
}

} // namespace voxc::test
