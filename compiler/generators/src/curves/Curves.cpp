#include "voxc/generators/curves/Curves.h"

#include "Fronts.h"
#include "Parallel.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <optional>
#include <thread>

namespace voxc::curves {

namespace {

// Runs `part` and appends its wall time to `phases` under `name`; first throws Stopped when `stop` is requested.
template <typename Part>
void timed(std::vector<std::pair<std::string, double>>& phases, const char* name, Part&& part,
           const std::stop_token& stop = {}) {
    throwIfStopped(stop);
    const auto start = std::chrono::steady_clock::now();
    part();
    phases.emplace_back(name, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
}

// The linear solves stop at a max residual of 1e-4 (the parameters': 1e-4 * max(1, max alpha0)),
// not the spec's 1e-5: measured on the bench's cliff scene, the table's densities move by at
// most 5.4e-4 at 128x64x128 and 4.9e-3 at 256x128x256 (the surface by under 0.01 voxel; 0 and
// 4 of the cells change side, each within 0.01 voxel of the surface), while two V-cycles of
// eight are saved (docs/curves.md).
constexpr float kSolveTolerance = 1e-4f;

// solveCurves on `cs`; `owned` is cs itself where the caller gave it up (its N0, alpha0 and beta0
// are moved into the unknowns), else null (they are copied).
Result solve(const Constraints& cs, Constraints* owned, const Options& options, const Limits& limits,
             const Solvers& solvers) {
    const LinearSolver& linear =
        solvers.linear ? solvers.linear
                       : LinearSolver([&](const std::string& name, const std::vector<uint8_t>& fixed,
                                          std::vector<Field3*> components, float tolerance, const Limits& l) {
                             return solveLaplaceUntilStopped(name, fixed, std::move(components), tolerance, l, solvers.stop);
                         });
    checkBox(cs.box, limits);
    if (!(std::isfinite(options.k) && options.k > 0.0f)) throw ParameterError("k", options.k, "must be finite and > 0");
    if (options.smoothPasses < 0 || options.smoothPasses > limits.maxSmoothPasses)
        throw ParameterError("smooth_passes", options.smoothPasses, "must lie in [0, " + std::to_string(limits.maxSmoothPasses) + "]");
    const Box& b = cs.box;
    // Every field is allocated where it is first needed and fields are normalised in place: the
    // solve's fresh memory (its peak heap) is most of its page faults (HeapReuse.h).
    Result r;

    // A solve's Dirichlet mask (pointwise: two threads, a slab of slices each).
    auto maskOf = [&](uint8_t flag) {
        std::vector<uint8_t> fixed(b.cellCount());
        const size_t slice = size_t(b.size.x) * size_t(b.size.y);
        forTwoSlabs(b.size.z, 2, [&](int32_t z0, int32_t z1) {
            for (size_t i = size_t(z0) * slice; i < size_t(z1) * slice; ++i) fixed[i] = (cs.flags[i] & flag) ? 1 : 0;
        });
        return fixed;
    };
    if (options.normals == NormalMode::Laplace) {
        timed(r.phaseMs, "normals", [&] {
            Field3 x = owned ? std::move(owned->normalX) : cs.normalX;
            Field3 y = owned ? std::move(owned->normalY) : cs.normalY;
            Field3 z = owned ? std::move(owned->normalZ) : cs.normalZ;
            r.solves.push_back(linear("normals", maskOf(kInNormals), {&x, &y, &z}, kSolveTolerance, limits));
            normalizeField(x, y, z, x, y, z);
            r.normalX = std::move(x), r.normalY = std::move(y), r.normalZ = std::move(z);
        }, solvers.stop);
    } else {
        const uint32_t sweeps = options.sweeps != 0 ? options.sweeps : uint32_t(std::max({b.size.x, b.size.y, b.size.z}));
        if (sweeps > limits.maxSweeps) throw LimitError("Perona-Malik sweeps", sweeps, limits.maxSweeps);
        if (uint64_t(sweeps) * b.cellCount() > limits.maxSweepCellUpdates)
            throw LimitError("Perona-Malik sweep cell updates", uint64_t(sweeps) * b.cellCount(), limits.maxSweepCellUpdates);
        timed(r.phaseMs, "normals", [&] {
            NormalField n = peronaMalikFill(cs);
            if (solvers.peronaMalik) solvers.peronaMalik(cs, n, options.k, sweeps);
            else peronaMalikSweeps(cs, n, options.k, sweeps);
            normalizeField(n.x, n.y, n.z, n.x, n.y, n.z);
            r.normalX = std::move(n.x), r.normalY = std::move(n.y), r.normalZ = std::move(n.z);
        }, solvers.stop);
    }
    if (!solvers.material && !solvers.surface) {
        // The host's fronts are independent and single-threaded (growLayers): one per core,
        // their fields allocated here (Fronts.h).
        timed(r.phaseMs, "fronts", [&] {
            MaterialFront material = prepareMaterial(cs, owned ? &owned->material : nullptr);
            SurfaceFront surface = prepareSurface(cs, owned ? &owned->surface : nullptr);
            bothOf([&] { growMaterial(cs, material); },
                   [&] { growSurface(cs, r.normalX, r.normalY, r.normalZ, options.propagate, surface); });
            r.material = std::move(material.field);
            r.surface = std::move(surface.field);
        }, solvers.stop);
    } else {
        timed(r.phaseMs, "material", [&] { r.material = (solvers.material ? solvers.material : propagateMaterial)(cs); }, solvers.stop);
        timed(r.phaseMs, "surface", [&] {
            r.surface = (solvers.surface ? solvers.surface : SurfacePropagator(propagateSurface))(
                cs, r.normalX, r.normalY, r.normalZ, options.propagate);
        }, solvers.stop);
    }
    // The parameters after the fronts, which do not read them: the fronts' scratch is free again
    // by then and holds the parameters' fields and solve, so the solve's peak heap (the fronts
    // beside the normals) is two fields smaller.
    timed(r.phaseMs, "parameters", [&] {
        const std::vector<uint8_t> fixed = maskOf(kInParams);
        // A max does not depend on the order: two threads give the same value.
        float slabMax[2] = {1.0f, 1.0f};
        const size_t slice = size_t(b.size.x) * size_t(b.size.y);
        forTwoSlabs(b.size.z, 2, [&](int32_t z0, int32_t z1) {
            float& m = slabMax[z0 == 0 ? 0 : 1];
            for (size_t i = size_t(z0) * slice; i < size_t(z1) * slice; ++i)
                if (fixed[i]) m = std::max(m, cs.amplitude.values[i]);
        });
        const float maxAmplitude = std::max(slabMax[0], slabMax[1]);
        r.amplitude = owned ? std::move(owned->amplitude) : cs.amplitude;
        r.roughness = owned ? std::move(owned->roughness) : cs.roughness;
        r.solves.push_back(linear("parameters", fixed, {&r.amplitude, &r.roughness}, kSolveTolerance * maxAmplitude, limits));
    }, solvers.stop);
    timed(r.phaseMs, "smoothing", [&] {
        r.smoothed = (solvers.smoothing ? solvers.smoothing : Smoother(smoothBinomial))(r.surface.distance, options.smoothPasses);
    }, solvers.stop);
    return r;
}

} // namespace

Result solveCurves(const Constraints& constraints, const Options& options, const Limits& limits, const Solvers& solvers) {
    return solve(constraints, nullptr, options, limits, solvers);
}

Result solveCurves(Constraints&& constraints, const Options& options, const Limits& limits, const Solvers& solvers) {
    return solve(constraints, &constraints, options, limits, solvers);
}

Result runCurves(const std::vector<FeatureCurve>& curves, const Box& box, const Options& options, const Limits& limits,
                 const Solvers& solvers) {
    std::vector<std::pair<std::string, double>> phases;
    std::optional<Constraints> constraints;
    timed(phases, "voxelize", [&] { constraints.emplace(voxelize(curves, box, options.seedValue, limits)); });
    Result r = solveCurves(std::move(*constraints), options, limits, solvers);
    r.phaseMs.insert(r.phaseMs.begin(), phases.front());
    return r;
}

} // namespace voxc::curves
