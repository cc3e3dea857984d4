#include "voxc/generators/curves/Scene.h"

#include "voxc/builtins/Functions.h"
#include "voxc/core/Errors.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

namespace voxc::curves {

namespace {

bool namesMaterial(const std::vector<FeatureCurve>& curves) {
    for (const FeatureCurve& curve : curves)
        for (const ConstraintPoint& point : curve.constraints)
            if (point.material != 0) return true;
    return false;
}

} // namespace

SolveTable solveScene(const Scene& scene, const Limits& limits, const LinearSolver& solver) {
    const Result solved = runCurves(scene.curves, scene.box, scene.options, limits, solver);
    const auto densityStart = std::chrono::steady_clock::now();
    // The builtin's own evaluation, so the displacement is the function a field would call.
    const FunctionInfo* warped = findFunction("warped_fbm");
    VOXC_ASSERT(warped != nullptr);
    const Box& box = scene.box;
    SolveTable table;
    table.min = box.min;
    table.size = box.size;
    table.density.resize(box.cellCount());
    const bool materials = namesMaterial(scene.curves);
    if (materials) table.material.resize(box.cellCount());
    for (int32_t z = 0; z < box.size.z; ++z)
        for (int32_t y = 0; y < box.size.y; ++y)
            for (int32_t x = 0; x < box.size.x; ++x) {
                const size_t i = box.index(x, y, z);
                const float s = solved.smoothed.values[i];
                const float alpha = solved.amplitude.values[i];
                float displacement = 0.0f;
                if (alpha != 0.0f) {
                    const glm::vec3 p = glm::vec3(box.min + glm::ivec3(x, y, z)) * scene.noiseFrequency;
                    const std::array<Value, 5> args{Value::makeVec3(p), Value::makeFloat(solved.roughness.values[i]),
                                                    Value::makeFloat(0.0f), Value::makeFloat(0.0f),
                                                    Value::makeInt(int32_t(scene.noiseSeed))};
                    displacement = alpha * warped->eval(args).v.x;
                }
                const float d = s - displacement;
                // +infinity: no seed reaches the cell, so it is air.
                const float density = d < INFINITY ? std::clamp(0.5f - d / 2.0f, 0.0f, 1.0f) : 0.0f;
                table.density[i] = density;
                if (materials && density >= 0.5f) table.material[i] = uint8_t(solved.material.material[i]);
            }
    table.phaseMs = solved.phaseMs;
    table.phaseMs.emplace_back(
        "density", std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - densityStart).count());
    for (const SolveReport& report : solved.solves)
        table.solves.push_back({report.name, report.levels, report.residuals});
    return table;
}

} // namespace voxc::curves
