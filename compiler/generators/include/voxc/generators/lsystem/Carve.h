#pragma once
// The cave carve (spec §5.2, docs/architecture.md "Carving"): a skeleton's structural points,
// displaced on the CPU by curl noise, become a point set (voxc/program/PointSet.h); the carve is
// an ordinary field whose value at world voxel v is, in the spec's terms, f = (1 + F_tot) / 2
// (1 = cave air, 0 = rock), written as
//   M(v)    = clamp(1 + a_s m_s S + a_v m_v V, m_min, m_max)   (the 6 noise calls per voxel)
//   f_brush = clamp(1 - M D / 2, 0, 1),   D = min over displaced centres c_i of |v - c_i| / R_i
//   f_clr   = min(0.5 + 0.5x, 0.5 + 4x),     x = 1 - D_s / r_clear, D_s = distance to the skeleton
//   f       = max(f_brush, f_clr)
// so every voxel closer than r_clear to the skeleton is air (f > 0.5), and f is exactly 0 farther
// than 2R_i/m_min from every centre and 1.125 r_clear from the skeleton (the clearance term falls
// 8 times faster outside r_clear than inside, so it does not widen every tunnel by r_clear).
#include "voxc/generators/lsystem/Turtle.h"
#include "voxc/program/Field.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace voxc::lsystem {

struct CarveParams {
    double radius = 6.0;               // R: a metaball's air radius (voxels) on tunnels and connections
    double roomRadius = 0.0;           // R on segments of type room; 0 = radius
    double spacing = 0.0;              // d: between structural points; 0 = the segment's radius
    double clearance = 2.0;            // r_clear: always air within it of the skeleton
    double curlAmplitude = 3.0;        // A_c: the largest centre displacement
    double curlFrequency = 1.0 / 64.0; // f_c
    double yLimit = 0.25;              // k_y: the vertical share of the displacement
    double simplexFrequency = 1.0 / 48.0, simplexAmplitude = 0.35; // f_s, a_s
    double voronoiFrequency = 1.0 / 16.0, voronoiAmplitude = 0.25; // f_v, a_v
    double modulationFrequency = 1.0 / 256.0; // f_mod: the slow modulators m_c, m_s, m_v
    double minScale = 0.4, maxScale = 2.5;    // m_min, m_max: the clamp of M

    double radiusOf(SymbolType type) const;
};

struct CarveLimits {
    uint64_t maxCentres = uint64_t(1) << 18;
    uint64_t maxClearanceSegments = uint64_t(1) << 20;
    uint32_t maxPerCell = kMaxPointSetPerCell;          // centres or segments one 8^3 cell lists (GPU loop length)
    uint64_t maxListEntries = kMaxPointSetListEntries;  // list entries over all cells (the runtime's bounds too)
};

// The distance beyond which a centre or a skeleton segment changes nothing (its term of f is at
// most -0.1 before the clamp, resp. -0.5), a margin float roundings cannot cross: 2.2 / m_min in
// the centres' scaled distance (2.2 R_i / m_min voxels) and 1.25 r_clear. Distances are capped
// there (PointSet), so farther points need no listing.
double centreReach(const CarveParams& params);
double segmentReach(const CarveParams& params);

// Throws ParameterError-like UserErrors naming the key (docs/language.md keys) for unusable values.
void checkCarveParams(const CarveParams& params);

// Structural points (§5.2) with the radius of their segment's type: for each skeleton segment
// and connection-line segment (a, b), a + (k/n)(b - a) for k < n = max(1, ceil(|b - a| / d)),
// d = spacing or that radius, then every segment end that starts no segment (a leaf). Throws
// LimitError("maxCentres") before storing too many.
struct StructuralPoint {
    glm::dvec3 position{0.0};
    double radius = 0.0;
};
std::vector<StructuralPoint> structuralPoints(const Skeleton& skeleton, const CarveParams& params,
                                              const CarveLimits& limits);

// sp + A_c m_c (u.x, k_y u.y, u.z): u = c / max(|c|, 1), c = curl3(sp f_c, substream(seed, 311)),
// m_c = 0.5 + 0.5 simplex3(sp f_mod, substream(seed, 321)); in double, the caller rounds once.
glm::dvec3 displacedCentre(glm::dvec3 point, const CarveParams& params, uint32_t seed);

// The skeleton's displaced centres and clearance segments (skeleton and connection lines), with
// the lists binned over the grid worldOrigin .. worldOrigin + worldSize - 1 (the same lists every
// backend reads). Throws LimitError for more centres or segments than the limits allow, and for
// lists over maxPerCell / maxListEntries.
std::shared_ptr<const PointSet> carvePointSet(const Skeleton& skeleton, const CarveParams& params, uint32_t seed,
                                              glm::ivec3 worldOrigin, glm::ivec3 worldSize, const CarveLimits& limits);

// binPointSetOverGrid, turning PointSetLimitError into LimitError.
PointBins binCarveCells(const PointSet& set, glm::ivec3 worldOrigin, glm::ivec3 worldSize, const CarveLimits& limits);

// Where the carve's point set is measured from: the voxel's world place (a pipeline stage), or
// a stamp's frame x, y, z (docs/language.md, "Stamps": the skeleton, moved to start at the
// frame's origin, moves and turns with the window that fires). The brush's noise reads the world place either way, so each stamped
// cave's walls differ.
enum class CarveFrame : uint8_t { World, Stamp };

// The carve's field (nodes and Float root; the caller names it and locates its nodes).
Field carveField(std::shared_ptr<const PointSet> set, const CarveParams& params, uint32_t seed,
                 CarveFrame frame = CarveFrame::World);

} // namespace voxc::lsystem
