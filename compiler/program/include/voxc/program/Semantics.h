#pragma once
// The grammar's execution order, defined once (digest §1, decisions 2-4) and used by the
// interpreter, the IR lowering and the runtime's dispatch expansion alike.
//
// - Rules of one window size form a sweep; sweeps run largest window volume first, equal
//   volumes in the declaration order of their first rule.
// - Anchors are boundsMin + n*stride for every n whose window lies inside the half-open bounds.
// - A sweep's anchors split into phases by n mod ceil(size/stride) per axis, so the windows of
//   one phase never overlap. n counts from the declared bounds' min (Grammar::firstAnchor), so a
//   region grid runs the declared grid's phases. Phases run x fastest, then y, then z; each reads the previous result.
// - Among matching rules the highest priority wins; ties are drawn by weight with
//   anchorHash(RuleChoice); the chosen rule then fires with its probability (anchorHash(Probability)).
// - Stamps: once every window of a phase was matched and transformed, the stamps of the phase's
//   firings are applied one firing after another in anchor order (z, then y, then x), each over
//   its window grown by its reach, clipped to the grid, combined like a field stage
//   (combineField; a non-finite field value is 0). Grown windows of one phase may overlap.
#include "voxc/program/Program.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace voxc {

struct Sweep {
    glm::ivec3 window{1, 1, 1};
    std::vector<uint32_t> rules; // indices into Grammar::rules, declaration order
    glm::ivec3 anchorCount{0};   // anchors per axis over the whole sweep (0: window does not fit)
    glm::ivec3 phaseCount{1};    // ceil(window / stride) per axis
    int phases() const { return phaseCount.x * phaseCount.y * phaseCount.z; }
};

std::vector<Sweep> orderSweeps(const Grammar& grammar);

// Phase p in [0, sweep.phases()) as per-axis residues, x fastest.
glm::ivec3 phaseResidue(const Sweep& sweep, int phase);

// The anchors of one phase: start + i*step for i in [0, count) per axis (grid-local).
struct PhaseAnchors {
    glm::ivec3 start{0};
    glm::ivec3 step{1};
    glm::ivec3 count{0};
};
PhaseAnchors phaseAnchors(const Grammar& grammar, const Sweep& sweep, int phase);

// Picks among the matched rules (indices into Grammar::rules, ascending) at one anchor.
// Returns the rule that fires, or -1 when none does (no match, or the probability draw failed).
int chooseRule(const Grammar& grammar, const std::vector<uint32_t>& matched, uint32_t seed, uint32_t iteration,
               uint32_t sweepIndex, glm::ivec3 anchorWorld);

// kSolidDensity (Aggregates.h): densities at or above it are solid for material writes too.

// One voxel's channels.
struct VoxelState {
    float density = 0.0f;
    uint8_t material = kMaterialNone;
};

// A field stage at one voxel: the field's value `f` combined with the voxel by `mode`
// (d = f, max(d, f), min(d, 1 - f), min(d, f); Paint keeps d), with max(a, b) = a < b ? b : a
// and min(a, b) = b < a ? b : a so ties and signed zeros resolve identically on every backend.
// When the stage has a material it is written where the field *wins* and the voxel ends solid:
//   set: always wins; union: f > d; subtract: 1 - f < d; intersect: f < d; paint: f >= 0.5;
// and then the resulting density >= kSolidDensity. So `union arch material stone` paints the
// arch's new rock, `subtract cave material sand` paints the rock left in the cave's density ramp
// (its walls), and `paint low material rock` paints solid voxels where `low` is >= 0.5.
// (inline: combineFieldRow's loops inline it per mode)
inline VoxelState combineField(FieldMode mode, std::optional<uint8_t> material, float f, VoxelState voxel) {
    const float d = voxel.density;
    float result = d;
    bool wins = false;
    switch (mode) {
    case FieldMode::Set: result = f, wins = true; break;
    case FieldMode::Union: wins = d < f, result = wins ? f : d; break;
    case FieldMode::Subtract: {
        const float carved = 1.0f - f;
        wins = carved < d, result = wins ? carved : d;
        break;
    }
    case FieldMode::Intersect: wins = f < d, result = wins ? f : d; break;
    case FieldMode::Paint: wins = f >= kSolidDensity; break;
    }
    VoxelState out{result, voxel.material};
    if (material && wins && result >= kSolidDensity) out.material = *material;
    return out;
}

// combineField at each of n voxels in a row: field values f[i], densities d[i], materials m[i].
void combineFieldRow(FieldMode mode, std::optional<uint8_t> material, const float* f, int n, float* d, uint8_t* m);

} // namespace voxc
