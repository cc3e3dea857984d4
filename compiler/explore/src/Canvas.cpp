#include "Canvas.h"

#include "BitmapFont.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace voxc::explore {

void fillRect(Image& image, int x0, int y0, int x1, int y1, Rgb color) {
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, image.width - 1);
    y1 = std::min(y1, image.height - 1);
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) image.set(x, y, color);
}

void drawLine(Image& image, int x0, int y0, int x1, int y1, Rgb color, int thickness) {
    const int dx = std::abs(x1 - x0), sx = x0 < x1 ? 1 : -1;
    const int dy = -std::abs(y1 - y0), sy = y0 < y1 ? 1 : -1;
    const int before = (thickness - 1) / 2, after = thickness / 2;
    int error = dx + dy;
    while (true) {
        fillRect(image, x0 - before, y0 - before, x0 + after, y0 + after, color);
        if (x0 == x1 && y0 == y1) break;
        const int twice = 2 * error;
        if (twice >= dy) {
            error += dy;
            x0 += sx;
        }
        if (twice <= dx) {
            error += dx;
            y0 += sy;
        }
    }
}

int textWidth(std::string_view text, int scale) {
    return text.empty() ? 0 : (int(text.size()) * kGlyphAdvance - (kGlyphAdvance - kGlyphWidth)) * scale;
}

int textHeight(int scale) { return kGlyphHeight * scale; }

void drawText(Image& image, int x, int y, std::string_view text, Rgb color, int scale, Align align) {
    if (align == Align::Center) x -= textWidth(text, scale) / 2;
    if (align == Align::Right) x -= textWidth(text, scale);
    for (char c : text) {
        const auto& rows = glyph(c);
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int column = 0; column < kGlyphWidth; ++column)
                if (rows[row] & (0x10 >> column))
                    fillRect(image, x + column * scale, y + row * scale, x + (column + 1) * scale - 1,
                             y + (row + 1) * scale - 1, color);
        x += kGlyphAdvance * scale;
    }
}

Rgb blend(Rgb base, Rgb color, double amount) {
    auto mix = [&](uint8_t a, uint8_t b) { return uint8_t(std::lround(a + (double(b) - a) * amount)); };
    return {mix(base.r, color.r), mix(base.g, color.g), mix(base.b, color.b)};
}

} // namespace voxc::explore
