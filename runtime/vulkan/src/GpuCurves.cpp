#include "voxc/vulkan/GpuCurves.h"

#include "SolvePass.h"
#include "voxc/builtins/Shapes.h"
#include "voxc/codegen/Template.h"
#include "voxc/core/Errors.h"
#include "voxc/vulkan/GpuMultigrid.h"
#include "voxc/vulkan/SolveRunner.h"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>

namespace voxc {

namespace {

using curves::Box;
using curves::Field3;

constexpr uint32_t kLocalSize = 64; // every curves_*.glsl pass but the front's advance step
// Layers a front cycle expands between two read-backs of the front's size: an empty layer's
// dispatch is zero workgroups, so overshooting the last layer costs a few empty dispatches.
constexpr int32_t kLayersPerCycle = 8;
// FrontControl's words (curves_front_common.glsl).
enum FrontWord : uint32_t { kNextCount, kCount, kGroups, kLayer = kGroups + 3, kHalf, kLastLayer, kFrontWords };

// The pass's SPIR-V, compiled once per process.
const Kernel& passKernel(const char* file) {
    static std::mutex mutex;
    static std::map<std::string, Kernel> compiled;
    const std::lock_guard lock(mutex);
    const auto found = compiled.find(file);
    if (found != compiled.end()) return found->second;
    return compiled.emplace(file, solvePassKernel(file, file, codegen::instantiateTemplate(file, {}), kLocalSize)).first->second;
}

uint32_t word(float v) { return std::bit_cast<uint32_t>(v); }
float value(uint32_t w) { return std::bit_cast<float>(w); }

// One invocation per cell; push words: size (w: `first`), origin (w: `second`), the float, the seed.
SolveStep cellStep(uint32_t kernel, const Box& box, int32_t first, int32_t second, float f = 0.0f, int32_t seed = 0) {
    SolveStep s;
    s.kernel = kernel;
    s.groups[0] = uint32_t((box.size.x + int32_t(kLocalSize) - 1) / int32_t(kLocalSize));
    s.groups[1] = uint32_t(box.size.y), s.groups[2] = uint32_t(box.size.z);
    s.push = {box.size.x, box.size.y, box.size.z, first, box.min.x, box.min.y, box.min.z, second,
              std::bit_cast<int32_t>(f), 0, 0, 0, seed, 0, 0, 0};
    return s;
}

std::vector<uint32_t> words(const std::vector<float>& values) {
    std::vector<uint32_t> out(values.size());
    for (size_t i = 0; i < values.size(); ++i) out[i] = word(values[i]);
    return out;
}

// Runs a program whose steps all sit in its prologue.
SolveRun runOnce(VulkanContext& context, const SolveProgram& program, const std::vector<std::vector<uint32_t>>& initial,
                 const std::vector<uint64_t>& read) {
    VulkanSolveRunner runner(context, program);
    return runner.run(initial, read);
}

// A front propagation: buffers 0 layers, 1 fronts, 2 control, then the pass's own. `seeds` are
// layer 0, ascending; `own` the pass's buffers' initial words. Returns the run (its buffers read
// per `read`) and the last layer that reached a cell.
struct FrontRun {
    SolveRun run;
    int32_t lastLayer = 0;
};
FrontRun runFront(VulkanContext& context, const char* pass, const Box& box, int32_t rule,
                  const std::vector<uint32_t>& seeds, std::vector<std::vector<uint32_t>> own, std::vector<uint64_t> read) {
    const uint64_t cells = box.cellCount();
    if (cells * 2 > uint64_t(std::numeric_limits<uint32_t>::max()))
        throw InternalError("curves: a front over more cells than uint32 indexes");
    SolveProgram p;
    p.kernels = {passKernel(pass), passKernel("curves_front_advance.glsl")};
    p.bufferWords = {cells, cells * 2, kFrontWords};
    for (const std::vector<uint32_t>& w : own) p.bufferWords.push_back(w.size());
    for (int32_t l = 0; l < kLayersPerCycle; ++l) {
        SolveStep expand = cellStep(0, box, rule, 0);
        expand.indirect = true;
        expand.indirectBuffer = 2, expand.indirectWord = kGroups;
        SolveStep advance = cellStep(1, box, rule, 0);
        advance.groups[0] = advance.groups[1] = advance.groups[2] = 1;
        p.cycle.push_back(expand);
        p.cycle.push_back(advance);
    }
    p.stop = SolveProgram::Stop::CountIsZero;
    p.measureBuffer = 2, p.measureWord = kCount;
    // Each cycle but the last expands at least one layer that reaches a cell; layers <= the cells.
    p.maxCycles = int32_t(std::min<uint64_t>(cells / kLayersPerCycle + 2, std::numeric_limits<int32_t>::max()));

    std::vector<std::vector<uint32_t>> initial(3);
    initial[0].assign(cells, uint32_t(-1));
    for (uint32_t i : seeds) initial[0][i] = 0;
    initial[1] = seeds;
    const uint32_t groups = (uint32_t(seeds.size()) + kLocalSize - 1) / kLocalSize;
    initial[2] = {0, uint32_t(seeds.size()), std::min(groups, 65535u), (groups + 65534u) / 65535u, 1, 1, 0, 0};
    for (std::vector<uint32_t>& w : own) initial.push_back(std::move(w));
    read.insert(read.begin(), {cells, 0, kFrontWords});
    FrontRun out;
    out.run = runOnce(context, p, initial, read);
    if (!out.run.converged) throw InternalError(fmt::format("curves: the {} front did not run out", pass));
    out.lastLayer = int32_t(out.run.buffers.at(2).at(kLastLayer));
    return out;
}

} // namespace

void vulkanPeronaMalikSweeps(VulkanContext& context, const curves::Constraints& cs, curves::NormalField& n, float k,
                             uint32_t sweeps) {
    const Box& b = cs.box;
    const uint64_t cells = b.cellCount();
    SolveProgram p;
    p.kernels = {passKernel("curves_pm_normalize.glsl"), passKernel("curves_pm_sweep.glsl")};
    // Flags, the even half of the normals, the unit normals, the odd half.
    p.bufferWords = {cells, cells * 3, cells * 3, cells * 3};
    for (uint32_t s = 0; s < sweeps; ++s) {
        const int32_t source = int32_t(s % 2);
        p.prologue.push_back(cellStep(0, b, source, 0));
        p.prologue.push_back(cellStep(1, b, source, 0, k));
    }
    std::vector<std::vector<uint32_t>> initial(4);
    initial[0].resize(cells);
    initial[1].resize(cells * 3);
    for (size_t i = 0; i < cells; ++i) {
        initial[0][i] = (n.set[i] ? 1u : 0u) | ((cs.flags[i] & curves::kInNormals) ? 2u : 0u);
        initial[1][i * 3] = word(n.x.values[i]), initial[1][i * 3 + 1] = word(n.y.values[i]);
        initial[1][i * 3 + 2] = word(n.z.values[i]);
    }
    initial[3] = initial[1]; // cells a sweep skips never change: both halves hold them
    const uint32_t result = sweeps % 2 == 0 ? 1 : 3;
    std::vector<uint64_t> read(4, 0);
    read[result] = cells * 3;
    const SolveRun run = runOnce(context, p, initial, read);
    const std::vector<uint32_t>& out = run.buffers.at(result);
    for (size_t i = 0; i < cells; ++i) {
        n.x.values[i] = value(out[i * 3]);
        n.y.values[i] = value(out[i * 3 + 1]);
        n.z.values[i] = value(out[i * 3 + 2]);
    }
}

Field3 vulkanSmoothBinomial(VulkanContext& context, const Field3& field, int32_t passes) {
    if (passes <= 0) return field;
    const Box& b = field.box;
    const uint64_t cells = b.cellCount();
    SolveProgram p;
    p.kernels = {passKernel("curves_smooth.glsl")};
    p.bufferWords = {cells * 2};
    int32_t source = 0;
    for (int32_t pass = 0; pass < passes; ++pass)
        for (int32_t axis = 0; axis < 3; ++axis, source = 1 - source) p.prologue.push_back(cellStep(0, b, axis, source));
    const SolveRun run = runOnce(context, p, {words(field.values)}, {cells * 2});
    Field3 out(b);
    const std::vector<uint32_t>& w = run.buffers.at(0);
    for (size_t i = 0; i < cells; ++i) out.values[i] = value(w[uint64_t(source) * cells + i]);
    return out;
}

curves::MaterialField vulkanPropagateMaterial(VulkanContext& context, const curves::Constraints& cs) {
    const Box& b = cs.box;
    const uint64_t cells = b.cellCount();
    std::vector<uint32_t> seeds, material(cells, 0), confidence(cells, word(0.0f));
    for (uint32_t i = 0; i < cells; ++i)
        if (cs.flags[i] & curves::kInParams) seeds.push_back(i), material[i] = cs.material[i], confidence[i] = word(1.0f);
    const FrontRun f = runFront(context, "curves_front_material.glsl", b, 0, seeds, {material, confidence}, {cells, cells});
    curves::MaterialField out{std::vector<uint16_t>(cells, 0), Field3(b), std::vector<uint8_t>(cells, 0), f.lastLayer};
    const std::vector<uint32_t>& layers = f.run.buffers.at(0);
    for (size_t i = 0; i < cells; ++i) {
        out.assigned[i] = int32_t(layers[i]) >= 0 ? 1 : 0;
        out.material[i] = uint16_t(f.run.buffers.at(3)[i]);
        out.confidence.values[i] = value(f.run.buffers.at(4)[i]);
    }
    return out;
}

curves::SurfaceField vulkanPropagateSurface(VulkanContext& context, const curves::Constraints& cs, const Field3& nx,
                                            const Field3& ny, const Field3& nz, curves::PropagateRule rule) {
    const Box& b = cs.box;
    const uint64_t cells = b.cellCount();
    std::vector<uint32_t> seeds, distance(cells, word(std::numeric_limits<float>::infinity())), normals(cells * 3);
    for (uint32_t i = 0; i < cells; ++i) {
        if (cs.flags[i] & curves::kInSurface) seeds.push_back(i), distance[i] = word(cs.surface.values[i]);
        normals[i * 3] = word(nx.values[i]), normals[i * 3 + 1] = word(ny.values[i]), normals[i * 3 + 2] = word(nz.values[i]);
    }
    const FrontRun f = runFront(context, "curves_front_surface.glsl", b, rule == curves::PropagateRule::SignedMin ? 1 : 0,
                                seeds, {distance, normals}, {cells, 0});
    curves::SurfaceField out{Field3(b), std::vector<curves::FrontLayer>(cells), f.lastLayer};
    for (size_t i = 0; i < cells; ++i) {
        out.layer[i] = curves::FrontLayer(int32_t(f.run.buffers.at(0)[i]));
        out.distance.values[i] = value(f.run.buffers.at(3)[i]);
    }
    return out;
}

std::vector<float> vulkanDisplacement(VulkanContext& context, const Field3& amplitude, const Field3& roughness,
                                      float frequency, uint32_t seed) {
    const Box& b = amplitude.box;
    const uint64_t cells = b.cellCount();
    SolveProgram p;
    p.kernels = {passKernel("curves_displace.glsl")};
    p.bufferWords = {cells, cells, 256, cells};
    p.prologue.push_back(cellStep(0, b, 0, 0, frequency, int32_t(seed)));
    std::vector<uint32_t> permutation;
    for (int v : perlinPermutation()) permutation.push_back(uint32_t(v));
    const SolveRun run = runOnce(context, p, {words(amplitude.values), words(roughness.values), permutation}, {0, 0, 0, cells});
    std::vector<float> out(cells);
    for (size_t i = 0; i < cells; ++i) out[i] = value(run.buffers.at(3)[i]);
    return out;
}

curves::Solvers vulkanCurvesSolvers(std::function<VulkanContext*()> device) {
    curves::Solvers s;
    s.linear = [device](const std::string& name, const std::vector<uint8_t>& fixed, std::vector<Field3*> components,
                        float tolerance, const curves::Limits& limits) {
        VulkanContext* c = device();
        return c ? vulkanLinearSolver(*c)(name, fixed, std::move(components), tolerance, limits)
                 : curves::solveLaplace(name, fixed, std::move(components), tolerance, limits);
    };
    s.peronaMalik = [device](const curves::Constraints& cs, curves::NormalField& n, float k, uint32_t sweeps) {
        VulkanContext* c = device();
        return c ? vulkanPeronaMalikSweeps(*c, cs, n, k, sweeps) : curves::peronaMalikSweeps(cs, n, k, sweeps);
    };
    s.smoothing = [device](const Field3& field, int32_t passes) {
        VulkanContext* c = device();
        return c ? vulkanSmoothBinomial(*c, field, passes) : curves::smoothBinomial(field, passes);
    };
    s.material = [device](const curves::Constraints& cs) {
        VulkanContext* c = device();
        return c ? vulkanPropagateMaterial(*c, cs) : curves::propagateMaterial(cs);
    };
    s.surface = [device](const curves::Constraints& cs, const Field3& nx, const Field3& ny, const Field3& nz,
                         curves::PropagateRule rule) {
        VulkanContext* c = device();
        return c ? vulkanPropagateSurface(*c, cs, nx, ny, nz, rule) : curves::propagateSurface(cs, nx, ny, nz, rule);
    };
    // Without a device, none: the host evaluates the displacement only where it counts (Scene.cpp).
    s.displacement = [device](const Field3& amplitude, const Field3& roughness, float frequency, uint32_t seed) {
        VulkanContext* c = device();
        return c ? vulkanDisplacement(*c, amplitude, roughness, frequency, seed) : std::vector<float>{};
    };
    return s;
}

} // namespace voxc
