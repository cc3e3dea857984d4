#include "voxc/explore/Png.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"

#include <fmt/format.h>
#include <png.h>

namespace voxc::explore {

// libpng's simplified API: one call for the size, one for the bytes.
std::string encodePng(const Image& image) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = png_uint_32(image.width);
    png.height = png_uint_32(image.height);
    png.format = PNG_FORMAT_RGB;
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&png, nullptr, &size, 0, image.rgb.data(), 0, nullptr))
        throw InternalError(fmt::format("libpng could not size a {}x{} image: {}", image.width, image.height, png.message));
    std::string out(size, '\0');
    if (!png_image_write_to_memory(&png, out.data(), &size, 0, image.rgb.data(), 0, nullptr))
        throw InternalError(fmt::format("libpng could not encode a {}x{} image: {}", image.width, image.height, png.message));
    out.resize(size);
    return out;
}

void writePng(const std::string& path, const Image& image) { writeFileAtomically(path, encodePng(image)); }

} // namespace voxc::explore
