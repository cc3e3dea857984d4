#pragma once
// PNG output through libpng's simplified API: 8-bit RGB, libpng's own choice of filters and compression.
#include "voxc/explore/Image.h"

#include <string>

namespace voxc::explore {

// The whole file, as libpng writes it.
std::string encodePng(const Image& image);

// Writes encodePng(image) atomically; UserError when the file cannot be written.
void writePng(const std::string& path, const Image& image);

} // namespace voxc::explore
