#pragma once
// The paper's rule file (§III-B.4): one `Symbol;SubstituteString;Type;Weight` record per line.
// A `Z` line is a production, any other symbol a macro substitute. Blank lines and lines starting
// with `#` are skipped (a voxc extension). Thesis alphabet only.
#include "voxc/generators/lsystem/Definition.h"
#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

#include <map>
#include <optional>
#include <string_view>
#include <vector>

namespace voxc::lsystem {

struct RuleSet {
    std::map<char, std::vector<Alternative>> productions;
    std::map<char, std::vector<Alternative>> macros;
};

// Every mistake is reported located in `source` with a stable code: a record without four
// fields or a Symbol that is not one character E0001, an unbalanced bracket E0001, a symbol
// neither in the thesis alphabet nor a macro of the file E0002, an unknown Type E0002, a turtle
// symbol used as a macro E0003, an empty substitute E0009, a Weight that is not a number E0010
// or not finite E0007, a macro inside a substitute E0013, more alternatives than
// Limits::maxAlternatives E0012. Returns nothing when an error was reported.
std::optional<RuleSet> parseRuleFile(const SourceFile& source, Diagnostics& diagnostics, const Limits& limits = {});

// voxc's reconstruction of the lost Appendix VIII rule file (lsystem-spec.md §2.6).
std::string_view defaultRuleFileText();

} // namespace voxc::lsystem
