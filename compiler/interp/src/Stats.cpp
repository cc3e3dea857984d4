#include "voxc/interp/Stats.h"

#include <fmt/format.h>

namespace voxc {

std::string formatFireStats(const Program& program, const FireStats& stats) {
    std::string out;
    for (size_t g = 0; g < program.grammars.size() && g < stats.firings.size(); ++g) {
        const std::vector<uint64_t>& perRule = stats.firings[g];
        if (perRule.empty()) continue; // the grammar did not run
        uint64_t total = 0;
        for (uint64_t n : perRule) total += n;
        const uint64_t anchors = g < stats.anchors.size() ? stats.anchors[g] : 0;
        out += fmt::format("grammar {}: {} anchors tested, {} firings\n", program.grammars[g].name, anchors, total);
        for (size_t r = 0; r < perRule.size(); ++r)
            out += fmt::format("  {} {}\n", program.grammars[g].rules[r].name, perRule[r]);
    }
    return out;
}

} // namespace voxc
