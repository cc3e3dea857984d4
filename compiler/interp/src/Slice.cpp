#include "voxc/interp/Slice.h"

#include "voxc/core/Errors.h"

#include <cmath>
#include <fmt/format.h>

namespace voxc {

namespace {

char densityChar(float d) {
    if (std::isnan(d)) return '?';
    if (d < 0.0f) return '<';
    if (d == 0.0f) return ' ';
    if (d < 0.25f) return '.';
    if (d < 0.5f) return ':';
    if (d < 1.0f) return '+';
    if (d == 1.0f) return '#';
    return '>';
}

constexpr char kAxisNames[3] = {'x', 'y', 'z'};

} // namespace

std::string renderSlice(const DenseGrid& grid, int axis, int index) {
    if (axis < 0 || axis > 2) throw UserError(fmt::format("slice axis {} is not 0 (x), 1 (y) or 2 (z)", axis));
    const glm::ivec3 size = grid.size();
    if (index < 0 || index >= size[axis])
        throw UserError(fmt::format("slice {}={} is outside the grid (0..{})", kAxisNames[axis], index, size[axis] - 1));
    const int colAxis = axis == 0 ? 1 : 0;
    const int rowAxis = axis == 2 ? 1 : 2;
    // Columns take the lower remaining axis, rows the higher one; for an x layer that is y, z.
    const int cols = size[colAxis];
    const int rows = size[rowAxis];

    std::string out = fmt::format("slice {}={}: columns {} 0..{}, rows {} {}..0 (top row first)\n", kAxisNames[axis],
                                  index, kAxisNames[colAxis], cols - 1, kAxisNames[rowAxis], rows - 1);
    out += "legend: ' ' 0  '.' (0,0.25)  ':' [0.25,0.5)  '+' [0.5,1)  '#' 1  '<' <0  '>' >1  '?' NaN\n";
    const int labelWidth = int(fmt::format("{}", rows - 1).size());
    for (int row = rows - 1; row >= 0; --row) {
        out += fmt::format("{:>{}} |", row, labelWidth);
        for (int col = 0; col < cols; ++col) {
            glm::ivec3 p{0};
            p[axis] = index;
            p[colAxis] = col;
            p[rowAxis] = row;
            out += densityChar(grid.at(p));
        }
        out += "|\n";
    }
    return out;
}

} // namespace voxc
