#pragma once
// Text forms of an exploration: the two CSV files and the table printed to the terminal.
#include "voxc/explore/Explore.h"

#include <string>

namespace voxc::explore {

// One row per (value, run):
//   parameter,value,run,seed,solid_fraction,surface_area
std::string formatRunsCsv(const ExploreResult& result);

// One row per value (iou_* empty with a single run):
//   parameter,value,runs,solid_fraction_mean,solid_fraction_stddev,surface_area_mean,
//   surface_area_stddev,iou_mean,iou_stddev
std::string formatSummaryCsv(const ExploreResult& result);

// An aligned table of the summary, then for each descriptor how much its mean moves across the
// sweep compared with its spread over seeds.
std::string formatSummaryTable(const ExploreResult& result);

} // namespace voxc::explore
