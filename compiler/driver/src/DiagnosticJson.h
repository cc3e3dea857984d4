#pragma once
// A diagnostic as a JSON object, for `--diagnostics-format json` (docs/cli.md, "Diagnostics as
// JSON"): code, severity, file, range (1-based lines and columns in characters, end exclusive,
// null for a diagnostic about the whole file), message and notes (file, range, message).
#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

#include <nlohmann/json.hpp>

namespace voxc::driver {

nlohmann::ordered_json diagnosticJson(const Diagnostic& diagnostic, const SourceFile& checked);

} // namespace voxc::driver
