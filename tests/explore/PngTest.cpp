// The PNG writer's output is a valid PNG: signature, IHDR, CRCs, and IDAT that inflates to the rows.
#include "voxc/explore/Explore.h"
#include "voxc/explore/Plot.h"
#include "voxc/explore/Png.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <zlib.h>

using namespace voxc;
using namespace voxc::explore;

namespace {

uint32_t bigEndian(const std::string& bytes, size_t at) {
    uint32_t value = 0;
    for (size_t i = 0; i < 4; ++i) value = (value << 8) | uint8_t(bytes[at + i]);
    return value;
}

struct Chunk {
    std::string type;
    std::string data;
};

// Splits the file into chunks, checking every CRC.
std::vector<Chunk> readChunks(const std::string& png) {
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    std::vector<Chunk> chunks;
    for (size_t at = 8; at + 12 <= png.size();) {
        const uint32_t length = bigEndian(png, at);
        const std::string typed = png.substr(at + 4, 4 + length);
        const uint32_t crc = bigEndian(png, at + 8 + length);
        EXPECT_EQ(crc, uint32_t(crc32(0, reinterpret_cast<const Bytef*>(typed.data()), uInt(typed.size()))));
        chunks.push_back({typed.substr(0, 4), typed.substr(4)});
        at += 12 + length;
    }
    return chunks;
}

// IHDR width and height, and the inflated image data.
std::tuple<uint32_t, uint32_t, std::string> decode(const std::string& png) {
    const std::vector<Chunk> chunks = readChunks(png);
    EXPECT_GE(chunks.size(), 3u);
    EXPECT_EQ(chunks.front().type, "IHDR");
    EXPECT_EQ(chunks.back().type, "IEND");
    const std::string& header = chunks.front().data;
    EXPECT_EQ(header.size(), 13u);
    EXPECT_EQ(header.substr(8), std::string("\x08\x02\x00\x00\x00", 5)); // 8-bit RGB
    const uint32_t width = bigEndian(header, 0), height = bigEndian(header, 4);
    std::string compressed;
    for (const Chunk& chunk : chunks)
        if (chunk.type == "IDAT") compressed += chunk.data;
    std::string raw(size_t(height) * (1 + 3 * size_t(width)), '\0');
    uLongf rawSize = uLongf(raw.size());
    EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(raw.data()), &rawSize,
                         reinterpret_cast<const Bytef*>(compressed.data()), uLong(compressed.size())),
              Z_OK);
    EXPECT_EQ(rawSize, raw.size());
    return {width, height, raw};
}

} // namespace

TEST(Png, EncodesPixelsRowByRow) {
    Image image(3, 2, {10, 20, 30});
    image.set(2, 1, {255, 0, 128});
    image.set(5, 5, {1, 1, 1}); // outside: ignored
    const auto [width, height, raw] = decode(encodePng(image));
    EXPECT_EQ(width, 3u);
    EXPECT_EQ(height, 2u);
    const std::string row0 = std::string(1, '\0') + std::string("\x0a\x14\x1e\x0a\x14\x1e\x0a\x14\x1e", 9);
    const std::string row1 = std::string(1, '\0') + std::string("\x0a\x14\x1e\x0a\x14\x1e\xff\x00\x80", 9);
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
