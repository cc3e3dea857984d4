#include "voxc/explore/Report.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::explore {

namespace {

// CSV fields are plain numbers and the parameter, which is an identifier: nothing to quote.
std::string optionalNumber(const std::optional<MeanDeviation>& value, double MeanDeviation::*member) {
    return value ? fmt::format("{}", (*value).*member) : std::string();
}

struct Effect {
    double minMean = 0.0, maxMean = 0.0, typicalStddev = 0.0;
};

template <typename Get>
Effect effectOf(const ExploreResult& result, Get get) {
    Effect effect;
    bool first = true;
    double stddevSum = 0.0;
    size_t count = 0;
    for (const ValueSummary& summary : result.values) {
        const std::optional<MeanDeviation> md = get(summary);
        if (!md) continue;
        effect.minMean = first ? md->mean : std::min(effect.minMean, md->mean);
        effect.maxMean = first ? md->mean : std::max(effect.maxMean, md->mean);
        first = false;
        stddevSum += md->stddev;
        ++count;
    }
    if (count > 0) effect.typicalStddev = stddevSum / double(count);
    return effect;
}

} // namespace

std::string formatRunsCsv(const ExploreResult& result) {
    std::string csv = "parameter,value,run,seed,solid_fraction,surface_area\n";
    for (const ValueSummary& summary : result.values)
        for (const RunRecord& run : summary.runs)
            csv += fmt::format("{},{},{},{},{},{}\n", result.parameter, summary.value, run.run, run.seed,
                               run.descriptors.solidFraction, run.descriptors.surfaceArea);
    return csv;
}

std::string formatSummaryCsv(const ExploreResult& result) {
    std::string csv = "parameter,value,runs,solid_fraction_mean,solid_fraction_stddev,surface_area_mean,"
                      "surface_area_stddev,iou_mean,iou_stddev\n";
    for (const ValueSummary& s : result.values)
        csv += fmt::format("{},{},{},{},{},{},{},{},{}\n", result.parameter, s.value, s.runs.size(),
                           s.solidFraction.mean, s.solidFraction.stddev, s.surfaceArea.mean, s.surfaceArea.stddev,
                           optionalNumber(s.iou, &MeanDeviation::mean), optionalNumber(s.iou, &MeanDeviation::stddev));
    return csv;
}

std::string formatSummaryTable(const ExploreResult& result) {
    std::string table = fmt::format("{:>12}  {:>22}  {:>24}  {:>22}\n", result.parameter, "solid fraction (+/- sd)",
                                    "surface area (+/- sd)", "pairwise IoU (+/- sd)");
    for (const ValueSummary& s : result.values) {
        const std::string iou = s.iou ? fmt::format("{:.4f} +/- {:.4f}", s.iou->mean, s.iou->stddev) : "-";
        table += fmt::format("{:>12}  {:>22}  {:>24}  {:>22}\n", fmt::format("{}", s.value),
                             fmt::format("{:.4f} +/- {:.4f}", s.solidFraction.mean, s.solidFraction.stddev),
                             fmt::format("{:.1f} +/- {:.1f}", s.surfaceArea.mean, s.surfaceArea.stddev), iou);
    }
    auto line = [&](const char* name, const Effect& e, int precision) {
        table += fmt::format("{}: the mean ranges over {:.{}f}..{:.{}f} across the sweep; seeds vary it by "
                             "{:.{}f} (mean stddev)\n",
                             name, e.minMean, precision, e.maxMean, precision, e.typicalStddev, precision);
    };
    line("solid fraction", effectOf(result, [](const ValueSummary& s) { return std::optional(s.solidFraction); }), 4);
    line("surface area", effectOf(result, [](const ValueSummary& s) { return std::optional(s.surfaceArea); }), 1);
    if (!result.values.empty() && result.values.front().iou)
        line("pairwise IoU", effectOf(result, [](const ValueSummary& s) { return s.iou; }), 4);
    return table;
}

} // namespace voxc::explore
