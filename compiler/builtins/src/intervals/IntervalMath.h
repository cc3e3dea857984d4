#pragma once
// The arithmetic the interval rules share (Intervals.cpp, NoiseIntervals.cpp, SdfIntervals.cpp):
// outward rounding, component access, the four operations, min/max and dot/length.
#include "voxc/builtins/Intervals.h"

#include <initializer_list>
#include <limits>
#include <span>
#include <utility>

namespace voxc::intervals {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
// One float rounding is at most 2^-24 relative; 1e-6 also covers the double arithmetic of the
// bounds. kTiny covers results that round to or from subnormals.
inline constexpr double kRelative = 1e-6, kTiny = 1e-36;
inline constexpr double kFloatMax = std::numeric_limits<float>::max();
// The records' GPU tolerances (compiler/builtins/src/functions), added to rules of functions
// that are not bit-exact on the GPU.
inline constexpr double kSqrtTolerance = 4e-5, kPowTolerance = 2e-3, kTrigTolerance = 4.8828125e-4,
                 kPlaneTolerance = 1e-4, kSmoothTolerance = 5e-5;

int components(Type t);
bool isFloatLike(Type t);
// Outward by one rounding; past the float range the float result may be infinite.
double down(double x);
double up(double x);
double downBy(double x, int steps);
double upBy(double x, int steps);
// Component c of an operand, a float broadcast to every component.
double lo(const Interval& a, int c);
double hi(const Interval& a, int c);
Interval floatInterval(double l, double h);
bool finite(const Interval& a);
double maxAbs(const Interval& a);
// Outward by `absolute` plus `relative` of each bound's magnitude (never exact).
Interval widened(Interval r, double absolute, double relative);
Interval boolInterval(bool canBeFalse, bool canBeTrue);
std::pair<double, double> hullOf(std::initializer_list<double> values);

Interval add(std::span<const Interval> a);
Interval sub(std::span<const Interval> a);
Interval mul(std::span<const Interval> a);
Interval div(std::span<const Interval> a);
Interval neg(std::span<const Interval> a); // exact
// GLSL min/max of two floats (exact when the operands are strictly ordered).
Interval pick(const Interval& a, const Interval& b, bool maximum);
Interval minRule(std::span<const Interval> a);
Interval maxRule(std::span<const Interval> a);
Interval clampRule(std::span<const Interval> a);
// Bounds of x * y summed over components (exact reals), for dot and length.
std::pair<double, double> dotBounds(const Interval& a, const Interval& b);
double squaredGap(double l, double h);
Interval dotRule(std::span<const Interval> a);
Interval lengthRule(std::span<const Interval> a);

// A table of rules by FunctionInfo::name, merged by rangeRule.
struct NamedRule {
    std::string_view function;
    RangeRule rule;
};
std::span<const NamedRule> noiseRules();
std::span<const NamedRule> sdfRules();

} // namespace voxc::intervals
