#include "voxc/builtins/ValueSet.h"

#include <algorithm>

namespace voxc {

ValueSet ValueSet::all() {
    ValueSet s;
    s.intervals_.push_back(ValueInterval{});
    return s;
}

ValueSet ValueSet::point(float v) {
    ValueSet s;
    s.intervals_.push_back(ValueInterval{v, v, true, true});
    return s;
}

ValueSet ValueSet::below(float v, bool inclusive) {
    ValueSet s;
    ValueInterval i;
    i.hi = v;
    i.hiClosed = inclusive;
    s.intervals_.push_back(i);
    return s;
}

ValueSet ValueSet::above(float v, bool inclusive) {
    ValueSet s;
    ValueInterval i;
    i.lo = v;
    i.loClosed = inclusive;
    s.intervals_.push_back(i);
    return s;
}

ValueSet ValueSet::allBut(float v) {
    ValueSet s = below(v, false);
    s.intervals_.push_back(above(v, false).intervals_.front());
    return s;
}

namespace {

// The intersection of two intervals; `ok` is false when it is empty.
ValueInterval intersectOne(const ValueInterval& a, const ValueInterval& b, bool& ok) {
    ValueInterval r;
    if (a.lo > b.lo || (a.lo == b.lo && !a.loClosed)) {
        r.lo = a.lo;
        r.loClosed = a.loClosed;
    } else {
        r.lo = b.lo;
        r.loClosed = b.loClosed;
    }
    if (a.hi < b.hi || (a.hi == b.hi && !a.hiClosed)) {
        r.hi = a.hi;
        r.hiClosed = a.hiClosed;
    } else {
        r.hi = b.hi;
        r.hiClosed = b.hiClosed;
    }
    ok = r.lo < r.hi || (r.lo == r.hi && r.loClosed && r.hiClosed);
    return r;
}

} // namespace

ValueSet ValueSet::intersect(const ValueSet& other) const {
    ValueSet result;
    for (const ValueInterval& a : intervals_) {
        for (const ValueInterval& b : other.intervals_) {
            bool ok = false;
            ValueInterval r = intersectOne(a, b, ok);
            if (ok) result.intervals_.push_back(r);
        }
    }
    std::sort(result.intervals_.begin(), result.intervals_.end(),
              [](const ValueInterval& a, const ValueInterval& b) { return a.lo < b.lo; });
    return result;
}

} // namespace voxc
