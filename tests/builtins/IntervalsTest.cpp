// Every interval rule is conservative: values sampled inside random argument boxes, evaluated by
// the interpreter's record, never leave the rule's interval, and an `exact` result is the
// evaluated float bit for bit.
#include "voxc/builtins/Functions.h"
#include "voxc/builtins/Intervals.h"

#include <gtest/gtest.h>

#include <bit>
#include <map>
#include <random>
#include <vector>

namespace voxc {
namespace {

using T = Type;
// One argument signature per function with a rule.
const std::map<std::string_view, std::vector<Type>> kSignatures = {
    {"add", {T::Float, T::Float}}, {"sub", {T::Vec3, T::Float}}, {"mul", {T::Vec2, T::Vec2}},
    {"div", {T::Float, T::Float}}, {"neg", {T::Vec3}}, {"min", {T::Float, T::Float}},
    {"max", {T::Float, T::Float}}, {"clamp", {T::Float, T::Float, T::Float}}, {"abs", {T::Float}},
    {"floor", {T::Float}}, {"vec2", {T::Float, T::Float}}, {"vec3", {T::Float, T::Float, T::Float}},
    {"dot", {T::Vec3, T::Vec3}}, {"length", {T::Vec3}}, {"lt", {T::Float, T::Float}},
    {"le", {T::Float, T::Float}}, {"gt", {T::Float, T::Float}}, {"ge", {T::Float, T::Float}},
    {"and", {T::Bool, T::Bool}}, {"or", {T::Bool, T::Bool}}, {"not", {T::Bool}},
    {"select", {T::Bool, T::Float, T::Float}}, {"sdf_sphere", {T::Vec3, T::Vec3, T::Float}},
    {"sdf_box", {T::Vec3, T::Vec3, T::Vec3}}, {"sdf_capsule", {T::Vec3, T::Vec3, T::Vec3, T::Float}},
    {"sdf_union", {T::Float, T::Float}}, {"sdf_intersect", {T::Float, T::Float}},
    {"sdf_subtract", {T::Float, T::Float}}, {"density", {T::Float, T::Float}},
    {"perlin3", {T::Vec3, T::Int}}, {"simplex3", {T::Vec3, T::Int}}, {"value3", {T::Vec3, T::Int}},
    {"fbm", {T::Vec3, T::Int, T::Float, T::Float, T::Int}},
};

int components(Type t) { return t == T::Vec3 ? 3 : t == T::Vec2 ? 2 : 1; }

struct Sampler {
    std::mt19937 rng{12345};
    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
    bool chance(double p) { return std::bernoulli_distribution(p)(rng); }

    // A random interval of `type`; points (exact) a third of the time.
    Interval interval(Type type, float scale) {
        Interval r{type, glm::dvec3(0.0), glm::dvec3(0.0), chance(0.33)};
        for (int c = 0; c < components(type); ++c) {
            if (type == T::Int) {
                r.lo.x = r.hi.x = double(int(uniform(1, 9)));
                r.exact = true;
            } else if (type == T::Bool) {
                r.lo.x = chance(0.5) ? 0 : 1;
                r.hi.x = r.exact ? r.lo.x : 1;
            } else {
                const float a = uniform(-scale, scale), b = r.exact ? a : a + uniform(0, scale / 4);
                r.lo[c] = a;
                r.hi[c] = b;
            }
        }
        return r;
    }
    Value value(const Interval& box) {
        switch (box.type) {
        case T::Int: return Value::makeInt(int32_t(box.lo.x));
        case T::Bool: return Value::makeBool(box.lo.x == box.hi.x ? box.lo.x == 1 : chance(0.5));
        default: {
            Value v{box.type, glm::vec3(0.0f), 0, false};
            for (int c = 0; c < components(box.type); ++c)
                v.v[c] = box.exact ? float(box.lo[c]) : uniform(float(box.lo[c]), float(box.hi[c]));
            return v;
        }
        }
    }
};

bool inside(const Interval& r, const Value& v) {
    if (r.type != v.type) return false;
    for (int c = 0; c < components(v.type); ++c) {
        const double x = v.type == T::Bool ? double(v.b) : v.type == T::Int ? double(v.i) : double(v.v[c]);
        if (std::isnan(x) || x < r.lo[c] || x > r.hi[c]) return false;
        if (r.exact && v.type != T::Bool && std::bit_cast<uint32_t>(float(r.lo[c])) != std::bit_cast<uint32_t>(float(x)))
            return false;
    }
    return true;
}

TEST(builtins_Intervals, EveryRuleIsConservativeUnderSampling) {
    Sampler sampler;
    int exactResults = 0;
    for (const FunctionInfo& info : functions()) {
        const RangeRule rule = rangeRule(info.name);
        if (!rule) continue;
        const auto signature = kSignatures.find(info.name);
        ASSERT_NE(signature, kSignatures.end()) << info.name << " has a rule but no test signature";
        for (float scale : {2.0f, 40.0f, 3000.0f}) {
            for (int trial = 0; trial < 300; ++trial) {
                std::vector<Interval> boxes;
                for (Type t : signature->second) boxes.push_back(sampler.interval(t, scale));
                const Interval result = rule(boxes);
                exactResults += result.exact;
                for (int sample = 0; sample < 20; ++sample) {
                    std::vector<Value> args;
                    for (const Interval& box : boxes) args.push_back(sampler.value(box));
                    const Value v = info.eval(args);
                    ASSERT_TRUE(inside(result, v)) << info.name << " trial " << trial << " scale " << scale;
                }
            }
        }
    }
    EXPECT_GT(exactResults, 0); // the exact paths ran
}

TEST(builtins_Intervals, DensityFarFromTheSurfaceIsExactlyAirOrRock) {
    const RangeRule density = rangeRule("density");
    ASSERT_NE(density, nullptr);
    const Interval far[] = {{T::Float, {3, 0, 0}, {9, 0, 0}, false}, Interval::point(T::Float, {1, 0, 0})};
    const Interval air = density(std::span<const Interval>(far));
    EXPECT_TRUE(air.exact);
    EXPECT_EQ(std::bit_cast<uint64_t>(air.lo.x), std::bit_cast<uint64_t>(0.0));
    const Interval deep[] = {{T::Float, {-9, 0, 0}, {-3, 0, 0}, false}, Interval::point(T::Float, {1, 0, 0})};
    EXPECT_TRUE(density(std::span<const Interval>(deep)).exact);
    EXPECT_EQ(density(std::span<const Interval>(deep)).lo.x, 1.0);
    const Interval near[] = {{T::Float, {-0.2, 0, 0}, {9, 0, 0}, false}, Interval::point(T::Float, {1, 0, 0})};
    EXPECT_FALSE(density(std::span<const Interval>(near)).exact);
}

} // namespace
} // namespace voxc
