#include "voxc/generators/caves/Speleothems.h"

#include "voxc/builtins/Functions.h"
#include "voxc/core/Errors.h"
#include "voxc/generators/WorkErrors.h"
#include "voxc/program/Semantics.h"

#include <array>
#include <cmath>
#include <fmt/format.h>

namespace voxc::caves {

namespace {

constexpr std::array<std::string_view, 4> kKindNames{"stalactite", "stalagmite", "column", "hoodoo"};

void checkRange(const char* key, double value, double lo, double hi) {
    if (!std::isfinite(value)) throw generators::ParameterError("speleothems", key, value, "must be finite");
    if (value < lo || value > hi)
        throw generators::ParameterError("speleothems", key, value, fmt::format("must lie in [{}, {}]", lo, hi));
}

// The builtin simplex3 record, so the noise is the one field expressions and the GPU use.
float simplex3(glm::vec3 p, uint32_t seed) {
    static const FunctionInfo* record = findFunction("simplex3");
    VOXC_ASSERT(record != nullptr);
    const std::array<Value, 2> args{Value::makeVec3(p), Value::makeInt(int32_t(seed))};
    return record->eval(args).v.x;
}

bool growsDown(SpeleothemKind kind) { return kind != SpeleothemKind::Stalagmite; }
bool growsUp(SpeleothemKind kind) { return kind != SpeleothemKind::Stalactite; }

// Union with the taper density at grid voxel (x, y, z), as a field stage's union combines.
void writeVoxel(const SpeleothemParams& params, glm::ivec3 origin, glm::ivec3 local, float value, DenseGrid& grid,
                const ProtectedVoxel& isProtected) {
    if (isProtected && isProtected(origin + local)) return;
    const VoxelState out =
        combineField(FieldMode::Union, params.material, value, VoxelState{grid.at(local), grid.materialAt(local)});
    grid.at(local) = out.density;
    grid.materialAt(local) = out.material;
}

// The features of source column (sx, sz), written into column (x, z) of `grid`.
void growFrom(const SpeleothemParams& params, uint32_t seed, glm::ivec3 origin, const AirMask& before, int32_t sx,
              int32_t sz, int32_t x, int32_t z, DenseGrid& grid, const ProtectedVoxel& isProtected) {
    for (const AirRun& run : closedRuns(params, before, sx, sz)) {
        const int32_t length = speleothemLength(params, seed, origin.x + sx, origin.z + sz, origin.y + run.floorY,
                                                origin.y + run.ceilingY);
        for (int32_t k = 0; k < length; ++k) {
            const float value = taperDensity(k, length, params.taper);
            if (growsDown(params.kind)) writeVoxel(params, origin, {x, run.ceilingY - 1 - k, z}, value, grid, isProtected);
            if (growsUp(params.kind)) writeVoxel(params, origin, {x, run.floorY + 1 + k, z}, value, grid, isProtected);
        }
    }
}

} // namespace

std::string_view speleothemKindName(SpeleothemKind kind) { return kKindNames[size_t(kind)]; }

std::optional<SpeleothemKind> findSpeleothemKind(std::string_view name) {
    for (size_t i = 0; i < kKindNames.size(); ++i)
        if (kKindNames[i] == name) return SpeleothemKind(i);
    return std::nullopt;
}

void checkSpeleothemParams(const SpeleothemParams& p) {
    checkRange("cluster_frequency", p.clusterFrequency, 0, 1000);
    checkRange("cluster_low", p.clusterLow, -1, 1);
    checkRange("cluster_high", p.clusterHigh, -1, 1);
    if (p.clusterLow > p.clusterHigh)
        throw generators::ParameterError("speleothems", "cluster_low", p.clusterLow,
                                         fmt::format("must be <= cluster_high ({})", p.clusterHigh));
    checkRange("spawn_frequency", p.spawnFrequency, 0, 1000);
    // Below 1, so 1 - s_thr (the reach's denominator) is positive; the bound as the float a
    // checked 0.99 becomes, so the checker's range and this one agree.
    checkRange("spawn_threshold", p.spawnThreshold, -1, double(0.99f));
    checkRange("growth", p.growth, 0, 1000);
    checkRange("taper", p.taper, 0, 8);
    checkRange("min_gap", p.minGap, 1, 4096);
    checkRange("max_gap", p.maxGap, p.minGap, 4096);
}

uint32_t clusterSeed(uint32_t seed) { return seed + 401u * 0x9E3779B9u; }
uint32_t spawnSeed(uint32_t seed) { return seed + 402u * 0x9E3779B9u; }

AirMask::AirMask(const DenseGrid& grid)
    : size_(grid.size()), wordsPerColumn_((grid.size().y + 31) / 32),
      words_(size_t(size_.x) * size_t(size_.z) * size_t(wordsPerColumn_), 0u) {
    for (int32_t z = 0; z < size_.z; ++z)
        for (int32_t x = 0; x < size_.x; ++x)
            for (int32_t y = 0; y < size_.y; ++y)
                if (grid.at({x, y, z}) < kSolidDensity) words_[columnStart(x, z) + size_t(y / 32)] |= 1u << (y % 32);
}

std::vector<AirRun> closedRuns(const SpeleothemParams& params, const AirMask& mask, int32_t x, int32_t z) {
    std::vector<AirRun> runs;
    int32_t floorY = -1; // the last rock voxel below; none yet, so air from the bottom is open
    for (int32_t y = 0; y < mask.size().y; ++y) {
        if (mask.air(x, y, z)) continue;
        const AirRun run{floorY, y};
        if (floorY >= 0 && run.gap() >= params.minGap && run.gap() <= params.maxGap) runs.push_back(run);
        floorY = y;
    }
    return runs;
}

int32_t speleothemLength(const SpeleothemParams& params, uint32_t seed, int32_t worldX, int32_t worldZ,
                         int32_t worldFloorY, int32_t worldCeilingY) {
    // Integer sum first, then one conversion and an exact halving.
    const glm::vec3 midpoint(float(worldX), float(worldFloorY + worldCeilingY) * 0.5f, float(worldZ));
    const float cluster = simplex3(midpoint * params.clusterFrequency, clusterSeed(seed));
    if (!(cluster >= params.clusterLow && cluster <= params.clusterHigh)) return 0;
    const float spawn = simplex3(midpoint * params.spawnFrequency, spawnSeed(seed));
    if (!(spawn > params.spawnThreshold)) return 0;
    const float reach = params.growth * (spawn - params.spawnThreshold) * speleothemReachScale(params);
    const float phi = std::min(std::max(reach, 0.0f), 1.0f);
    return int32_t(std::ceil(phi * float(worldCeilingY - worldFloorY - 1) * 0.5f));
}

float taperDensity(int32_t k, int32_t length, int32_t taper) {
    const float t = float(length - k) / float(length + 1);
    float power = 1.0f;
    for (int32_t i = 0; i < taper; ++i) power = power * t;
    return 0.5f + 0.5f * power;
}

void growSpeleothemColumn(const SpeleothemParams& params, uint32_t seed, glm::ivec3 origin, const AirMask& before,
                          int32_t x, int32_t z, DenseGrid& grid, const ProtectedVoxel& isProtected) {
    VOXC_ASSERT(before.size() == grid.size());
    growFrom(params, seed, origin, before, x, z, x, z, grid, isProtected);
    if (params.kind != SpeleothemKind::Hoodoo) return;
    if (x > 0) growFrom(params, seed, origin, before, x - 1, z, x, z, grid, isProtected);
    if (z > 0) growFrom(params, seed, origin, before, x, z - 1, x, z, grid, isProtected);
    if (x > 0 && z > 0) growFrom(params, seed, origin, before, x - 1, z - 1, x, z, grid, isProtected);
}

void growSpeleothems(const SpeleothemParams& params, uint32_t seed, glm::ivec3 origin, DenseGrid& grid,
                     const ProtectedVoxel& isProtected) {
    checkSpeleothemParams(params);
    const AirMask before(grid);
    for (int32_t z = 0; z < grid.size().z; ++z)
        for (int32_t x = 0; x < grid.size().x; ++x) growSpeleothemColumn(params, seed, origin, before, x, z, grid, isProtected);
}

} // namespace voxc::caves
