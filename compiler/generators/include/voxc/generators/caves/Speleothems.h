#pragma once
// Speleothems (lsystem-spec §6.2): stalactites, stalagmites, columns and hoodoos grown into the
// closed air runs of every grid column, from cluster and spawn simplex noise at the run's
// midpoint. A stage that reads the grid earlier stages wrote. Runs are found in the grid as it
// was before the stage (`AirMask`), so no feature sees another one and the result does not
// depend on the order columns are visited in, nor on the chunk size. compiler/shaders/
// speleothems.glsl performs the same float operations in the same order (bit-exact on lavapipe).
#include "voxc/grid/Grid.h"
#include "voxc/program/Speleothems.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace voxc::caves {

std::string_view speleothemKindName(SpeleothemKind kind); // "stalactite", ...
std::optional<SpeleothemKind> findSpeleothemKind(std::string_view name);

// Throws generators::ParameterError naming the first bad key as a .vox file writes it.
void checkSpeleothemParams(const SpeleothemParams& params);

// Seeds of the two noise fields: the builtins' substream(seed, 401) and (seed, 402).
uint32_t clusterSeed(uint32_t seed);
uint32_t spawnSeed(uint32_t seed);

// The voxels that were air (density < 0.5; NaN is not air) before the stage, one bit per voxel.
// Column (x, z) owns `wordsPerColumn` consecutive words from (x + size.x * z) * wordsPerColumn;
// voxel y is bit y % 32 of its word y / 32 (the GPU's scratch buffer has this layout).
class AirMask {
public:
    explicit AirMask(const DenseGrid& grid);
    glm::ivec3 size() const { return size_; }
    int32_t wordsPerColumn() const { return wordsPerColumn_; }
    bool air(int32_t x, int32_t y, int32_t z) const {
        return (words_[columnStart(x, z) + size_t(y / 32)] >> (y % 32) & 1u) != 0;
    }
    const std::vector<uint32_t>& words() const { return words_; }

private:
    size_t columnStart(int32_t x, int32_t z) const { return (size_t(x) + size_t(size_.x) * size_t(z)) * size_t(wordsPerColumn_); }
    glm::ivec3 size_;
    int32_t wordsPerColumn_;
    std::vector<uint32_t> words_;
};

// A closed air run of one column: rock at floorY and ceilingY (grid-local), air between.
struct AirRun {
    int32_t floorY = 0;
    int32_t ceilingY = 0;
    int32_t gap() const { return ceilingY - floorY - 1; }
};

// The closed runs of column (x, z) with min_gap <= gap <= max_gap, bottom up. A run that reaches
// the grid's bottom or top has no floor or ceiling there and is not listed.
std::vector<AirRun> closedRuns(const SpeleothemParams& params, const AirMask& mask, int32_t x, int32_t z);

// L, the voxels a feature grows from each anchor: 0 when the run's midpoint fails the cluster
// range or the spawn threshold, else ceil(phi * gap / 2) with
// phi = clamp(growth * (n_s - s_thr) * speleothemReachScale, 0, 1), the scale 1 / (1 - s_thr).
// `worldX`, `worldZ`: the column; the midpoint's y is (world floor + world ceiling) / 2.
int32_t speleothemLength(const SpeleothemParams& params, uint32_t seed, int32_t worldX, int32_t worldZ,
                         int32_t worldFloorY, int32_t worldCeilingY);

// The density of the k-th voxel from its anchor (k = 0 .. length - 1):
// 0.5 + 0.5 * ((length - k) / (length + 1))^taper, which is 1 - (k + 1) / (length + 1) of the spec.
float taperDensity(int32_t k, int32_t length, int32_t taper);

// True where the stage must not write (an L-system's clearance radius); world coordinates.
using ProtectedVoxel = std::function<bool(glm::ivec3 world)>;

// Writes every feature that reaches column (x, z) into that column only, found in `before` at
// (x, z) and, for hoodoos, also at (x-1, z), (x, z-1) and (x-1, z-1): the shape of one GPU
// invocation. Each voxel is the union (max) with the taper density, with the material where that
// wins and is solid; a protected voxel is never written.
void growSpeleothemColumn(const SpeleothemParams& params, uint32_t seed, glm::ivec3 origin, const AirMask& before,
                          int32_t x, int32_t z, DenseGrid& grid, const ProtectedVoxel& isProtected = {});

// The whole stage on the CPU: the air mask of `grid`, then every column. `origin`: the world
// coordinate of grid voxel (0, 0, 0).
void growSpeleothems(const SpeleothemParams& params, uint32_t seed, glm::ivec3 origin, DenseGrid& grid,
                     const ProtectedVoxel& isProtected = {});

} // namespace voxc::caves
