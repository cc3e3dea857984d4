// Every interval rule is conservative: for every function record and every overload its type
// rule accepts, values sampled inside random argument boxes, evaluated by the interpreter's
// record, never leave the rule's interval; a NaN result only where the rule gave up (-inf, inf);
// an `exact` result is the evaluated float bit for bit. Iterating the registry means a new
// record without a rule, or a wrong rule, fails here.
#include "voxc/builtins/Functions.h"
#include "voxc/builtins/Intervals.h"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace voxc {
namespace {

using T = Type;

// Records that intentionally have no rule, with the reason. Empty: every record has one.
const std::map<std::string_view, std::string_view> kWithoutRule = {};

int components(Type t) { return t == T::Vec3 ? 3 : t == T::Vec2 ? 2 : 1; }

// Every argument-type list of up to five arguments the record's type rule accepts.
std::vector<std::vector<Type>> overloads(const FunctionInfo& info) {
    const Type all[] = {T::Float, T::Int, T::Bool, T::Vec2, T::Vec3};
    std::vector<std::vector<Type>> found;
    for (size_t arity = 1; arity <= 5; ++arity) {
        std::vector<size_t> digits(arity, 0);
        for (;;) {
            std::vector<Type> args;
            for (size_t d : digits) args.push_back(all[d]);
            if (info.typeRule(args)) found.push_back(args);
            size_t i = 0;
            while (i < arity && ++digits[i] == 5) digits[i++] = 0;
            if (i == arity) break;
        }
    }
    return found;
}

struct Sampler {
    std::mt19937 rng{12345};
    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
    bool chance(double p) { return std::bernoulli_distribution(p)(rng); }

    // A random interval of `type`; points (exact) a third of the time, sometimes straddling 0.
    Interval interval(Type type, float scale) {
        Interval r{type, glm::dvec3(0.0), glm::dvec3(0.0), chance(0.33)};
        for (int c = 0; c < components(type); ++c) {
            if (type == T::Int) {
                r.lo.x = integer(-3, 20);
                r.hi.x = r.exact ? r.lo.x : r.lo.x + integer(0, 6);
            } else if (type == T::Bool) {
                r.lo.x = chance(0.5) ? 0 : 1;
                r.hi.x = r.exact ? r.lo.x : 1;
            } else {
                const float width = chance(0.5) ? scale / 4 : scale / 64;
                const float a = chance(0.1) ? -width / 2 : uniform(-scale, scale);
                r.lo[c] = a;
                r.hi[c] = r.exact ? a : a + uniform(0, width);
            }
        }
        return r;
    }
    float inside(double lo, double hi) {
        if (lo == hi) return float(lo);
        if (chance(0.1)) return float(chance(0.5) ? lo : hi); // the extremes are often at the ends
        return uniform(float(lo), float(hi));
    }
    Value value(const Interval& box) {
        switch (box.type) {
        case T::Int: return Value::makeInt(integer(int(box.lo.x), int(box.hi.x)));
        case T::Bool: return Value::makeBool(box.lo.x == box.hi.x ? box.lo.x == 1 : chance(0.5));
        default: {
            Value v{box.type, glm::vec3(0.0f), 0, false};
            for (int c = 0; c < components(box.type); ++c) v.v[c] = inside(box.lo[c], box.hi[c]);
            return v;
        }
        }
    }
};

// Empty when v lies in r; else what is wrong.
std::string outside(const Interval& r, const Value& v) {
    if (r.type != v.type) return "type differs";
    for (int c = 0; c < components(v.type); ++c) {
        const double x = v.type == T::Bool ? double(v.b) : v.type == T::Int ? double(v.i) : double(v.v[c]);
        const std::string where = "component " + std::to_string(c) + " value " + std::to_string(x) + " not in [" +
                                  std::to_string(r.lo[c]) + ", " + std::to_string(r.hi[c]) + "]";
        if (std::isnan(x)) {
            if (r.lo[c] != -INFINITY || r.hi[c] != INFINITY) return "NaN in a bounded interval, " + where;
            continue;
        }
        if (x < r.lo[c] || x > r.hi[c]) return where;
        if (r.exact && v.type != T::Bool && std::bit_cast<uint32_t>(float(r.lo[c])) != std::bit_cast<uint32_t>(float(x)))
            return "not the exact float, " + where;
    }
    return {};
}

std::string describe(std::span<const Interval> boxes) {
    std::string s;
    for (const Interval& b : boxes) {
        s += " [";
        for (int c = 0; c < components(b.type); ++c)
            s += (c ? "; " : "") + std::to_string(b.lo[c]) + ".." + std::to_string(b.hi[c]);
        s += b.exact ? "]!" : "]";
    }
    return s;
}

TEST(builtins_Intervals, EveryRecordHasARuleOrAListedReason) {
    for (const FunctionInfo& info : functions())
        EXPECT_NE(rangeRule(info.name) == nullptr, kWithoutRule.count(info.name) == 0)
            << info.name << ": give it a rule in Intervals.cpp (or list why not)";
}

TEST(builtins_Intervals, EveryRuleIsConservativeUnderSampling) {
    Sampler sampler;
    int exactResults = 0;
    for (const FunctionInfo& info : functions()) {
        const RangeRule rule = rangeRule(info.name);
        if (!rule) continue;
        const auto signatures = overloads(info);
        ASSERT_FALSE(signatures.empty()) << info.name;
        int bounded = 0; // trials with a finite result somewhere: the rule is not a dead "unknown"
        for (const std::vector<Type>& signature : signatures) {
            for (float scale : {2.0f, 40.0f, 3000.0f, 1e30f}) {
                const int trials = scale > 1e6f ? 40 : 150;
                for (int trial = 0; trial < trials; ++trial) {
                    std::vector<Interval> boxes;
                    for (Type t : signature) boxes.push_back(sampler.interval(t, scale));
                    const Interval result = rule(boxes);
                    exactResults += result.exact;
                    bounded += std::isfinite(result.lo.x) && std::isfinite(result.hi.x);
                    for (int sample = 0; sample < 20; ++sample) {
                        std::vector<Value> args;
                        for (const Interval& box : boxes) args.push_back(sampler.value(box));
                        const std::string error = outside(result, info.eval(args));
                        ASSERT_TRUE(error.empty()) << info.name << " scale " << scale << describe(boxes) << ": " << error;
                    }
                }
            }
        }
        EXPECT_GT(bounded, 0) << info.name << " never gives a bounded interval";
    }
    EXPECT_GT(exactResults, 0); // the exact paths ran
}

// Point arguments at the float's special values (docs/language.md, "Non-finite values"): where
// the record's result is NaN the rule must have given up, elsewhere the result lies inside (and
// is the exact float where the rule says so). NaN itself has no interval, so it is not drawn.
TEST(builtins_Intervals, EveryRuleHoldsAtInfinitiesAndTheFloatLimits) {
    const float specials[] = {INFINITY, -INFINITY, FLT_MAX, -FLT_MAX, 0.0f, -0.0f, 1.0f, -2.0f, 0.5f, 1e30f, -3e38f};
    Sampler sampler;
    for (const FunctionInfo& info : functions()) {
        const RangeRule rule = rangeRule(info.name);
        if (!rule) continue;
        for (const std::vector<Type>& signature : overloads(info)) {
            for (int trial = 0; trial < 300; ++trial) {
                std::vector<Interval> boxes;
                for (Type t : signature) {
                    Interval box = sampler.interval(t, 4.0f);
                    if (t == T::Float || t == T::Vec2 || t == T::Vec3) {
                        for (int c = 0; c < components(t); ++c)
                            box.lo[c] = box.hi[c] = specials[sampler.integer(0, int(std::size(specials)) - 1)];
                        box.exact = true;
                    }
                    boxes.push_back(box);
                }
                std::vector<Value> args;
                for (const Interval& box : boxes) args.push_back(sampler.value(box));
                const std::string error = outside(rule(boxes), info.eval(args));
                ASSERT_TRUE(error.empty()) << info.name << describe(boxes) << ": " << error;
            }
        }
    }
}

Interval f(double lo, double hi) { return {T::Float, {lo, 0, 0}, {hi, 0, 0}, false}; }
Interval exact(double v) { return Interval::point(T::Float, {v, 0, 0}); }
Interval apply(std::string_view name, std::initializer_list<Interval> args) {
    const RangeRule rule = rangeRule(name);
    EXPECT_NE(rule, nullptr) << name;
    return rule(std::span<const Interval>(args.begin(), args.size()));
}

TEST(builtins_Intervals, DensityFarFromTheSurfaceIsExactlyAirOrRock) {
    const Interval air = apply("density", {f(3, 9), exact(1)});
    EXPECT_TRUE(air.exact);
    EXPECT_EQ(std::bit_cast<uint64_t>(air.lo.x), std::bit_cast<uint64_t>(0.0));
    const Interval rock = apply("density", {f(-9, -3), exact(1)});
    EXPECT_TRUE(rock.exact);
    EXPECT_EQ(rock.lo.x, 1.0);
    EXPECT_FALSE(apply("density", {f(-0.2, 9), exact(1)}).exact);
}

TEST(builtins_Intervals, NoiseBoundsAreTheProvenOnes) {
    const Interval p{T::Vec3, glm::dvec3(-100), glm::dvec3(100), false};
    const Interval seed = Interval::point(T::Int, {7, 0, 0});
    EXPECT_LT(apply("perlin3", {p, seed}).hi.x, 1.501);
    EXPECT_GT(apply("perlin3", {p, seed}).lo.x, -1.501);
    EXPECT_LT(apply("value3", {p, seed}).hi.x, 1.001);
    EXPECT_LT(apply("worley_f1", {p, seed}).hi.x, 1.733);
    // fbm with gain 1/2 over 5 octaves: 1.5 * 1.9375.
    const Interval fbm = apply("fbm", {p, Interval::point(T::Int, {5, 0, 0}), exact(2), exact(0.5), seed});
    EXPECT_LT(fbm.hi.x, 1.5 * 1.9375 + 0.01);
    EXPECT_GT(fbm.hi.x, 1.5 * 1.9375);
    EXPECT_EQ(apply("turbulence", {p, Interval::point(T::Int, {5, 0, 0}), exact(2), exact(0.5), seed}).lo.x < 0, true);
    EXPECT_GT(apply("ridged", {p, Interval::point(T::Int, {5, 0, 0}), exact(2), exact(0.5), seed}).lo.x, -1e-3);
    // A non-finite position can make the noise NaN: no bound then.
    const Interval far{T::Vec3, glm::dvec3(-INFINITY), glm::dvec3(0), false};
    EXPECT_EQ(apply("perlin3", {far, seed}).hi.x, INFINITY);
}

TEST(builtins_Intervals, TrigonometryIsTightOnShortIntervals) {
    const Interval s = apply("sin", {f(0.1, 0.2)});
    EXPECT_NEAR(s.lo.x, std::sin(0.1), 1e-3);
    EXPECT_NEAR(s.hi.x, std::sin(0.2), 1e-3);
    EXPECT_GT(apply("cos", {f(-0.1, 0.1)}).hi.x, 1.0); // the crest at 0, widened by the tolerance
    EXPECT_LT(apply("cos", {f(-0.1, 0.1)}).lo.x, std::cos(0.1));
}

TEST(builtins_Intervals, SmoothstepAndMixAreExactWherePinned) {
    const Interval below = apply("smoothstep", {exact(0), exact(1), f(-9, -1)});
    EXPECT_TRUE(below.exact);
    EXPECT_EQ(below.lo.x, 0.0);
    const Interval above = apply("smoothstep", {exact(0), exact(1), f(2, 9)});
    EXPECT_TRUE(above.exact);
    EXPECT_EQ(above.lo.x, 1.0);
    EXPECT_TRUE(apply("mix", {exact(3), exact(5), above}).exact);
}

TEST(builtins_Intervals, SmoothCsgIsTheHardOpWithinAQuarterOfK) {
    const Interval hard = apply("sdf_smooth_union", {f(1, 2), f(3, 4), exact(0)});
    EXPECT_TRUE(hard.exact == false && hard.lo.x == 1 && hard.hi.x == 2);
    const Interval soft = apply("sdf_smooth_union", {f(1, 2), f(1.5, 4), exact(2)});
    EXPECT_LT(soft.lo.x, 0.5);
    EXPECT_GT(soft.lo.x, 0.49);
    EXPECT_LT(soft.hi.x, 2.01);
    const Interval apart = apply("sdf_smooth_intersect", {f(1, 2), f(10, 11), exact(2)});
    EXPECT_GT(apart.lo.x, 9.99);
    EXPECT_LT(apart.hi.x, 11.01);
}

} // namespace
} // namespace voxc
