#include "voxc/generators/terrain/Terrain.h"

#include <array>
#include <fmt/format.h>

namespace voxc::terrain {

ErosionSettings presetSettings(std::string_view name) {
    const Preset* preset = findPreset(name);
    if (!preset) throw ParameterError(fmt::format("preset '{}'", name), 0.0, "is not one of fantasy, mountain_range, mountain_river, combined");
    ErosionSettings settings;
    settings.params = preset->params;
    settings.levelSteps = preset->levelSteps;
    return settings;
}

void runErosionSteps(ErosionGrid& grid, const ErosionParams& params, int32_t level, uint32_t firstStep,
                     uint32_t steps, bool drain) {
    erosionSteps(grid, params, level, firstStep, steps, drain);
}

Field2 gaussian5(const Field2& field) {
    static constexpr std::array<float, 25> kTaps{1, 4, 7, 4, 1, 4, 16, 26, 16, 4, 7, 26, 41, 26, 7, 4, 16, 26, 16, 4, 1, 4, 7, 4, 1};
    Field2 out(field.width, field.height);
    for (int32_t y = 0; y < field.height; ++y)
        for (int32_t x = 0; x < field.width; ++x) {
            float sum = 0.0f;
            for (int32_t j = 0; j < 5; ++j)
                for (int32_t i = 0; i < 5; ++i) sum = sum + kTaps[size_t(j * 5 + i)] * field.clamped(x + i - 2, y + j - 2);
            out.at(x, y) = sum / 273.0f;
        }
    return out;
}

namespace {

Field2 smoothFourTimes(Field2 field) {
    for (int k = 0; k < 4; ++k) field = gaussian5(field);
    return field;
}

void checkErosion(const TerrainMap& map, const ErosionSettings& erosion, const Limits& limits) {
    validateErosion(erosion.params);
    uint64_t cellSteps = 0;
    for (const auto& [level, steps] : erosion.levelSteps) {
        if (level < map.domain.minLevel || level > map.domain.maxLevel)
            throw ParameterError(fmt::format("erosion level {}", level), level,
                                 fmt::format("must lie in the map's levels {}..{}", map.domain.minLevel, map.domain.maxLevel));
        if (steps > limits.maxIterationsPerLevel) throw LimitError(fmt::format("erosion steps on level {}", level), steps, limits.maxIterationsPerLevel);
        cellSteps += (uint64_t(1) << (2 * level)) * steps;
    }
    if (erosion.drainSteps > limits.maxIterationsPerLevel) throw LimitError("drain steps", erosion.drainSteps, limits.maxIterationsPerLevel);
    cellSteps += (uint64_t(1) << (2 * map.domain.maxLevel)) * erosion.drainSteps;
    if (cellSteps > limits.maxErosionCellSteps) throw LimitError("erosion cell-steps", cellSteps, limits.maxErosionCellSteps);
}

double total(const Field2& field) {
    double sum = 0.0;
    for (float v : field.values) sum += v;
    return sum;
}

// Runs the erosion schedule level by level as the cascade delivers each level's terrain.
class ErosionRun {
public:
    ErosionRun(const TerrainMap& map, const ErosionSettings& settings, TerrainResult& result)
        : map_(map), settings_(settings), result_(result) {}

    void level(const LevelFields& fields) {
        const auto it = settings_.levelSteps.find(fields.level);
        const uint32_t steps = it == settings_.levelSteps.end() ? 0 : it->second;
        if (!grid_ && steps == 0) return; // below the first eroded level
        const int32_t n = fields.height.width;
        ErosionGrid next(n, n);
        if (grid_) { // carry the state up: prolong S_h, d, s and the fluxes, then the Gaussian x4 (velocity is recomputed)
            const bool thesis = settings_.thesisProlongation;
            next.difference = smoothFourTimes(prolong(grid_->difference, thesis));
            next.water = smoothFourTimes(prolong(grid_->water, thesis));
            next.sediment = smoothFourTimes(prolong(grid_->sediment, thesis));
            next.fluxL = smoothFourTimes(prolong(grid_->fluxL, thesis));
            next.fluxR = smoothFourTimes(prolong(grid_->fluxR, thesis));
            next.fluxT = smoothFourTimes(prolong(grid_->fluxT, thesis));
            next.fluxB = smoothFourTimes(prolong(grid_->fluxB, thesis));
        }
        const Field2 noise = levelNoise(map_, fields.level, fields.params);
        for (size_t i = 0; i < next.base.values.size(); ++i) next.base.values[i] = fields.height.values[i] + noise.values[i];
        next.rain = fields.params[size_t(Param::Rain)];
        next.capacity = fields.params[size_t(Param::Capacity)];
        grid_.emplace(std::move(next));
        if (steps > 0) runner()(*grid_, settings_.params, fields.level, 0, steps, false);
        result_.erosionSteps += steps;
        result_.erosionCellSteps += uint64_t(steps) * uint64_t(n) * uint64_t(n);
    }

    // The drain, the final deposit (S_h += s, s = 0; B2.5) and the Gaussian x4 on S_h.
    void finish() {
        if (!grid_) return;
        if (settings_.drainSteps > 0) runner()(*grid_, settings_.params, 0, 0, settings_.drainSteps, true);
        const uint64_t cells = grid_->base.values.size();
        result_.erosionSteps += settings_.drainSteps;
        result_.erosionCellSteps += uint64_t(settings_.drainSteps) * cells;
        for (size_t i = 0; i < cells; ++i) {
            grid_->difference.values[i] = grid_->difference.values[i] + grid_->sediment.values[i];
            grid_->sediment.values[i] = 0.0f;
        }
        grid_->difference = smoothFourTimes(grid_->difference);
    }

    const std::optional<ErosionGrid>& grid() const { return grid_; }

private:
    ErosionRunner runner() const { return settings_.runner ? settings_.runner : ErosionRunner(runErosionSteps); }

    const TerrainMap& map_;
    const ErosionSettings& settings_;
    TerrainResult& result_;
    std::optional<ErosionGrid> grid_;
};

} // namespace

void validateTerrain(const TerrainMap& map, const std::optional<ErosionSettings>& erosion, const Limits& limits) {
    validateMap(map, limits);
    if (erosion) checkErosion(map, *erosion, limits);
}

TerrainResult generateTerrain(const TerrainMap& map, const std::optional<ErosionSettings>& erosion, const Limits& limits) {
    validateTerrain(map, erosion, limits);
    TerrainResult result;
    std::optional<ErosionRun> run;
    if (erosion) run.emplace(map, *erosion, result);
    const LevelFields last = runCascade(map, limits, [&](const LevelFields& fields) {
        if (run) run->level(fields);
    });
    const int32_t n = last.height.width;
    if (run && run->grid()) { // eroded state is carried up to Lmax, where base = v + N already
        result.height = run->grid()->base;
    } else {
        result.height = levelNoise(map, map.domain.maxLevel, last.params);
        for (size_t i = 0; i < result.height.values.size(); ++i)
            result.height.values[i] = last.height.values[i] + result.height.values[i];
    }
    result.difference = result.water = result.sediment = Field2(n, n);
    if (run) {
        run->finish();
        if (run->grid()) {
            const ErosionGrid& grid = *run->grid();
            for (size_t i = 0; i < result.height.values.size(); ++i)
                result.height.values[i] = result.height.values[i] + grid.difference.values[i];
            result.difference = grid.difference;
            result.water = grid.water;
            result.sediment = grid.sediment;
        }
    }
    result.totalWater = total(result.water);
    result.totalSediment = total(result.sediment);
    result.totalDifference = total(result.difference);
    return result;
}

} // namespace voxc::terrain
