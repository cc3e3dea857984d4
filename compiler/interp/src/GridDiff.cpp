#include "voxc/interp/GridDiff.h"

#include "voxc/core/Errors.h"
#include "voxc/interp/Slice.h"

#include <algorithm>
#include <bit>
#include <glm/common.hpp>
#include <fmt/format.h>
#include <vector>

namespace voxc {

const char* changeKindName(ChangeKind kind) {
    switch (kind) {
    case ChangeKind::None: return "unchanged";
    case ChangeKind::Carved: return "carved";
    case ChangeKind::Filled: return "filled";
    case ChangeKind::MaterialChanged: return "material changed";
    case ChangeKind::DensityChanged: return "density changed";
    }
    return "unchanged";
}

ChangeKind classifyChange(float densityBefore, uint8_t materialBefore, float densityAfter, uint8_t materialAfter,
                          float iso) {
    const bool solidBefore = densityBefore > iso;
    const bool solidAfter = densityAfter > iso;
    if (solidBefore && !solidAfter) return ChangeKind::Carved;
    if (!solidBefore && solidAfter) return ChangeKind::Filled;
    if (materialBefore != materialAfter) return ChangeKind::MaterialChanged;
    // Bits, not values: the interpreter and the device agree bit for bit, and so does the report.
    if (std::bit_cast<uint32_t>(densityBefore) != std::bit_cast<uint32_t>(densityAfter))
        return ChangeKind::DensityChanged;
    return ChangeKind::None;
}

GridDiff diffGrids(const DenseGrid& before, const DenseGrid& after, float iso) {
    VOXC_ASSERT(before.size() == after.size());
    const glm::ivec3 size = after.size();
    GridDiff diff;
    diff.iso = iso;
    diff.min = size;
    diff.max = glm::ivec3(-1);
    std::vector<uint64_t> perLayer(size_t(size.y), 0);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const glm::ivec3 p(x, y, z);
                const size_t i = after.index(p);
                const uint8_t from = before.materials()[i];
                const uint8_t to = after.materials()[i];
                const ChangeKind kind = classifyChange(before.data()[i], from, after.data()[i], to, iso);
                if (kind == ChangeKind::None) continue;
                ++diff.changed;
                ++diff.counts[size_t(kind)][kind == ChangeKind::Carved ? from : to];
                if (kind == ChangeKind::MaterialChanged) ++diff.materialChanges[{from, to}];
                ++perLayer[size_t(y)];
                diff.min = glm::min(diff.min, p);
                diff.max = glm::max(diff.max, p);
            }
    diff.busiestY = int(std::max_element(perLayer.begin(), perLayer.end()) - perLayer.begin());
    return diff;
}

namespace {

std::string materialName(const Program& program, uint8_t id) {
    if (id == kMaterialNone) return "none";
    const Material* material = program.findMaterial(id);
    return material ? material->name : fmt::format("material{}", id);
}

} // namespace

std::string formatGridDiff(const Program& program, const GridDiff& diff) {
    if (diff.changed == 0) return "changed voxels: none (the stage left every voxel's density and material as it was)\n";
    std::string out = fmt::format("changed voxels: {} (solid: density > {})\n", diff.changed, diff.iso);
    for (size_t kind = size_t(ChangeKind::Carved); kind < kChangeKinds; ++kind) {
        uint64_t total = 0;
        for (uint64_t count : diff.counts[kind]) total += count;
        if (total == 0) continue;
        const ChangeKind changeKind = ChangeKind(kind);
        std::string line = fmt::format("  {:<18}{}", std::string(changeKindName(changeKind)) + ":", total);
        if (changeKind == ChangeKind::MaterialChanged) {
            std::string pairs;
            for (const auto& [change, count] : diff.materialChanges)
                pairs += fmt::format("{}{} -> {} {}", pairs.empty() ? "" : ", ", materialName(program, change.first),
                                     materialName(program, change.second), count);
            line += fmt::format(" ({})", pairs);
        } else {
            std::string byMaterial;
            for (size_t id = 0; id < 256; ++id)
                if (diff.counts[kind][id] != 0)
                    byMaterial += fmt::format("{}{} {}", byMaterial.empty() ? "" : ", ",
                                              materialName(program, uint8_t(id)), diff.counts[kind][id]);
            line += fmt::format(" ({} {})", changeKind == ChangeKind::Carved ? "was" : "now", byMaterial);
        }
        out += line + "\n";
    }
    out += fmt::format("  box of the change: ({},{},{})..({},{},{}) inclusive, grid voxels; {}x{}x{}\n", diff.min.x,
                       diff.min.y, diff.min.z, diff.max.x, diff.max.y, diff.max.z, diff.max.x - diff.min.x + 1,
                       diff.max.y - diff.min.y + 1, diff.max.z - diff.min.z + 1);
    return out;
}

std::string renderDiffSlice(const DenseGrid& before, const DenseGrid& after, float iso, int axis, int index) {
    VOXC_ASSERT(before.size() == after.size());
    return renderLayer(after.size(), axis, index,
                       "legend: ' ' unchanged, not solid  '#' unchanged, solid  '-' carved  '+' filled  'm' material "
                       "changed  '~' density changed",
                       [&](glm::ivec3 p) {
                           const size_t i = after.index(p);
                           switch (classifyChange(before.data()[i], before.materials()[i], after.data()[i],
                                                  after.materials()[i], iso)) {
                           case ChangeKind::None: return after.data()[i] > iso ? '#' : ' ';
                           case ChangeKind::Carved: return '-';
                           case ChangeKind::Filled: return '+';
                           case ChangeKind::MaterialChanged: return 'm';
                           case ChangeKind::DensityChanged: return '~';
                           }
                           return '?';
                       });
}

} // namespace voxc
