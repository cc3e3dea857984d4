#pragma once
#include "voxc/syntax/Ast.h"
#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

#include <cstdint>

namespace voxc {

constexpr uint32_t kDefaultMaxNesting = 256;

// Parses the whole file, recovering from syntax errors so that several are reported at once
// (each as E0001). The returned tree is complete only when no error was reported; after
// errors it holds whatever could be recovered and should not be checked.
//
// A tree deeper than `maxNesting` rules (Limits::maxNesting) is error E0012 at the token that
// passes the limit, and nothing else is built, so no later pass recurses deeper than that.
ast::File parse(const SourceFile& source, Diagnostics& diagnostics, uint32_t maxNesting = kDefaultMaxNesting);

} // namespace voxc
