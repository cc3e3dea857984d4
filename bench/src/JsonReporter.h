#pragma once
// Collects Google Benchmark's runs and prints them as voxc's record list:
// [{"case": ..., "n": ..., "backend": "vulkan"|"interp", "ms": ..., "device": ...}, ...]
#include <benchmark/benchmark.h>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

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

    bool ReportContext(const Context&) override { return true; }
    void ReportRuns(const std::vector<Run>& runs) override;
    void Finalize() override;

private:
    std::map<std::string, RecordKey> keys_;
    nlohmann::json records_ = nlohmann::json::array();
};

} // namespace voxc::bench
