#include "JsonReporter.h"

#include <iostream>

namespace voxc::bench {

void JsonReporter::ReportRuns(const std::vector<Run>& runs) {
    for (const Run& run : runs) {
        const auto key = keys_.find(run.run_name.str());
        if (key == keys_.end()) continue;
        nlohmann::json record;
        record["case"] = key->second.caseName;
        record["n"] = key->second.n;
        record["backend"] = key->second.backend;
        record["device"] = key->second.device;
        if (run.error_occurred) {
            record["error"] = run.error_message;
        } else {
            record["ms"] = run.GetAdjustedRealTime(); // the benchmarks use millisecond units
            record["runs"] = run.iterations;
            for (const auto& [counter, value] : run.counters) record[counter] = double(value);
        }
        records_.push_back(record);
    }
}

void JsonReporter::Finalize() { std::cout << records_.dump(2) << std::endl; }

} // namespace voxc::bench
