#include "voxc/interp/Slice.h"

#include "voxc/core/Errors.h"

#include <array>
#include <cctype>
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

// One character per declared material: its name's first letter, else that letter's other case,
// else the first free letter or digit. ' ' and '.' are the slice's own.
std::array<char, 256> materialChars(const Program& program) {
    std::array<char, 256> chars;
    chars.fill('?');
    chars[kMaterialNone] = '.';
    std::string taken = " .?";
    const std::string spare = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    for (const Material& material : program.materials) {
        const char first = material.name.empty() ? 'm' : material.name[0];
        const char lower = char(std::tolower(static_cast<unsigned char>(first)));
        const char upper = char(std::toupper(static_cast<unsigned char>(first)));
        char chosen = 0;
        for (char candidate : {lower, upper})
            if (std::isalnum(static_cast<unsigned char>(candidate)) && taken.find(candidate) == std::string::npos) {
                chosen = candidate;
                break;
            }
        if (chosen == 0)
            for (char candidate : spare)
                if (taken.find(candidate) == std::string::npos) {
                    chosen = candidate;
                    break;
                }
        if (chosen == 0) continue; // more than 62 materials: the rest show as '?'
        chars[material.id] = chosen;
        taken += chosen;
    }
    return chars;
}

} // namespace

std::string renderLayer(glm::ivec3 size, int axis, int index, std::string_view legend,
                        const std::function<char(glm::ivec3)>& cell) {
    if (axis < 0 || axis > 2) throw UserError(fmt::format("slice axis {} is not 0 (x), 1 (y) or 2 (z)", axis));
    if (index < 0 || index >= size[axis])
        throw UserError(fmt::format("slice {}={} is outside the grid (0..{})", kAxisNames[axis], index, size[axis] - 1));
    const int colAxis = axis == 0 ? 1 : 0;
    const int rowAxis = axis == 2 ? 1 : 2;
    // Columns take the lower remaining axis, rows the higher one; for an x layer that is y, z.
    const int cols = size[colAxis];
    const int rows = size[rowAxis];
    std::string out = fmt::format("slice {}={}: columns {} 0..{}, rows {} {}..0 (top row first)\n", kAxisNames[axis],
                                  index, kAxisNames[colAxis], cols - 1, kAxisNames[rowAxis], rows - 1);
    out += fmt::format("{}\n", legend);
    const int labelWidth = int(fmt::format("{}", rows - 1).size());
    for (int row = rows - 1; row >= 0; --row) {
        out += fmt::format("{:>{}} |", row, labelWidth);
        for (int col = 0; col < cols; ++col) {
            glm::ivec3 p{0};
            p[axis] = index;
            p[colAxis] = col;
            p[rowAxis] = row;
            out += cell(p);
        }
        out += "|\n";
    }
    return out;
}

std::string renderSlice(const DenseGrid& grid, int axis, int index) {
    return renderLayer(grid.size(), axis, index,
                       "legend: ' ' 0  '.' (0,0.25)  ':' [0.25,0.5)  '+' [0.5,1)  '#' 1  '<' <0  '>' >1  '?' NaN",
                       [&](glm::ivec3 p) { return densityChar(grid.at(p)); });
}

std::string renderMaterialSlice(const Program& program, const DenseGrid& grid, float iso, int axis, int index) {
    const std::array<char, 256> chars = materialChars(program);
    std::string legend = fmt::format("legend: ' ' not solid (density <= {})  '.' none", iso);
    for (const Material& material : program.materials)
        legend += fmt::format("  '{}' {}", chars[material.id], material.name);
    return renderLayer(grid.size(), axis, index, legend, [&](glm::ivec3 p) {
        return grid.at(p) > iso ? chars[grid.materialAt(p)] : ' ';
    });
}

} // namespace voxc
