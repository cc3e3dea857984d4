#include "voxc/core/Suggest.h"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <vector>

namespace voxc {

namespace {

char lower(char c) { return char(std::tolower(static_cast<unsigned char>(c))); }

// Edit distance ignoring case, where swapping two neighbouring letters counts as one edit
// (optimal string alignment), since "SOILD" for "SOLID" is the commonest typo of all.
size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

} // namespace

// Names longer than this get no suggestion: comparing two long names costs the product of
// their lengths, and a file may hold names of megabytes.
constexpr size_t kMaxSuggestedLength = 64;

std::string_view closestName(std::string_view name, std::span<const std::string_view> candidates) {
    if (name.size() > kMaxSuggestedLength) return {};
    size_t limit = std::max<size_t>(1, name.size() / 3);
    std::string_view best;
    size_t bestDistance = limit + 1;
    for (std::string_view candidate : candidates) {
        // The distance is at least the difference in length.
        const size_t lengthDifference = std::max(name.size(), candidate.size()) - std::min(name.size(), candidate.size());
        if (lengthDifference >= bestDistance) continue;
        size_t distance = editDistance(name, candidate);
        if (distance < bestDistance) {
            best = candidate;
            bestDistance = distance;
        }
    }
    if (best == name) return {};
    return best;
}

std::string didYouMean(std::string_view name, std::span<const std::string_view> candidates) {
    const std::string_view best = closestName(name, candidates);
    if (best.empty()) return {};
    return fmt::format("; did you mean '{}'?", best);
}

std::string suggestOrList(std::string_view name, std::span<const std::string_view> candidates) {
    std::string suggestion = didYouMean(name, candidates);
    if (!suggestion.empty() || candidates.empty()) return suggestion;
    return fmt::format(" (expected one of: {})", fmt::join(candidates, ", "));
}

} // namespace voxc
