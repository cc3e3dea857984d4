#pragma once
#include "voxc/syntax/Ast.h"
#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

namespace voxc {

// Parses the whole file, recovering from syntax errors so that several are reported at once
// (each as E0001). The returned tree is complete only when no error was reported; after
// errors it holds whatever could be recovered and should not be checked.
ast::File parse(const SourceFile& source, Diagnostics& diagnostics);

} // namespace voxc
