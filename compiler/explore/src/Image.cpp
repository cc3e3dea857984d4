#include "voxc/explore/Image.h"

#include "voxc/core/Errors.h"

namespace voxc::explore {

Image::Image(int width_, int height_, Rgb fill) : width(width_), height(height_) {
    VOXC_ASSERT(width > 0 && height > 0);
    rgb.resize(size_t(width) * size_t(height) * 3);
    for (size_t i = 0; i < rgb.size(); i += 3) {
        rgb[i] = fill.r;
        rgb[i + 1] = fill.g;
        rgb[i + 2] = fill.b;
    }
}

Rgb Image::at(int x, int y) const {
    const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void Image::set(int x, int y, Rgb color) {
    if (!inside(x, y)) return;
    const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 3;
    rgb[i] = color.r;
    rgb[i + 1] = color.g;
    rgb[i + 2] = color.b;
}

} // namespace voxc::explore
