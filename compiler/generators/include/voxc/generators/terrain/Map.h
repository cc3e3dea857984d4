#pragma once
// The 2D map model of Mathisen's multigrid terrain (spec Part B, B1.1-B1.3 and B3.1): a square
// XZ domain cut into levels Lmin..Lmax (level L has 2^L x 2^L cells), a maximum height, and
// feature splines (cubic Bezier pieces with meta points), each active on a range of levels.
// World units are voxels; y is up; heights are normalised by max_height inside the generator.
#include "voxc/generators/terrain/Limits.h"

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace voxc::terrain {

struct Domain {
    glm::dvec2 origin{0.0}; // world (x, z) of the domain's minimum corner
    double size = 2048.0;   // edge length in world voxels
    int32_t minLevel = 2;
    int32_t maxLevel = 11;
    double maxHeight = 256.0; // world voxels; heights are stored as y / maxHeight

    double cellSize(int32_t level) const; // size / 2^level
};

// The upper bound of a meta point's noise amplitude A, warps D and F, rain w and capacity s
// (docs/terrain.md, "Value ranges"): the generator's check and the checker's keys read this one
// number, so a value the checker accepts is one the generator accepts.
inline constexpr double kMaxMetaFactor = 1e3;

// Table 3.1's meta point, with the spec's defaults (B3.1). Every attribute but u interpolates
// linearly between the two meta points around a spline position.
struct MetaPoint {
    double u = 0.0;               // position on the spline, in [0, pieces]
    double radius = 0.0;          // r: half width of the flat elevation band, world voxels
    glm::dvec2 left{0.0};         // a: (.x band width in world voxels, .y height rise in world voxels)
    glm::dvec2 right{0.0};        // b: the same on the right side
    double hardness = 0.0;        // h: beta at the spline side of a gradient band, in [0, 1]
    double noiseAmplitude = 0.0;  // A
    double noiseRoughness = 0.5;  // R
    double warpLow = 0.0;         // D
    double warpHigh = 0.0;        // F
    double rain = 1.0;            // w: rain multiplier
    double capacity = 1.0;        // s: sediment-capacity multiplier
};

struct Spline {
    // 3 * pieces + 1 control points (world x, y, z); piece k uses points 3k..3k+3.
    std::vector<glm::dvec3> controlPoints;
    std::vector<MetaPoint> metaPoints; // sorted by u; none means one default meta point
    int32_t minLevel = 0;              // active on levels minLevel..maxLevel (inclusive)
    int32_t maxLevel = 0;
    uint32_t samplings = 300;          // samples per piece (Table 5.1)

    uint32_t pieces() const { return controlPoints.size() < 4 ? 0 : uint32_t((controlPoints.size() - 1) / 3); }
    bool activeOn(int32_t level) const { return minLevel <= level && level <= maxLevel; }
};

// The noise of B3.3: N_L = (amplitude / maxHeight) * A * warped_fbm2(scale * xi / 1000, R, D, F).
struct NoiseSettings {
    double amplitude = 0.0; // world voxels (Table 5.1's "Noise Amplitude")
    double scale = 1.0;     // Table 5.1's "Noise Scale"
    uint32_t seed = 0;
};

// How a level's sweep count follows from its level number (B2.6): `level` = L * m (voxc's
// reading, default), `side` = 2^L * m, `sqrtSide` = 2^(L/2) * m.
enum class IterationRule : uint8_t { Level, Side, SqrtSide };

struct DiffusionSettings {
    double multiplier = 2.0; // Table 5.1's diffusion iteration multiplier m
    IterationRule rule = IterationRule::Level;
    bool isotropicGradient = false; // B2.8: G *= |N_x|^3 + |N_y|^3
    bool thesisProlongation = false; // B2.12: Alg. 4 (shifts half a fine cell per level) instead of bilinear
};

struct TerrainMap {
    Domain domain;
    std::vector<Spline> splines;
    NoiseSettings noise;
    DiffusionSettings diffusion;
};

// Throws ParameterError for a value outside its range and LimitError for a size over `limits`.
void validateMap(const TerrainMap& map, const Limits& limits);

// Terrain sweeps on `level` (>= 1); the normal and parameter fields run max(1, sweeps / 2).
uint32_t terrainSweeps(const DiffusionSettings& settings, int32_t level);
uint32_t fieldSweeps(const DiffusionSettings& settings, int32_t level);

} // namespace voxc::terrain
