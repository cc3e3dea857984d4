// The heightmap PNG through libpng and the .npy maps, written through OutputFiles.
#include "voxc/core/Errors.h"
#include "voxc/generators/terrain/Output.h"
#include "voxc/grid/Grid.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
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

TEST(OutputTest, NotAPngIsAUserError) {
    EXPECT_THROW(decodeGray16Png("definitely not a png"), UserError);
    const std::string png = encodeHeightPng(ramp(8, 8));
    EXPECT_THROW(decodeGray16Png(png.substr(0, png.size() / 2)), UserError); // truncated
}

} // namespace
} // namespace voxc::terrain
