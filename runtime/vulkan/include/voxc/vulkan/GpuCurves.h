#pragma once
// The curves solve's passes besides the multigrid (GpuMultigrid.h) as SolvePrograms on a Vulkan
// device: Perona-Malik sweeps, binomial smoothing, the noise displacement, and the material and
// surface fronts (one indirect dispatch per BFS layer over a compacted front list). Each is the
// host loop's schedule in its operation order (compiler/shaders/curves_*.glsl), so lavapipe gives
// the host's values bit for bit; the displacement, through warped_fbm's exp2, agrees within the
// builtin's tolerance (docs/curves.md, "What runs where").
#include "voxc/generators/curves/Solvers.h"
#include "voxc/vulkan/Context.h"

#include <functional>

namespace voxc {

// Every pass (the multigrid, Perona-Malik sweeps, smoothing, material and surface fronts, the
// displacement) on the context `device()` returns when the pass runs (opened then, if the caller
// likes), or the host's loop where it returns null. The context must outlive the result.
curves::Solvers vulkanCurvesSolvers(std::function<VulkanContext*()> device);

// The passes alone, for tests and benchmarks.
void vulkanPeronaMalikSweeps(VulkanContext& context, const curves::Constraints& constraints, curves::NormalField& normals,
                             float k, uint32_t sweeps);
curves::Field3 vulkanSmoothBinomial(VulkanContext& context, const curves::Field3& field, int32_t passes);
curves::MaterialField vulkanPropagateMaterial(VulkanContext& context, const curves::Constraints& constraints);
curves::SurfaceField vulkanPropagateSurface(VulkanContext& context, const curves::Constraints& constraints,
                                            const curves::Field3& nx, const curves::Field3& ny, const curves::Field3& nz,
                                            curves::PropagateRule rule);
std::vector<float> vulkanDisplacement(VulkanContext& context, const curves::Field3& amplitude,
                                      const curves::Field3& roughness, float frequency, uint32_t seed);

} // namespace voxc
