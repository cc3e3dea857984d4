#include "voxc/vulkan/GpuErosion.h"

#include "SolvePass.h"
#include "voxc/codegen/Template.h"
#include "voxc/core/Errors.h"
#include "voxc/vulkan/SolveRunner.h"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <mutex>

namespace voxc {

namespace {

constexpr uint32_t kLocalSize = 64; // every erosion_*.glsl pass
enum Pass : uint32_t { kRainPass, kSurfacePass, kFluxPass, kWaterPass, kErodePass, kTransportPass, kEvaporatePass, kPassCount };
constexpr const char* kPassFiles[kPassCount] = {"erosion_rain.glsl",  "erosion_surface.glsl",   "erosion_flux.glsl",
                                                "erosion_water.glsl", "erosion_erode.glsl",     "erosion_transport.glsl",
                                                "erosion_evaporate.glsl"};
constexpr uint32_t kStateBuffer = 0, kMeasureBuffer = 1;

// Buffer 0: kHeaderWords constants (erosion_common.glsl's k* word indices), then the channels.
constexpr uint32_t kHeaderWords = 16;
enum Channel : int32_t {
    kBase, kRainField, kCapacityField, kDifference0, kDifference1, kWater, kSediment, kFluxL, kFluxR, kFluxT, kFluxB,
    kVelocityU, kVelocityV, kSuspended, kSurfaceField, kChannelCount
};

// The grid's fields by channel (the two S_h channels are difference and differenceNext).
std::array<terrain::Field2*, kChannelCount> channels(terrain::ErosionGrid& g) {
    return {&g.base,     &g.rain,  &g.capacity, &g.difference, &g.differenceNext, &g.water,     &g.sediment, &g.fluxL,
            &g.fluxR,    &g.fluxT, &g.fluxB,    &g.velocityU,  &g.velocityV,      &g.suspended, &g.surface};
}

// SPIR-V of the passes, compiled once per process.
const std::vector<Kernel>& passKernels() {
    static std::once_flag once;
    static std::vector<Kernel> kernels;
    std::call_once(once, [] {
        for (const char* file : kPassFiles) kernels.push_back(solvePassKernel(file, file, codegen::instantiateTemplate(file, {}), kLocalSize));
    });
    return kernels;
}

int32_t floatWord(float v) { return std::bit_cast<int32_t>(v); }

// The constants the passes read, each computed here in float exactly as the host step does.
std::vector<uint32_t> header(const terrain::ErosionParams& p) {
    const float limited = std::isfinite(p.depthLimit) ? 1.0f : 0.0f;
    const float values[] = {(p.dt * p.pipeArea) * p.gravity,
                            p.pipeLength,
                            p.cellSize * p.cellSize,
                            p.dt,
                            (0.5f * p.cellSize) / p.dt,
                            p.cellSize,
                            p.depthLimit,
                            limited,
                            p.capacity,
                            p.minTilt,
                            p.dt * p.suspension,
                            p.dt * p.deposition};
    std::vector<uint32_t> words(kHeaderWords, 0);
    for (size_t i = 0; i < std::size(values); ++i) words[i] = std::bit_cast<uint32_t>(values[i]);
    return words;
}

} // namespace

SolveProgram erosionProgram(int32_t width, int32_t height, const terrain::ErosionParams& params, int32_t level,
                            uint32_t firstStep, uint32_t steps, bool drain) {
    const uint64_t cells = uint64_t(width) * uint64_t(height);
    if (width < 1 || height < 1 || kHeaderWords + kChannelCount * cells > uint64_t(INT32_MAX))
        throw InternalError("erosionProgram: a grid outside what int32 word indexes reach");
    SolveProgram p;
    p.kernels = passKernels();
    p.bufferWords = {kHeaderWords + kChannelCount * cells, 1};
    p.measureBuffer = kMeasureBuffer;
    const auto step = [&](Pass pass, int32_t difference, int32_t mode, std::array<float, 4> values = {}) {
        SolveStep s;
        s.kernel = pass;
        s.groups[0] = uint32_t((cells + kLocalSize - 1) / kLocalSize);
        s.push = {width, height, difference, difference == kDifference0 ? kDifference1 : kDifference0, mode, 0, 0, 0,
                  floatWord(values[0]), floatWord(values[1]), floatWord(values[2]), floatWord(values[3])};
        p.prologue.push_back(s);
    };
    int32_t difference = kDifference0;
    const float keep = drain ? 1.0f - 0.9f : 1.0f - params.evaporation * params.dt;
    for (uint32_t n = firstStep; n < firstStep + steps; ++n) {
        if (!drain && params.rain == terrain::RainMode::Uniform) step(kRainPass, difference, 0, {params.dt * params.uniformRain});
        if (!drain && params.rain == terrain::RainMode::Drops) {
            const terrain::Drop drop = terrain::dropAt(params, width, height, level, n);
            step(kRainPass, difference, 1, {drop.intensity, drop.radius * drop.radius, drop.centreX, drop.centreY});
        }
        step(kSurfacePass, difference, 1);
        step(kFluxPass, difference, 0);
        step(kWaterPass, difference, 0);
        step(kSurfacePass, difference, 0);
        step(kErodePass, difference, 0);
        difference = difference == kDifference0 ? kDifference1 : kDifference0;
        step(kTransportPass, difference, params.transport == terrain::Transport::Mei ? 1 : 0);
        step(kEvaporatePass, difference, 0, {keep});
    }
    return p;
}

terrain::ErosionRunner vulkanErosionRunner(VulkanContext& context) {
    return [&context](terrain::ErosionGrid& grid, const terrain::ErosionParams& params, int32_t level,
                      uint32_t firstStep, uint32_t steps, bool drain) {
        const SolveProgram program =
            erosionProgram(grid.width(), grid.height(), params, level, firstStep, steps, drain);
        const size_t cells = grid.base.values.size();
        std::vector<uint32_t> state = header(params);
        state.reserve(kHeaderWords + kChannelCount * cells);
        for (terrain::Field2* field : channels(grid))
            for (float v : field->values) state.push_back(std::bit_cast<uint32_t>(v));
        VulkanSolveRunner runner(context, program);
        const SolveRun run = runner.run({state}, {program.bufferWords[kStateBuffer]});
        const std::vector<uint32_t>& out = run.buffers.at(kStateBuffer);
        const auto fields = channels(grid);
        for (size_t c = 0; c < fields.size(); ++c)
            for (size_t i = 0; i < cells; ++i)
                fields[c]->values[i] = std::bit_cast<float>(out[kHeaderWords + c * cells + i]);
        // The host swaps S_h with its other half once per step.
        if (steps % 2 == 1) std::swap(grid.difference, grid.differenceNext);
    };
}

} // namespace voxc
