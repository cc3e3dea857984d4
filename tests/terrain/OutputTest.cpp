// The heightmap PNG through libpng and the .npy maps, written through OutputFiles.
#include "voxc/core/Errors.h"
#include "voxc/generators/terrain/Output.h"
#include "voxc/grid/Grid.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <png.h>
#include <sstream>
#include <unistd.h>

namespace voxc::terrain {
namespace {

std::filesystem::path scratchDirectory(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("voxc_terrain_" + name + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

Field2 ramp(int32_t width, int32_t height) {
    Field2 field(width, height);
    for (int32_t y = 0; y < height; ++y)
        for (int32_t x = 0; x < width; ++x) field.at(x, y) = float(x + width * y) / float(width * height - 1) * 1.2f - 0.1f;
    return field;
}

TEST(OutputTest, HeightPngRoundTripsThroughLibpng) {
    const Field2 height = ramp(37, 21); // odd sizes; values below 0 and above 1 clamp
    const Gray16Image image = decodeGray16Png(encodeHeightPng(height));
    ASSERT_EQ(image.width, 37);
    ASSERT_EQ(image.height, 21);
    for (size_t i = 0; i < height.values.size(); ++i) {
        const double expected = std::round(std::clamp(double(height.values[i]), 0.0, 1.0) * 65535.0);
        ASSERT_EQ(image.pixels[i], uint16_t(expected)) << i;
    }
    EXPECT_EQ(image.pixels.front(), 0);
    EXPECT_EQ(image.pixels.back(), 65535);
}

TEST(OutputTest, FilesAreWrittenTogether) {
    const auto dir = scratchDirectory("files");
    const Field2 height = ramp(16, 8);
    {
        OutputFiles outputs;
        writeHeightPng(outputs, (dir / "h.png").string(), height);
        writeFieldNpy(outputs, (dir / "h.npy").string(), height);
        EXPECT_FALSE(std::filesystem::exists(dir / "h.png")); // nothing before commit
        outputs.commit();
    }
    std::ifstream png(dir / "h.png", std::ios::binary);
    std::stringstream bytes;
    bytes << png.rdbuf();
    EXPECT_EQ(decodeGray16Png(bytes.str()).pixels, decodeGray16Png(encodeHeightPng(height)).pixels);
    const DenseGrid grid = readNpy((dir / "h.npy").string());
    ASSERT_EQ(grid.size(), glm::ivec3(16, 1, 8));
    for (int32_t y = 0; y < 8; ++y)
        for (int32_t x = 0; x < 16; ++x) ASSERT_EQ(grid.at({x, 0, y}), height.at(x, y));
    std::filesystem::remove_all(dir);
}

void appendTo(png_structp png, png_bytep data, png_size_t length) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
}

// An Adam7-interlaced 16-bit greyscale PNG, as other tools may write; empty on a libpng error.
std::string interlacedPng(const std::vector<uint16_t>& pixels, int32_t width, int32_t height) {
    std::vector<png_byte> bytes(pixels.size() * 2);
    for (size_t i = 0; i < pixels.size(); ++i) {
        bytes[2 * i] = png_byte(pixels[i] >> 8);
        bytes[2 * i + 1] = png_byte(pixels[i] & 0xff);
    }
    std::vector<png_bytep> rows(static_cast<size_t>(height));
    for (int32_t y = 0; y < height; ++y) rows[size_t(y)] = bytes.data() + size_t(y) * size_t(width) * 2;
    std::string out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return {};
    }
    png_set_write_fn(png, &out, appendTo, nullptr);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 16, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_ADAM7,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows.data()); // handles the interlace passes itself
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return out;
}

TEST(OutputTest, InterlacedPngsDecode) {
    std::vector<uint16_t> pixels(13 * 11);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = uint16_t(i * 977 % 65536);
    const std::string png = interlacedPng(pixels, 13, 11);
    ASSERT_FALSE(png.empty());
    const Gray16Image image = decodeGray16Png(png);
    EXPECT_EQ(image.width, 13);
    EXPECT_EQ(image.pixels, pixels);
}

TEST(OutputTest, NotAPngIsAUserError) {
    EXPECT_THROW(decodeGray16Png("definitely not a png"), UserError);
    const std::string png = encodeHeightPng(ramp(8, 8));
    EXPECT_THROW(decodeGray16Png(png.substr(0, png.size() / 2)), UserError); // truncated
    EXPECT_THROW(decodeGray16Png(encodeHeightPng(Field2(4097, 1))), UserError); // over the size cap
    EXPECT_EQ(decodeGray16Png(encodeHeightPng(Field2(4096, 1))).width, 4096);
}

} // namespace
} // namespace voxc::terrain
