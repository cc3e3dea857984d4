#pragma once
// What a terrain artist takes away: a 16-bit greyscale PNG heightmap (libpng) and float32 .npy maps
// of height, water and sediment. Files are added to an OutputFiles set, so a command's outputs are
// committed together or not at all (voxc/core/AtomicWrite.h).
#include "voxc/core/AtomicWrite.h"
#include "voxc/generators/terrain/Field2.h"

#include <cstdint>
#include <string>
#include <vector>

namespace voxc::terrain {

// Row y of the image is grid row y; pixel = round(clamp(H, 0, 1) * 65535), so 0..65535 spans 0..max_height.
std::string encodeHeightPng(const Field2& height);
void writeHeightPng(OutputFiles& outputs, const std::string& path, const Field2& height);

// A decoded 16-bit greyscale PNG (for checks and round trips). Throws UserError if the bytes are not
// one, or if it is wider or taller than 4096 (checked from the header, before any allocation).
struct Gray16Image {
    int32_t width = 0, height = 0;
    std::vector<uint16_t> pixels; // row-major
};
Gray16Image decodeGray16Png(const std::string& bytes);

// float32 .npy of shape (width, 1, height): arr[x, 0, y] is cell (x, y) (runtime/grid's writer, 1 high).
void writeFieldNpy(OutputFiles& outputs, const std::string& path, const Field2& field);

} // namespace voxc::terrain
