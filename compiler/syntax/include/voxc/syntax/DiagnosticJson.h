#pragma once
// A diagnostic as one line of JSON, for `--diagnostics-format json` (docs/cli.md, "Diagnostics as
// JSON"): code, severity, file, range (1-based lines and columns in characters, end exclusive,
// null for a diagnostic about the whole file), message, notes (file, range, message) and fixits
// (range, replacement).
#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

#include <string>

namespace voxc {

// Without a trailing newline. Messages quote the user's text, which the checker has already
// required to be UTF-8; anything else is replaced rather than refused.
std::string renderJson(const Diagnostic& diagnostic, const SourceFile& checked);

} // namespace voxc
