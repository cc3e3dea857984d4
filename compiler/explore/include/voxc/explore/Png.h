#pragma once
// A minimal PNG encoder (8-bit truecolour, no interlace, filter 0 on every row, zlib-compressed).
#include "voxc/explore/Image.h"

#include <string>

namespace voxc::explore {

// The whole file: signature, IHDR, one IDAT, IEND.
std::string encodePng(const Image& image);

// Writes encodePng(image) atomically; UserError when the file cannot be written.
void writePng(const std::string& path, const Image& image);

} // namespace voxc::explore
