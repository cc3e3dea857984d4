#pragma once
// Height images: 8- and 16-bit greyscale PNG (libpng), `.npy` arrays of float32 or uint16, and
// 32-bit float or 16-bit greyscale TIFF (libtiff), as a DEM or a terrain tool exports them.
#include "voxc/generators/inputs/Inputs.h"

#include <string>
#include <string_view>
#include <vector>

namespace voxc::inputs {

struct HeightImage {
    int32_t width = 0, height = 0; // pixels along x, and along z (rows)
    // The pixels as stored, row-major (row 0 first), x fastest: 0..255 or 0..65535 for integer
    // images, the floats themselves for float ones.
    std::vector<float> values;
    std::string format;     // "png8", "png16", "npy_f32", "npy_u16", "tiff_f32", "tiff_u16"
    double fullScale = 1.0; // the largest value of the integer type, 1 for float images
};

// Decides the format by the file's first bytes (the PNG signature, `\x93NUMPY`, `II*\0` or
// `MM\0*`), so a misnamed file still reads. InputError for anything else, a truncated or
// inconsistent file, a non-finite float, more than Limits::maxPixels pixels (checked from the
// header before the pixels are allocated) or an empty image.
// A .npy array is (rows, columns) = (z, x), or voxc's own (x, 1, z) layout (`voxc terrain
// --height`); C order only.
HeightImage decodeHeightImage(std::string_view bytes, const Limits& limits = {});

} // namespace voxc::inputs
