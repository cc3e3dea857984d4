#pragma once
// Every output file is written to a temporary beside it and renamed into place,
// so a failure never leaves a partial file behind.
#include <functional>
#include <ostream>
#include <string>

namespace voxc {

// Calls `write` with a stream on a temp file, then renames it to `path`.
// Throws UserError if the file cannot be written; removes the temp file on any failure.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

void writeFileAtomically(const std::string& path, const std::string& contents);

} // namespace voxc
