#pragma once
// A set of densities as a sorted union of disjoint intervals (ValueInterval: open or closed ends; not
// the interval arithmetic of Intervals.h), used by the checker to prove
// that a symbol cell can never pass or that two rules' cells can pass together.
#include <limits>
#include <vector>

namespace voxc {

struct ValueInterval {
    float lo = -std::numeric_limits<float>::infinity();
    float hi = std::numeric_limits<float>::infinity();
    bool loClosed = false;
    bool hiClosed = false;
};

class ValueSet {
public:
    static ValueSet all();
    static ValueSet point(float v);
    static ValueSet below(float v, bool inclusive);
    static ValueSet above(float v, bool inclusive);
    static ValueSet allBut(float v);

    ValueSet intersect(const ValueSet& other) const;
    bool empty() const { return intervals_.empty(); }
    const std::vector<ValueInterval>& intervals() const { return intervals_; }

private:
    std::vector<ValueInterval> intervals_;
};

} // namespace voxc
