#pragma once
// A 5x7 pixel font for plot labels: digits, capital letters and common punctuation. Lower-case
// letters are drawn as capitals; any other character as '?'.
#include <array>
#include <cstdint>

namespace voxc::explore {

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;
constexpr int kGlyphAdvance = 6; // one column of space between glyphs

// Row 0 is the top; bit 4 of a row is its leftmost pixel.
const std::array<uint8_t, kGlyphHeight>& glyph(char c);

} // namespace voxc::explore
