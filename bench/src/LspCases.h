#pragma once
#include "JsonReporter.h"

namespace voxc::bench {

// Registers lsp_latency: `voxc lsp` (lsp::serve, in this process, over pipes as an editor drives
// it) with examples/valley.vox open; each iteration sends an edit that leaves the file valid, then
// a completion request at the edit, and times the completion's answer (ms). The edit's check runs
// meanwhile on the server's checker thread; the time from the edit to its diagnostics is the
// counter diagnostics_ms (mean). docs/editors.md, "Nothing waits for a check".
void registerLspLatency(JsonReporter& reporter);

} // namespace voxc::bench
