// Arch (Dey Eq 4.2): a sphere swept along a cubic Bézier from `start` to `end`, thickened toward
// each end by the taper term T_i = r * M_i * (1 - I_i^E_i). docs/language.md ("Features").
#include "Placement.h"
#include "Records.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace voxc::dey {

namespace {

using K = GeneratorKeyType;

// Table 4.2 (ranges, steps) and Table 4.5 (defaults). The shared per-end keys set both ends;
// `start_*` / `end_*` override one end.
constexpr GeneratorKey kKeys[] = {
    {"start", K::Vec3, -1e6, 1e6, 0, {16, 16, 16}},
    {"end", K::Vec3, -1e6, 1e6, 0, {48, 48, 16}},
    {"iterations", K::Integer, 10, 50, 10, {50, 0, 0}},
    {"radius", K::Number, 1, 10, 1, {5, 0, 0}},
    {"offset", K::Number, 0, 1, 0.01, {0.5, 0, 0}},
    {"peak", K::Number, 0, 10, 5, {10, 0, 0}},
    {"taper_interpolant", K::Number, 0, 1, 0.01, {0, 0, 0}},
    {"taper_radius", K::Number, 0, 1, 0.01, {1, 0, 0}},
    {"taper_exponent", K::Number, 1, 4, 0.02, {1, 0, 0}},
    {"start_offset", K::Number, 0, 1, 0.01, {}, false, true},
    {"start_peak", K::Number, 0, 10, 5, {}, false, true},
    {"start_taper_interpolant", K::Number, 0, 1, 0.01, {}, false, true},
    {"start_taper_radius", K::Number, 0, 1, 0.01, {}, false, true},
    {"start_taper_exponent", K::Number, 1, 4, 0.02, {}, false, true},
    {"end_offset", K::Number, 0, 1, 0.01, {}, false, true},
    {"end_peak", K::Number, 0, 10, 5, {}, false, true},
    {"end_taper_interpolant", K::Number, 0, 1, 0.01, {}, false, true},
    {"end_taper_radius", K::Number, 0, 1, 0.01, {}, false, true},
    {"end_taper_exponent", K::Number, 1, 4, 0.02, {}, false, true},
    kTranslateKey,
    kRotateKey,
};

// One end's parameters: the `start_`/`end_` key when written, else the shared one.
struct End {
    double offset, peak, interpolant, multiplier, exponent;
};

End endParams(const GeneratorParams& params, std::string_view prefix) {
    auto get = [&](std::string_view key) {
        const std::string specific = fmt::format("{}_{}", prefix, key);
        return params.has(specific) ? params.number(specific) : params.number(key);
    };
    return {get("offset"), get("peak"), get("taper_interpolant"), get("taper_radius"), get("taper_exponent")};
}

std::optional<GeneratorProblem> validate(const GeneratorParams& params) {
    if (params.vec("start") == params.vec("end"))
        return GeneratorProblem{"end", "an arch's 'end' must differ from its 'start'"};
    return std::nullopt;
}

// T = r * M * (1 - I^E): I rises linearly from the taper interpolant at this end to 1 at the
// middle of the curve (s is the curve parameter measured from this end).
double taper(double radius, const End& end, double s) {
    const double interpolant = std::clamp(end.interpolant + (1.0 - end.interpolant) * 2.0 * s, 0.0, 1.0);
    return radius * end.multiplier * (1.0 - std::pow(interpolant, end.exponent));
}

Field build(const GeneratorParams& params, uint32_t /*seed*/) {
    const glm::dvec3 start = params.vec("start"), end = params.vec("end");
    const End first = endParams(params, "start"), last = endParams(params, "end");
    const glm::dvec3 span = end - start;
    const glm::dvec3 c1 = start + first.offset * span + glm::dvec3(0, first.peak, 0);
    const glm::dvec3 c2 = end - last.offset * span + glm::dvec3(0, last.peak, 0);
    const int steps = int(params.number("iterations"));
    const double radius = params.number("radius");
    const Placement placement = Placement::of(params, 0.5 * (start + end));

    std::vector<glm::dvec3> points;
    std::vector<double> radii;
    for (int k = 0; k <= steps; ++k) {
        const double t = double(k) / steps, s = 1.0 - t;
        const glm::dvec3 point = s * s * s * start + 3.0 * s * s * t * c1 + 3.0 * s * t * t * c2 + t * t * t * end;
        points.push_back(placement.apply(point));
        radii.push_back(radius + taper(radius, first, t) + taper(radius, last, s));
    }
    FieldBuilder builder;
    return builder.field(builder.call("density", {sweptSpheres(builder, points, radii), builder.number(1.0)}));
}

} // namespace

const GeneratorInfo& archGenerator() {
    static const GeneratorInfo info{"arch", kKeys, validate, build};
    return info;
}

} // namespace voxc::dey
