#pragma once
// SHA-256 (FIPS 180-4): the manifest's hash of the source text, the world tiles' hashes.
#include <string>
#include <string_view>

namespace voxc {

// The digest of `bytes` as 64 lowercase hex digits.
std::string sha256Hex(std::string_view bytes);

} // namespace voxc
