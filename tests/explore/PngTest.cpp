// The PNG writer's output reads back, through libpng's reader, as the same pixels.
#include "voxc/explore/Explore.h"
#include "voxc/explore/Plot.h"
#include "voxc/explore/Png.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <png.h>
#include <sstream>

using namespace voxc;
using namespace voxc::explore;

namespace {

// Width, height and the 8-bit RGB rows (x fastest) of a PNG file's bytes.
std::tuple<uint32_t, uint32_t, std::string> decode(const std::string& bytes) {
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size())) {
        ADD_FAILURE() << png.message;
        return {0, 0, ""};
    }
    EXPECT_EQ(png.format & PNG_FORMAT_FLAG_COLOR, PNG_FORMAT_FLAG_COLOR);
    png.format = PNG_FORMAT_RGB;
    std::string raw(PNG_IMAGE_SIZE(png), '\0');
    EXPECT_TRUE(png_image_finish_read(&png, nullptr, raw.data(), 0, nullptr)) << png.message;
    return {png.width, png.height, raw};
}

} // namespace

TEST(Png, EncodesPixelsRowByRow) {
    Image image(3, 2, {10, 20, 30});
    image.set(2, 1, {255, 0, 128});
    image.set(5, 5, {1, 1, 1}); // outside: ignored
    const auto [width, height, raw] = decode(encodePng(image));
    EXPECT_EQ(width, 3u);
    EXPECT_EQ(height, 2u);
    const std::string row0("\x0a\x14\x1e\x0a\x14\x1e\x0a\x14\x1e", 9);
    const std::string row1("\x0a\x14\x1e\x0a\x14\x1e\xff\x00\x80", 9);
    EXPECT_EQ(raw, row0 + row1);
}

TEST(Png, PlotIsAValidPngWithInk) {
    ExploreResult result;
    result.parameter = "ROCK";
    result.size = {8, 8, 8};
    for (int i = 0; i < 4; ++i) {
        ValueSummary summary;
        summary.value = 0.1 * i;
        summary.runs.resize(2);
        summary.solidFraction = {0.2 + 0.1 * i, 0.02};
        summary.surfaceArea = {1000.0 - 100.0 * i, 30.0};
        summary.iou = MeanDeviation{0.9 - 0.2 * i, 0.05};
        result.values.push_back(summary);
    }
    const Image plot = plotExploration(result, "TEST PLOT");
    const std::string path = (std::filesystem::temp_directory_path() / "voxc_explore_plot_test.png").string();
    writePng(path, plot);
    std::ifstream in(path, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    std::filesystem::remove(path);
    const auto [width, height, raw] = decode(bytes.str());
    EXPECT_EQ(int(width), plot.width);
    EXPECT_EQ(int(height), plot.height);
    // Each series' colour appears (its line and markers were drawn).
    size_t blue = 0, orange = 0, green = 0;
    for (size_t i = 0; i < plot.rgb.size(); i += 3) {
        const Rgb pixel{plot.rgb[i], plot.rgb[i + 1], plot.rgb[i + 2]};
        blue += pixel == Rgb{31, 119, 180};
        orange += pixel == Rgb{230, 110, 10};
        green += pixel == Rgb{44, 150, 44};
    }
    EXPECT_GT(blue, 100u);
    EXPECT_GT(orange, 100u);
    EXPECT_GT(green, 100u);
}
