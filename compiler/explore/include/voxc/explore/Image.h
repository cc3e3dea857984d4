#pragma once
// An 8-bit RGB raster, top row first, the plot's canvas and the PNG writer's input.
#include <cstdint>
#include <vector>

namespace voxc::explore {

struct Rgb {
    uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Rgb&) const = default;
};

struct Image {
    Image(int width, int height, Rgb fill);
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgb; // 3 bytes per pixel, x fastest

    bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
    Rgb at(int x, int y) const;
    void set(int x, int y, Rgb color); // ignores pixels outside
};

} // namespace voxc::explore
