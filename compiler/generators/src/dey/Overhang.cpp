// Overhang / cliff (Dey Eq 4.1): inside the box [min, max), rock where the normalised depth I_x
// is below min(S(u, v), P(u)), S a bicubic Bézier patch and P a parabola across the face.
// docs/language.md ("Features") gives the control net.
#include "Placement.h"
#include "Records.h"

#include <array>

namespace voxc::dey {

namespace {

using K = GeneratorKeyType;

// Table 4.1 (ranges, steps) and Table 4.4 (defaults); the box has no thesis default.
constexpr GeneratorKey kKeys[] = {
    {"lip_height", K::Number, 0, 1, 0.01, {0, 0, 0}},
    {"base_depth", K::Number, 0, 1, 0.01, {0, 0, 0}},
    {"top_erosion", K::Number, 0, 1, 0.01, {0, 0, 0}},
    {"bottom_erosion", K::Number, 0, 1, 0.01, {0, 0, 0}},
    {"parabola_offset", K::Number, 0, 1, 0.01, {0, 0, 0}},
    {"parabola_exponent", K::Number, 1, 4, 0.02, {1, 0, 0}},
    {"min", K::Vec3, -1e6, 1e6, 0, {}, true},
    {"max", K::Vec3, -1e6, 1e6, 0, {}, true},
    kTranslateKey,
    kRotateKey,
};

std::optional<GeneratorProblem> validate(const GeneratorParams& params) {
    const glm::dvec3 lo = params.vec("min"), hi = params.vec("max");
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
        return GeneratorProblem{"max", "an overhang's 'max' must exceed its 'min' on every axis"};
    return std::nullopt;
}

// G[i][j]: the face depth (a fraction of the box's x extent) of control point i along u (z) and
// j along v (down from the top). Columns are the vertical profile; the two inner rows (the
// middle of the face) are eroded by the erosion parameters.
using ControlNet = std::array<std::array<double, 4>, 4>;

ControlNet controlNet(const GeneratorParams& params) {
    const double lip = params.number("lip_height"), base = params.number("base_depth");
    const std::array<double, 4> profile{1.0, 0.5 + 0.5 * lip, 0.5 * (1.0 - base), 1.0 - base};
    ControlNet net{};
    for (int i = 0; i < 4; ++i) {
        net[i] = profile;
        if (i == 1 || i == 2) {
            net[i][1] *= 1.0 - params.number("top_erosion");
            net[i][2] *= 1.0 - params.number("bottom_erosion");
        }
    }
    return net;
}

// The four cubic Bernstein polynomials of t (the rows of U·B).
std::array<uint32_t, 4> bernstein(FieldBuilder& b, uint32_t t) {
    const uint32_t s = b.call("sub", {b.number(1.0), t});
    const uint32_t three = b.number(3.0);
    return {b.call("mul", {b.call("mul", {s, s}), s}), b.call("mul", {b.call("mul", {three, t}), b.call("mul", {s, s})}),
            b.call("mul", {b.call("mul", {three, b.call("mul", {t, t})}), s}),
            b.call("mul", {b.call("mul", {t, t}), t})};
}

Field build(const GeneratorParams& params, uint32_t /*seed*/) {
    const glm::dvec3 lo = params.vec("min"), hi = params.vec("max");
    const glm::dvec3 extent = hi - lo;
    FieldBuilder b;
    const uint32_t q = Placement::of(params, 0.5 * (lo + hi)).inverseOfPosition(b);
    uint32_t normalised[3];
    for (uint32_t axis = 0; axis < 3; ++axis)
        normalised[axis] = b.call("mul", {b.call("sub", {b.component(q, axis), b.number(lo[axis])}),
                                          b.number(1.0 / extent[axis])});
    const uint32_t u = b.call("clamp", {normalised[2], b.number(0.0), b.number(1.0)});
    const uint32_t v = b.call("clamp", {b.call("sub", {b.number(1.0), normalised[1]}), b.number(0.0), b.number(1.0)});

    // S(u, v) = U·B·G·Bᵀ·Vᵀ = sum_i Bu_i (sum_j G_ij Bv_j).
    const ControlNet net = controlNet(params);
    const std::array<uint32_t, 4> bu = bernstein(b, u), bv = bernstein(b, v);
    uint32_t surface = 0;
    for (int i = 0; i < 4; ++i) {
        uint32_t row = b.call("mul", {bv[0], b.number(net[i][0])});
        for (int j = 1; j < 4; ++j) row = b.call("add", {row, b.call("mul", {bv[j], b.number(net[i][j])})});
        const uint32_t term = b.call("mul", {bu[i], row});
        surface = i == 0 ? term : b.call("add", {surface, term});
    }

    // P(u) = offset + (1 - offset) (4u(1 - u))^k; k = 1 needs no pow (and stays bit-exact on GPUs).
    const double offset = params.number("parabola_offset"), exponent = params.number("parabola_exponent");
    uint32_t parabola = b.call("mul", {b.call("mul", {b.number(4.0), u}), b.call("sub", {b.number(1.0), u})});
    if (exponent != 1.0) parabola = b.call("pow", {parabola, b.number(exponent)});
    parabola = b.call("add", {b.number(offset), b.call("mul", {b.number(1.0 - offset), parabola})});

    // Signed depth in voxels (negative in rock), cut to the box's voxels min..max-1.
    const uint32_t depth = b.call("mul", {b.call("sub", {normalised[0], b.call("min", {surface, parabola})}),
                                          b.number(extent.x)});
    const uint32_t box = b.call("sdf_box", {q, b.vec3(0.5 * (lo + hi) - 0.5), b.vec3(0.5 * extent)});
    return b.field(b.call("density", {b.call("max", {depth, box}), b.number(1.0)}));
}

} // namespace

const GeneratorInfo& overhangGenerator() {
    static const GeneratorInfo info{"overhang", kKeys, validate, build};
    return info;
}

} // namespace voxc::dey
