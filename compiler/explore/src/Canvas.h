#pragma once
// Drawing primitives for the plot: rectangles, thick lines and bitmap-font text on an Image.
#include "voxc/explore/Image.h"

#include <string_view>

namespace voxc::explore {

enum class Align { Left, Center, Right };

// Pixels x0..x1, y0..y1 inclusive (either order); clipped to the image.
void fillRect(Image& image, int x0, int y0, int x1, int y1, Rgb color);

// A line of `thickness` pixels (a square brush at every Bresenham step).
void drawLine(Image& image, int x0, int y0, int x1, int y1, Rgb color, int thickness = 1);

// Text in the 5x7 font, each font pixel drawn as scale x scale; `y` is the top of the glyphs and
// `x` the left, centre or right end depending on `align`.
void drawText(Image& image, int x, int y, std::string_view text, Rgb color, int scale, Align align = Align::Left);
int textWidth(std::string_view text, int scale);
int textHeight(int scale);

// `amount` of `color` over `base` (0 = base, 1 = color).
Rgb blend(Rgb base, Rgb color, double amount);

} // namespace voxc::explore
