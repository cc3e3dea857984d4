#include "JsonReporter.h"

#include <algorithm>
#include <iostream>

namespace voxc::bench {

namespace {

nlohmann::json keyRecord(const RecordKey& key) {
    nlohmann::json record;
    record["case"] = key.caseName;
    record["n"] = key.n;
    record["backend"] = key.backend;
    record["device"] = key.device;
    return record;
}

} // namespace

void JsonReporter::addRecord(const RecordKey& key, double ms) {
    nlohmann::json record = keyRecord(key);
    record["ms"] = ms;
    record["runs"] = 1;
    extraRecords_.push_back(record);
}

void JsonReporter::ReportRuns(const std::vector<Run>& runs) {
    for (const Run& run : runs) {
        if (run.run_type != Run::RT_Iteration) continue; // aggregates are computed in Finalize
        const std::string name = run.run_name.str();
        const auto key = keys_.find(name);
        if (key == keys_.end()) continue;
        auto [entry, inserted] = runs_.try_emplace(name);
        if (inserted) {
            entry->second.key = key->second;
            order_.push_back(name);
        }
        Repetitions& repetitions = entry->second;
        if (run.error_occurred) {
            repetitions.error = run.error_message;
            continue;
        }
        repetitions.ms.push_back(run.GetAdjustedRealTime()); // the benchmarks use millisecond units
        repetitions.iterations += run.iterations;
        for (const auto& [counter, value] : run.counters) repetitions.counters[counter] = double(value);
    }
}

void JsonReporter::Finalize() {
    nlohmann::json records = nlohmann::json::array();
    for (const std::string& name : order_) {
        Repetitions& repetitions = runs_.at(name);
        nlohmann::json record = keyRecord(repetitions.key);
        if (!repetitions.error.empty() || repetitions.ms.empty()) {
            record["error"] = repetitions.error;
        } else {
            std::vector<double>& ms = repetitions.ms;
            std::sort(ms.begin(), ms.end());
            const size_t n = ms.size();
            record["ms"] = n % 2 ? ms[n / 2] : (ms[n / 2 - 1] + ms[n / 2]) / 2.0;
            record["runs"] = repetitions.iterations;
            if (n > 1) {
                record["repetitions"] = n;
                record["ms_min"] = ms.front();
                record["ms_max"] = ms.back();
            }
            for (const auto& [counter, value] : repetitions.counters) record[counter] = value;
        }
        records.push_back(record);
    }
    for (const nlohmann::json& record : extraRecords_) records.push_back(record);
    std::cout << records.dump(2) << std::endl;
}

} // namespace voxc::bench
