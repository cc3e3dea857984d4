// view_frame: what one frame of a viewer costs when the device draws offscreen, measured around
// MeshRenderer::draw (record, submit, wait, read back 1280x720 RGBA) with the scene uploaded once.
#include "ViewCases.h"

#include "Cases.h"

#include "voxc/mesh/MarchingCubes.h"
#include "voxc/render/MeshRenderer.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/vulkan/Executor.h"

#include <chrono>
#include <memory>

namespace voxc::bench {

void registerViewFrame(JsonReporter& reporter, VulkanContext& context) {
    constexpr rendering::ImageSize kSize{1280, 720};
    auto renderer = std::make_shared<std::unique_ptr<MeshRenderer>>();
    auto camera = std::make_shared<rendering::Camera>();
    const std::string name = "view_frame/vulkan";
    benchmark::RegisterBenchmark(name.c_str(), [&context, renderer, camera, kSize](benchmark::State& state) {
        if (!*renderer) {
            const Program program = loadExampleProgram("examples/scene.vox");
            VulkanExecutor executor(context, compileProgram(program, {}));
            const Mesh mesh = meshMarchingCubes(executor.run().grid, {});
            *camera = rendering::parseCamera("iso", rendering::meshBounds(mesh), float(kSize.width) / float(kSize.height));
            *renderer = std::make_unique<MeshRenderer>(context, kSize);
            (*renderer)->setScene(mesh, program.materials);
            (*renderer)->draw(*camera); // warm-up: first-use costs of the pipelines and targets
        }
        for (auto _ : state) {
            const auto start = std::chrono::steady_clock::now();
            benchmark::DoNotOptimize((*renderer)->draw(*camera).rgb.data());
            state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
    })->UseManualTime()->Unit(benchmark::kMillisecond);
    reporter.describe(name + "/manual_time", {"view_frame", int(kSize.height), "vulkan", context.device().name});
}

} // namespace voxc::bench
