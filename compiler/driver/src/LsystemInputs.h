#pragma once
// What the L-system verbs (`voxc lsystem`, `voxc lsystem cross`, `voxc evolve`) share: reading
// an lsystem block of a checked file.
#include "voxc/check/Check.h"
#include "voxc/generators/lsystem/Definition.h"

#include <string>
#include <utility>

namespace voxc::driver {

// Checks `path` like `voxc check` (diagnostics to stderr, UserError on errors).
CheckResult loadChecked(const std::string& path);

// The lsystem block `name` of a checked file; UserError naming the blocks there are otherwise.
const CheckedLsystem& findLsystem(const std::vector<CheckedLsystem>& lsystems, const std::string& path,
                                  const std::string& name);

// A limit the expansion or the turtle hits is a located E0012 at the block, as `voxc check`
// reports the limits it can predict.
[[noreturn]] void reportLimit(const CheckResult& result, const CheckedLsystem& lsystem,
                              const lsystem::LimitError& error);

// The expansion of `lsystem` step by step for `voxc interp --trace`: every choice among several
// productions or substitutes (expansion, position, symbol, which alternative and its text),
// then the length after each expansion; at most `maxLines` lines, `printed` counting them.
std::string expansionTrace(const CheckedLsystem& lsystem, uint64_t maxLines, uint64_t& printed);

// "a.vox:net" -> ("a.vox", "net"), split at the last ':'.
std::pair<std::string, std::string> splitReference(const std::string& reference);

} // namespace voxc::driver
