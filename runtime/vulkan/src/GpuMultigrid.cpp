#include "voxc/vulkan/GpuMultigrid.h"

#include "SolvePass.h"
#include "voxc/codegen/Template.h"
#include "voxc/core/Errors.h"
#include "voxc/vulkan/SolveRunner.h"

#include <fmt/format.h>

#include <bit>
#include <map>
#include <memory>
#include <mutex>

namespace voxc {

namespace {

constexpr uint32_t kLocalSize = 64; // every mg_*.glsl pass
enum Pass : uint32_t { kSmooth, kRestrict, kProlong, kResidual, kPassCount };
constexpr const char* kPassFiles[kPassCount] = {"mg_smooth.glsl", "mg_restrict.glsl", "mg_prolong.glsl",
                                                "mg_residual.glsl"};
constexpr uint32_t kMaskBuffer = 0, kUBuffer = 1, kFBuffer = 2, kMeasureBuffer = 3, kBufferCount = 4;

// SPIR-V of the passes per component count, compiled once per process.
const std::vector<Kernel>& passKernels(int32_t components) {
    static std::mutex mutex;
    static std::map<int32_t, std::vector<Kernel>> compiled;
    const std::lock_guard lock(mutex);
    const auto found = compiled.find(components);
    if (found != compiled.end()) return found->second;
    std::vector<Kernel> kernels;
    const codegen::TemplateSections sections{{"COMPONENTS", fmt::format("#define COMPONENTS {}", components)}};
    for (const char* file : kPassFiles)
        kernels.push_back(solvePassKernel(fmt::format("{} ({} components)", file, components), file,
                                          codegen::instantiateTemplate(file, sections), kLocalSize));
    return compiled.emplace(components, std::move(kernels)).first->second;
}

uint32_t groupsFor(int32_t invocations) { return uint32_t((invocations + int32_t(kLocalSize) - 1) / int32_t(kLocalSize)); }

struct Builder {
    const std::vector<curves::MultigridLevel>& levels;
    std::vector<int32_t> offsets; // each level's first cell

    SolveStep step(Pass pass, size_t fine, int32_t w, glm::ivec3 extent) const {
        SolveStep s;
        s.kernel = pass;
        s.groups[0] = groupsFor(extent.x), s.groups[1] = uint32_t(extent.y), s.groups[2] = uint32_t(extent.z);
        const curves::MultigridLevel& f = levels[fine];
        const size_t coarse = std::min(fine + 1, levels.size() - 1);
        const glm::ivec3 c = levels[coarse].size;
        s.push = {f.size.x, f.size.y, f.size.z, offsets[fine], c.x, c.y, c.z, offsets[coarse],
                  f.halved.x, f.halved.y, f.halved.z, w, std::bit_cast<int32_t>(f.weight.x),
                  std::bit_cast<int32_t>(f.weight.y), std::bit_cast<int32_t>(f.weight.z),
                  std::bit_cast<int32_t>(curves::kOverRelaxation)};
        return s;
    }
    void smooth(std::vector<SolveStep>& out, size_t l, int32_t sweeps) const {
        const glm::ivec3 size = levels[l].size;
        const glm::ivec3 half{(size.x + 1) / 2, size.y, size.z};
        for (int32_t s = 0; s < sweeps; ++s)
            for (int32_t colour : {0, 1}) out.push_back(step(kSmooth, l, colour, half));
    }
    // Level l+1 from level l: mode 0 residuals, 1 fixed values.
    void restrictTo(std::vector<SolveStep>& out, size_t l, int32_t mode) const {
        out.push_back(step(kRestrict, l, mode, levels[l + 1].size));
    }
    void prolongFrom(std::vector<SolveStep>& out, size_t l, bool add) const {
        out.push_back(step(kProlong, l, add ? 1 : 0, levels[l].size));
    }
    void vCycle(std::vector<SolveStep>& out, size_t l) const {
        if (l + 1 == levels.size()) return smooth(out, l, curves::kCoarsestSweeps);
        smooth(out, l, curves::kPreSmooth);
        restrictTo(out, l, 0);
        vCycle(out, l + 1);
        prolongFrom(out, l, true);
        smooth(out, l, curves::kPostSmooth);
    }
};

} // namespace

SolveProgram multigridProgram(const std::vector<curves::MultigridLevel>& levels, int32_t components, float tolerance,
                              int32_t maxCycles) {
    if (levels.empty() || components < 1 || components > 3)
        throw InternalError("multigridProgram: no levels, or a component count outside 1..3");
    Builder b{levels, {}};
    int64_t cells = 0;
    for (const curves::MultigridLevel& level : levels) {
        b.offsets.push_back(int32_t(cells));
        cells += int64_t(level.size.x) * level.size.y * level.size.z;
    }
    if (cells > INT32_MAX) throw InternalError("multigridProgram: more cells than int32 indexes");
    SolveProgram p;
    p.kernels = passKernels(components);
    p.bufferWords.assign(kBufferCount, 1);
    p.bufferWords[kMaskBuffer] = uint64_t(cells);
    p.bufferWords[kUBuffer] = p.bufferWords[kFBuffer] = uint64_t(cells) * uint64_t(components);
    // Full multigrid start: Dirichlet values down the levels, the coarsest solved, then per
    // finer level a prolongation and a V-cycle (curves::solveLaplace).
    for (size_t l = 0; l + 1 < levels.size(); ++l) b.restrictTo(p.prologue, l, 1);
    b.smooth(p.prologue, levels.size() - 1, curves::kCoarsestSweeps);
    for (size_t l = levels.size() - 1; l-- > 0;) {
        b.prolongFrom(p.prologue, l, false);
        b.vCycle(p.prologue, l);
    }
    b.vCycle(p.cycle, 0);
    p.measure.push_back(b.step(kResidual, 0, 0, levels[0].size));
    p.measureBuffer = kMeasureBuffer;
    p.tolerance = tolerance;
    p.maxCycles = maxCycles;
    return p;
}

curves::LinearSolver vulkanLinearSolver(VulkanContext& context) {
    return [&context](const std::string& name, const std::vector<uint8_t>& fixed, std::vector<curves::Field3*> components,
                      float tolerance, const curves::Limits& limits) {
        if (components.empty() || components.size() > 3)
            throw InternalError("curves: a Vulkan linear solve needs 1 to 3 components");
        for (const curves::Field3* c : components)
            if (c->box.size != components.front()->box.size || c->values.size() != fixed.size())
                throw InternalError("curves: the components and mask of a linear solve differ in size");
        const std::vector<curves::MultigridLevel> levels = curves::multigridLevels(components.front()->box.size);
        const SolveProgram program = multigridProgram(levels, int32_t(components.size()), tolerance, limits.maxCycles);
        // Masks of every level; the finest level's unknowns: the Dirichlet values, free cells 0.
        std::vector<std::vector<uint32_t>> initial(kBufferCount);
        for (const std::vector<uint8_t>& mask : curves::multigridMasks(levels, fixed))
            initial[kMaskBuffer].insert(initial[kMaskBuffer].end(), mask.begin(), mask.end());
        const size_t count = components.size();
        std::vector<uint32_t>& u = initial[kUBuffer];
        u.resize(fixed.size() * count, 0u);
        for (size_t c = 0; c < count; ++c)
            for (size_t i = 0; i < fixed.size(); ++i)
                if (fixed[i]) u[i * count + c] = std::bit_cast<uint32_t>(components[c]->values[i]);
        std::vector<uint64_t> read(kBufferCount, 0);
        read[kUBuffer] = fixed.size() * count;
        VulkanSolveRunner runner(context, program);
        const SolveRun run = runner.run(initial, read);
        curves::SolveReport report{name, int32_t(levels.size()), run.measures, {}}; // no per-level residuals
        if (!run.converged) throw curves::ConvergenceError(name, report.cycles(), report.residuals.back(), tolerance);
        const std::vector<uint32_t>& words = run.buffers.at(kUBuffer);
        VOXC_ASSERT(words.size() == fixed.size() * count);
        for (size_t c = 0; c < count; ++c)
            for (size_t i = 0; i < fixed.size(); ++i) components[c]->values[i] = std::bit_cast<float>(words[i * count + c]);
        return report;
    };
}

} // namespace voxc
