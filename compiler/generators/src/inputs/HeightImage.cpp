#include "voxc/generators/inputs/HeightImage.h"

#include <fmt/format.h>
#include <png.h>
#include <tiffio.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <limits>
#include <regex>

namespace voxc::inputs {

namespace {

void checkPixels(int64_t width, int64_t height, const Limits& limits, std::string_view what) {
    if (width <= 0 || height <= 0) malformed(fmt::format("the {} has no pixels ({} x {})", what, width, height));
    if (width * height > limits.maxPixels)
        throw InputError("E0012", fmt::format("the {} has {} x {} pixels, more than the limit of {}", what, width, height,
                                              limits.maxPixels));
}

void checkFinite(const HeightImage& image) {
    for (size_t i = 0; i < image.values.size(); ++i)
        if (!std::isfinite(image.values[i]))
            malformed(fmt::format("pixel ({}, {}) is not a finite number", i % size_t(image.width),
                                  i / size_t(image.width)));
}

// ---- PNG (libpng; errors longjmp back with their message) ----

struct PngReader {
    std::string_view bytes;
    size_t offset = 0;
    std::string error;
};

void pngError(png_structp png, png_const_charp message) {
    static_cast<PngReader*>(png_get_error_ptr(png))->error = message;
    png_longjmp(png, 1);
}
void pngWarning(png_structp, png_const_charp) {}
void pngRead(png_structp png, png_bytep data, png_size_t length) {
    auto* reader = static_cast<PngReader*>(png_get_io_ptr(png));
    if (reader->bytes.size() - reader->offset < length) png_error(png, "the file ends inside the image (truncated)");
    std::memcpy(data, reader->bytes.data() + reader->offset, length);
    reader->offset += length;
}

HeightImage decodePng(std::string_view bytes, const Limits& limits) {
    PngReader reader{bytes, 0, {}};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &reader, pngError, pngWarning);
    if (!png) throw std::bad_alloc();
    png_infop info = png_create_info_struct(png);
    HeightImage image;
    std::vector<png_byte> rows;
    // What the longjmp may skip over must not need destructors: set up before setjmp.
    std::string unsupported;
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        malformed(fmt::format("not a readable PNG: {}", reader.error));
    }
    png_set_read_fn(png, &reader, pngRead);
    // libpng refuses a larger header before allocating anything.
    const png_uint_32 side = png_uint_32(std::min<int64_t>(limits.maxPixels, PNG_USER_WIDTH_MAX));
    png_set_user_limits(png, side, side);
    png_read_info(png, info);
    const int depth = png_get_bit_depth(png, info), colour = png_get_color_type(png, info);
    const int64_t width = png_get_image_width(png, info), height = png_get_image_height(png, info);
    if (colour != PNG_COLOR_TYPE_GRAY || (depth != 8 && depth != 16))
        unsupported = fmt::format("the PNG is {}-bit {}; a height image is 8- or 16-bit greyscale", depth,
                                  colour == PNG_COLOR_TYPE_GRAY ? "greyscale" : "colour or with alpha");
    else if (width * height > limits.maxPixels)
        unsupported = fmt::format("the PNG has {} x {} pixels, more than the limit of {}", width, height, limits.maxPixels);
    if (!unsupported.empty()) {
        png_destroy_read_struct(&png, &info, nullptr);
        throw InputError(width * height > limits.maxPixels ? "E0012" : "E0010", unsupported);
    }
    if (depth == 16) png_set_swap(png); // little-endian words on this host
    const size_t bytesPerPixel = size_t(depth / 8);
    rows.resize(size_t(width) * size_t(height) * bytesPerPixel);
    const int passes = png_set_interlace_handling(png);
    for (int pass = 0; pass < passes; ++pass)
        for (int64_t y = 0; y < height; ++y)
            png_read_row(png, rows.data() + size_t(y) * size_t(width) * bytesPerPixel, nullptr);
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    image.width = int32_t(width), image.height = int32_t(height);
    image.values.resize(size_t(width) * size_t(height));
    for (size_t i = 0; i < image.values.size(); ++i) {
        if (depth == 8) {
            image.values[i] = float(rows[i]);
        } else {
            uint16_t v;
            std::memcpy(&v, rows.data() + 2 * i, 2);
            image.values[i] = float(v);
        }
    }
    image.format = depth == 8 ? "png8" : "png16";
    image.fullScale = depth == 8 ? 255.0 : 65535.0;
    return image;
}

// ---- .npy (version 1-3 header: a Python dict literal) ----

HeightImage decodeNpy(std::string_view bytes, const Limits& limits) {
    if (bytes.size() < 10) malformed("the .npy file ends inside its header (truncated)");
    const int major = uint8_t(bytes[6]);
    size_t headerLength = 0, headerStart = 0;
    if (major == 1) {
        headerLength = uint8_t(bytes[8]) | size_t(uint8_t(bytes[9])) << 8, headerStart = 10;
    } else if (major == 2 || major == 3) {
        if (bytes.size() < 12) malformed("the .npy file ends inside its header (truncated)");
        for (int i = 0; i < 4; ++i) headerLength |= size_t(uint8_t(bytes[8 + size_t(i)])) << (8 * i);
        headerStart = 12;
    } else {
        malformed(fmt::format("unknown .npy version {}", major));
    }
    if (bytes.size() - headerStart < headerLength) malformed("the .npy file ends inside its header (truncated)");
    // numpy writes a few hundred bytes; the bound keeps the header's regular expressions cheap.
    if (headerLength > 4096) malformed(fmt::format("the .npy header is {} bytes long", headerLength));
    const std::string header(bytes.substr(headerStart, headerLength));
    std::smatch match;
    if (!std::regex_search(header, match, std::regex(R"('descr'\s*:\s*'([^']*)')")))
        malformed("the .npy header has no 'descr'");
    const std::string descr = match[1];
    if (std::regex_search(header, std::regex(R"('fortran_order'\s*:\s*True)")))
        throw InputError("E0010", "the .npy array is in Fortran order; save it in C order");
    if (!std::regex_search(header, match, std::regex(R"('shape'\s*:\s*\(([^)]*)\))")))
        malformed("the .npy header has no 'shape'");
    std::vector<int64_t> shape;
    const std::string dims = match[1];
    const std::regex number(R"(\d+)");
    for (std::sregex_iterator it(dims.begin(), dims.end(), number), end; it != end; ++it) {
        if (it->str().size() > 12) throw InputError("E0012", "the .npy array is larger than the pixel limit");
        shape.push_back(std::stoll(it->str()));
    }
    int64_t width = 0, height = 0;
    bool voxcLayout = false; // (x, 1, z), as voxc terrain writes its maps
    if (shape.size() == 2) {
        height = shape[0], width = shape[1];
    } else if (shape.size() == 3 && shape[1] == 1) {
        width = shape[0], height = shape[2], voxcLayout = true;
    } else {
        throw InputError("E0010", fmt::format("the .npy array has shape ({}); a height image is (rows, columns) or "
                                              "voxc's (x, 1, z)",
                                              dims));
    }
    checkPixels(width, height, limits, ".npy array");
    size_t itemSize = 0;
    bool isFloat = false;
    if (descr == "<f4" || descr == "=f4") itemSize = 4, isFloat = true;
    else if (descr == "<u2" || descr == "=u2") itemSize = 2;
    else
        throw InputError("E0010", fmt::format("the .npy array holds '{}'; a height image is float32 ('<f4') or uint16 "
                                              "('<u2'): save it with numpy as array.astype(numpy.float32)",
                                              descr));
    const size_t count = size_t(width) * size_t(height);
    const size_t dataStart = headerStart + headerLength;
    if (bytes.size() - dataStart < count * itemSize)
        malformed(fmt::format("the .npy file holds {} bytes of data where its shape needs {} (truncated)",
                              bytes.size() - dataStart, count * itemSize));
    HeightImage image;
    image.width = int32_t(width), image.height = int32_t(height);
    image.values.resize(count);
    for (int64_t z = 0; z < height; ++z)
        for (int64_t x = 0; x < width; ++x) {
            const size_t from = voxcLayout ? size_t(x) * size_t(height) + size_t(z) : size_t(z) * size_t(width) + size_t(x);
            const char* at = bytes.data() + dataStart + from * itemSize;
            float v;
            if (isFloat) {
                std::memcpy(&v, at, 4);
            } else {
                uint16_t u;
                std::memcpy(&u, at, 2);
                v = float(u);
            }
            image.values[size_t(z) * size_t(width) + size_t(x)] = v;
        }
    image.format = isFloat ? "npy_f32" : "npy_u16";
    image.fullScale = isFloat ? 1.0 : 65535.0;
    if (isFloat) checkFinite(image);
    return image;
}

// ---- TIFF (libtiff over the bytes in memory) ----

struct TiffStream {
    std::string_view bytes;
    toff_t offset = 0;
};

tsize_t tiffRead(thandle_t handle, tdata_t data, tsize_t size) {
    auto* s = static_cast<TiffStream*>(handle);
    if (s->offset >= s->bytes.size()) return 0;
    const size_t n = std::min<size_t>(size_t(size), s->bytes.size() - size_t(s->offset));
    std::memcpy(data, s->bytes.data() + s->offset, n);
    s->offset += n;
    return tsize_t(n);
}
tsize_t tiffWrite(thandle_t, tdata_t, tsize_t) { return 0; }
toff_t tiffSeek(thandle_t handle, toff_t offset, int whence) {
    auto* s = static_cast<TiffStream*>(handle);
    const toff_t base = whence == SEEK_SET ? 0 : whence == SEEK_CUR ? s->offset : toff_t(s->bytes.size());
    s->offset = base + offset;
    return s->offset;
}
int tiffClose(thandle_t) { return 0; }
toff_t tiffSize(thandle_t handle) { return static_cast<TiffStream*>(handle)->bytes.size(); }
int tiffMap(thandle_t, tdata_t*, toff_t*) { return 0; }
void tiffUnmap(thandle_t, tdata_t, toff_t) {}

// libtiff reports through handlers; these keep the first error of the current decode.
thread_local std::string tiffError;
int tiffErrorHandler(TIFF*, void*, const char*, const char* format, va_list args) {
    if (tiffError.empty()) {
        char buffer[512];
        std::vsnprintf(buffer, sizeof buffer, format, args);
        tiffError = buffer;
    }
    return 1;
}
int tiffWarningHandler(TIFF*, void*, const char*, const char*, va_list) { return 1; }

HeightImage decodeTiff(std::string_view bytes, const Limits& limits) {
    TiffStream stream{bytes};
    tiffError.clear();
    TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
    TIFFOpenOptionsSetErrorHandlerExtR(options, tiffErrorHandler, nullptr);
    TIFFOpenOptionsSetWarningHandlerExtR(options, tiffWarningHandler, nullptr);
    TIFF* tiff = TIFFClientOpenExt("input", "rm", &stream, tiffRead, tiffWrite, tiffSeek, tiffClose, tiffSize, tiffMap,
                                   tiffUnmap, options);
    TIFFOpenOptionsFree(options);
    if (!tiff) malformed(fmt::format("not a readable TIFF: {}", tiffError));
    struct Closer {
        TIFF* tiff;
        ~Closer() { TIFFClose(tiff); }
    } closer{tiff};
    uint32_t width = 0, height = 0;
    uint16_t bits = 0, samples = 1, format = SAMPLEFORMAT_UINT;
    TIFFGetField(tiff, TIFFTAG_IMAGEWIDTH, &width);
    TIFFGetField(tiff, TIFFTAG_IMAGELENGTH, &height);
    TIFFGetFieldDefaulted(tiff, TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(tiff, TIFFTAG_SAMPLESPERPIXEL, &samples);
    TIFFGetFieldDefaulted(tiff, TIFFTAG_SAMPLEFORMAT, &format);
    checkPixels(width, height, limits, "TIFF");
    const bool isFloat = format == SAMPLEFORMAT_IEEEFP && bits == 32;
    const bool isU16 = format == SAMPLEFORMAT_UINT && bits == 16;
    if (samples != 1 || !(isFloat || isU16))
        throw InputError("E0010", fmt::format("the TIFF has {} sample(s) of {} bits ({}); a height image is one 32-bit "
                                              "float or 16-bit unsigned sample per pixel",
                                              samples, bits, format == SAMPLEFORMAT_IEEEFP ? "float" : "integer"));
    if (TIFFIsTiled(tiff)) throw InputError("E0010", "the TIFF is tiled; save it in strips");
    if (tsize_t(TIFFScanlineSize(tiff)) != tsize_t(width) * (bits / 8))
        malformed("the TIFF's scanline size does not match its width");
    HeightImage image;
    image.width = int32_t(width), image.height = int32_t(height);
    image.values.resize(size_t(width) * size_t(height));
    std::vector<uint8_t> line(size_t(width) * (bits / 8));
    for (uint32_t y = 0; y < height; ++y) {
        if (TIFFReadScanline(tiff, line.data(), y, 0) < 0)
            malformed(fmt::format("cannot read row {} of the TIFF: {}", y, tiffError.empty() ? "truncated" : tiffError));
        for (uint32_t x = 0; x < width; ++x) {
            float v;
            if (isFloat) {
                std::memcpy(&v, line.data() + 4 * size_t(x), 4);
            } else {
                uint16_t u;
                std::memcpy(&u, line.data() + 2 * size_t(x), 2);
                v = float(u);
            }
            image.values[size_t(y) * width + x] = v;
        }
    }
    image.format = isFloat ? "tiff_f32" : "tiff_u16";
    image.fullScale = isFloat ? 1.0 : 65535.0;
    if (isFloat) checkFinite(image);
    return image;
}

} // namespace

HeightImage decodeHeightImage(std::string_view bytes, const Limits& limits) {
    static constexpr unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (bytes.size() >= 8 && std::memcmp(bytes.data(), kPng, 8) == 0) return decodePng(bytes, limits);
    if (bytes.size() >= 6 && bytes.substr(0, 6) == "\x93NUMPY") return decodeNpy(bytes, limits);
    if (bytes.size() >= 4 && (bytes.substr(0, 4) == std::string_view("II*\0", 4) || bytes.substr(0, 4) == std::string_view("MM\0*", 4)))
        return decodeTiff(bytes, limits);
    throw InputError("E0102", "not a height image: a 8- or 16-bit greyscale PNG, a float32 or uint16 .npy array or a "
                              "float32 or uint16 TIFF");
}

} // namespace voxc::inputs
