#include "voxc/explore/Sweep.h"

#include "voxc/core/Errors.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <string>

namespace voxc::explore {

namespace {

struct ParsedNumber {
    double value = 0.0;
    int decimals = 0; // -1: written with an exponent
};

ParsedNumber parseNumber(std::string_view text, std::string_view whole, const char* part) {
    ParsedNumber number;
    const char* end = text.data() + text.size();
    auto [ptr, error] = std::from_chars(text.data(), end, number.value);
    if (text.empty() || error != std::errc() || ptr != end || !std::isfinite(number.value))
        throw UserError(fmt::format("--range '{}': {} '{}' is not a number (expected A:B:STEP, e.g. 0.2:0.8:0.1)",
                                    whole, part, text));
    if (text.find_first_of("eE") != std::string_view::npos)
        number.decimals = -1;
    else if (size_t dot = text.find('.'); dot != std::string_view::npos)
        number.decimals = int(text.size() - dot - 1);
    return number;
}

} // namespace

SweepRange parseSweepRange(std::string_view text) {
    const size_t colon1 = text.find(':');
    const size_t colon2 = colon1 == std::string_view::npos ? colon1 : text.find(':', colon1 + 1);
    if (colon2 == std::string_view::npos || text.find(':', colon2 + 1) != std::string_view::npos)
        throw UserError(fmt::format("--range '{}': expected A:B:STEP, e.g. 0.2:0.8:0.1", text));
    const ParsedNumber first = parseNumber(text.substr(0, colon1), text, "A");
    const ParsedNumber last = parseNumber(text.substr(colon1 + 1, colon2 - colon1 - 1), text, "B");
    const ParsedNumber step = parseNumber(text.substr(colon2 + 1), text, "STEP");
    if (!(step.value > 0.0)) throw UserError(fmt::format("--range '{}': STEP must be greater than 0", text));
    if (last.value < first.value) throw UserError(fmt::format("--range '{}': B must not be less than A", text));
    SweepRange range{first.value, last.value, step.value, -1};
    if (first.decimals >= 0 && last.decimals >= 0 && step.decimals >= 0)
        range.decimals = std::max({first.decimals, last.decimals, step.decimals});
    return range;
}

std::vector<double> sweepValues(const SweepRange& range) {
    if (!(range.step > 0.0) || range.last < range.first)
        throw UserError("the sweep needs STEP > 0 and B >= A");
    const double steps = std::floor((range.last - range.first) / range.step + 1e-9);
    if (steps + 1.0 > double(kMaxSweepValues))
        throw UserError(fmt::format("--range {}:{}:{} has {} values; at most {} are allowed (use a larger STEP)",
                                    range.first, range.last, range.step, steps + 1.0, kMaxSweepValues));
    // Rounding to the decimals written only removes binary noise; more than 15 would add some.
    const bool round = range.decimals >= 0 && range.decimals <= 15;
    const double scale = round ? std::pow(10.0, range.decimals) : 1.0;
    std::vector<double> values;
    for (size_t i = 0; i <= size_t(steps); ++i) {
        double value = range.first + double(i) * range.step;
        if (round) value = std::round(value * scale) / scale;
        values.push_back(value);
    }
    return values;
}

} // namespace voxc::explore
