#pragma once
// Collects Google Benchmark's runs and prints them as voxc's record list:
// [{"case": ..., "n": ..., "backend": "vulkan"|"interp"|..., "ms": ..., "device": ...}, ...]
// With repetitions (voxc-bench --repetitions N), one record per case: "ms" is the median of the
// repetitions' means, "ms_min" and "ms_max" their spread, "repetitions" how many.
#include <benchmark/benchmark.h>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace voxc::bench {

struct RecordKey {
    std::string caseName;
    int n = 0;
    std::string backend;
    std::string device;
};

class JsonReporter : public benchmark::BenchmarkReporter {
public:
    // Registers what a benchmark name stands for; names not registered are ignored.
    void describe(const std::string& benchmarkName, RecordKey key) { keys_[benchmarkName] = std::move(key); }
    // A measurement made outside a timed loop (e.g. a package's pipeline creation), as its own record.
    void addRecord(const RecordKey& key, double ms);

    bool ReportContext(const Context&) override { return true; }
    void ReportRuns(const std::vector<Run>& runs) override;
    void Finalize() override;

private:
    struct Repetitions {
        RecordKey key;
        std::vector<double> ms;
        int64_t iterations = 0;
        std::map<std::string, double> counters; // the last repetition's
        std::string error;
    };
    std::map<std::string, RecordKey> keys_;
    std::vector<std::string> order_; // benchmark names in the order they ran
    std::map<std::string, Repetitions> runs_;
    nlohmann::json extraRecords_ = nlohmann::json::array();
};

} // namespace voxc::bench
