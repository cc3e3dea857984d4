// lsystem_expand: host-side expansion speed of the shipped rule file (macros with weighted
// substitutes, lsystem-spec.md §2.6) grown to about 10^6 symbols; reports symbols per second.
#include "LsystemCases.h"

#include "voxc/core/Errors.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/generators/lsystem/RuleFile.h"

#include <fmt/format.h>

namespace voxc::bench {

namespace {

lsystem::Definition defaultRulesDefinition(uint32_t expansions) {
    Diagnostics diagnostics;
    const auto rules = lsystem::parseRuleFile(SourceFile("default.rules", std::string(lsystem::defaultRuleFileText())),
                                              diagnostics);
    if (!rules) throw InternalError("the shipped L-system rule file does not parse");
    lsystem::Definition d;
    d.productions = rules->productions;
    d.macros = rules->macros;
    d.expansions = expansions;
    d.seed = 1;
    return d;
}

} // namespace

void registerLsystemExpand(JsonReporter& reporter) {
    // 11 expansions of Z -> I[I][I] give 3^11 tips: about 1.8 * 10^6 symbols (1771746 for seed 1).
    const lsystem::Definition definition = defaultRulesDefinition(11);
    const size_t symbols = lsystem::expand(definition).symbols.size(); // also the warm-up run
    const std::string name = "lsystem_expand";
    benchmark::RegisterBenchmark(name.c_str(), [definition, symbols](benchmark::State& state) {
        for (auto _ : state) benchmark::DoNotOptimize(lsystem::expand(definition).symbols.data());
        state.counters["symbols_per_second"] =
            benchmark::Counter(double(symbols), benchmark::Counter::kIsIterationInvariantRate);
    })->Unit(benchmark::kMillisecond)->UseRealTime();
    reporter.describe(name + "/real_time", {"lsystem_expand", int(symbols), "host", "cpu (1 thread)"});
}

} // namespace voxc::bench
