#include "voxc/render/CutAway.h"

#include "voxc/core/Errors.h"

#include <charconv>
#include <climits>
#include <fmt/format.h>
#include <optional>

namespace voxc::rendering {

namespace {

std::optional<int> parseInt(std::string_view text) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
    return value;
}

std::optional<glm::ivec3> parseCorner(std::string_view text) {
    glm::ivec3 corner{0};
    for (int axis = 0; axis < 3; ++axis) {
        const size_t comma = axis < 2 ? text.find(',') : text.size();
        if (comma == std::string_view::npos) return std::nullopt;
        const std::optional<int> value = parseInt(text.substr(0, comma));
        if (!value) return std::nullopt;
        corner[axis] = *value;
        text = axis < 2 ? text.substr(comma + 1) : std::string_view{};
    }
    return corner;
}

} // namespace

CutAway parseCutAway(std::string_view spec) {
    const auto refuse = [&](std::string_view why) {
        return UserError(fmt::format("--cut {}: {}; expected x>N, x<N (or y, z) or MINX,MINY,MINZ:MAXX,MAXY,MAXZ "
                                     "(world voxels, max excluded)",
                                     spec, why));
    };
    // Far enough past any grid (2^20 voxels per axis) that a half-space covers it whole.
    constexpr int kBeyond = 1 << 24;
    if (spec.size() >= 3 && (spec[1] == '>' || spec[1] == '<')) {
        const size_t axis = std::string_view("xyz").find(spec[0]);
        const std::optional<int> at = parseInt(spec.substr(2));
        if (axis == std::string_view::npos || !at) throw refuse("not an axis, a comparison and a whole number");
        if (*at <= -kBeyond || *at >= kBeyond) throw refuse("the plane lies beyond every grid");
        CutAway cut{glm::ivec3(-kBeyond), glm::ivec3(kBeyond)};
        if (spec[1] == '>') cut.min[axis] = *at + 1;
        else cut.max[axis] = *at;
        return cut;
    }
    const size_t colon = spec.find(':');
    if (colon == std::string_view::npos) throw refuse("not a plane or a box");
    const std::optional<glm::ivec3> lo = parseCorner(spec.substr(0, colon)), hi = parseCorner(spec.substr(colon + 1));
    if (!lo || !hi) throw refuse("a corner is not three whole numbers");
    if (!glm::all(glm::lessThan(*lo, *hi))) throw refuse("the box is empty; each min must be below its max");
    return {*lo, *hi};
}

size_t applyCutAway(ChunkedGrid& grid, const CutAway& cut) {
    const ChunkLayout& layout = grid.layout();
    const glm::ivec3 lo = glm::max(cut.min - layout.gridOrigin, glm::ivec3(0));
    const glm::ivec3 hi = glm::min(cut.max - layout.gridOrigin, layout.gridSize);
    size_t removed = 0;
    for (int z = lo.z; z < hi.z; ++z)
        for (int y = lo.y; y < hi.y; ++y)
            for (int x = lo.x; x < hi.x; ++x) {
                grid.at({x, y, z}) = 0.0f;
                grid.materialAt({x, y, z}) = kMaterialNone;
                ++removed;
            }
    return removed;
}

} // namespace voxc::rendering
