#pragma once
// The parameter values of a sweep, `--range A:B:STEP`: A, A+STEP, ... up to and including B.
#include <cstddef>
#include <string_view>
#include <vector>

namespace voxc::explore {

constexpr size_t kMaxSweepValues = 200;

struct SweepRange {
    double first = 0.0;
    double last = 0.0;
    double step = 1.0;
    // Digits after the decimal point in the longest of the three numbers as written (-1 when one
    // used an exponent): values are rounded to this many decimals, so 0.1:0.3:0.1 gives 0.3, not
    // 0.30000000000000004.
    int decimals = -1;
};

// Parses "A:B:STEP". UserError when the text is malformed, STEP <= 0 or B < A.
SweepRange parseSweepRange(std::string_view text);

// first + i*step for i = 0, 1, ... while the value does not pass `last` (with a tolerance of
// 1e-9 steps, so a float step lands on B exactly). Each value is computed from i, never by
// accumulation, so there is no drift. UserError when there would be more than kMaxSweepValues.
std::vector<double> sweepValues(const SweepRange& range);

} // namespace voxc::explore
