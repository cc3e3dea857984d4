#include "voxc/generators/terrain/Output.h"

#include "voxc/core/Errors.h"
#include "voxc/grid/Grid.h"

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstring>
#include <png.h>

namespace voxc::terrain {

namespace {

constexpr png_uint_32 kMaxPngSide = 4096; // the largest terrain level

// libpng reports errors by longjmp; these callbacks only record the message, and the functions
// using setjmp keep every object with a destructor outside the jumped-over frame.
void recordError(png_structp png, png_const_charp message) {
    auto* error = static_cast<std::string*>(png_get_error_ptr(png));
    *error = message;
    png_longjmp(png, 1);
}
void ignoreWarning(png_structp, png_const_charp) {}

void appendBytes(png_structp png, png_bytep data, png_size_t length) {
    auto* out = static_cast<std::string*>(png_get_io_ptr(png));
    out->append(reinterpret_cast<const char*>(data), length);
}
void flushNothing(png_structp) {}

struct Reader {
    const std::string* bytes;
    size_t offset;
};
void readBytes(png_structp png, png_bytep data, png_size_t length) {
    auto* reader = static_cast<Reader*>(png_get_io_ptr(png));
    if (reader->bytes->size() - reader->offset < length) png_error(png, "truncated PNG");
    std::memcpy(data, reader->bytes->data() + reader->offset, length);
    reader->offset += length;
}

// Returns false (with `error` set) on a libpng error. `rows` are big-endian 16-bit rows.
bool encode(std::string& out, std::string& error, int32_t width, int32_t height, std::vector<png_bytep>& rows) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, recordError, ignoreWarning);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, &out, appendBytes, flushNothing);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 16, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

// Returns false (with `error` set) on a libpng error or an image that is not 16-bit greyscale.
bool decode(Reader& reader, std::string& error, Gray16Image& image, std::vector<uint8_t>& data) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, recordError, ignoreWarning);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_set_read_fn(png, &reader, readBytes);
    png_set_user_limits(png, kMaxPngSide, kMaxPngSide); // libpng refuses larger headers before allocating
    png_read_info(png, info);
    if (png_get_bit_depth(png, info) != 16 || png_get_color_type(png, info) != PNG_COLOR_TYPE_GRAY) {
        error = "not a 16-bit greyscale PNG";
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    image.width = int32_t(png_get_image_width(png, info));
    image.height = int32_t(png_get_image_height(png, info));
    data.resize(size_t(image.width) * size_t(image.height) * 2);
    const int passes = png_set_interlace_handling(png); // 7 for Adam7, each pass refines every row
    for (int pass = 0; pass < passes; ++pass)
        for (int32_t y = 0; y < image.height; ++y) png_read_row(png, data.data() + size_t(y) * size_t(image.width) * 2, nullptr);
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

} // namespace

std::string encodeHeightPng(const Field2& height) {
    const size_t stride = size_t(height.width) * 2;
    std::vector<uint8_t> data(stride * size_t(height.height));
    for (size_t i = 0; i < height.values.size(); ++i) {
        const float v = height.values[i];
        const float clamped = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
        const auto level = uint16_t(std::lround(double(clamped) * 65535.0));
        data[2 * i] = uint8_t(level >> 8); // PNG stores 16-bit samples big-endian
        data[2 * i + 1] = uint8_t(level & 0xff);
    }
    std::vector<png_bytep> rows(size_t(height.height));
    for (size_t y = 0; y < rows.size(); ++y) rows[y] = data.data() + y * stride;
    std::string out, error;
    if (!encode(out, error, height.width, height.height, rows)) throw InternalError("libpng could not encode the heightmap: " + error);
    return out;
}

void writeHeightPng(OutputFiles& outputs, const std::string& path, const Field2& height) {
    outputs.add(path, encodeHeightPng(height));
}

Gray16Image decodeGray16Png(const std::string& bytes) {
    Reader reader{&bytes, 0};
    Gray16Image image;
    std::vector<uint8_t> data;
    std::string error;
    if (!decode(reader, error, image, data)) throw UserError("not a readable 16-bit greyscale PNG: " + error);
    image.pixels.resize(data.size() / 2);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = uint16_t((data[2 * i] << 8) | data[2 * i + 1]);
    return image;
}

void writeFieldNpy(OutputFiles& outputs, const std::string& path, const Field2& field) {
    DenseGrid grid({field.width, 1, field.height});
    grid.data() = field.values; // DenseGrid index x + sx * (y + sy * z) with sy = 1 is the Field2 index
    writeNpy(outputs, path, grid);
}

} // namespace voxc::terrain
