#pragma once
// `voxc lsp`: a language server for .vox files over the Language Server Protocol (JSON-RPC 2.0
// in Transport.h's framing). It publishes the real checker's diagnostics (codes, ranges, notes)
// whenever a document opens, changes or any document is saved (a rule file may have changed),
// answers hover with the registries' docs and completion with keys, the file's names and
// builtins, and survives malformed input: bad JSON or a bad header is answered with an error or
// skipped, never a crash (docs/editors.md).
#include <istream>
#include <ostream>

namespace voxc::lsp {

// Serves until `exit` or the end of `in`; `log` receives one line per problem with the input.
// Returns the process's exit code: 0 when `exit` followed `shutdown`, 1 otherwise.
int serve(std::istream& in, std::ostream& out, std::ostream& log);

} // namespace voxc::lsp
