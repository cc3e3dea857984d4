#include "voxc/program/PointSet.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>

namespace voxc {

namespace {

// Lists may hold more than they need (a listed point beyond its reach changes no capped
// distance), never less: one voxel of slack covers every float rounding of the distances.
constexpr double kListSlack = 1.0;

int64_t floorDiv(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// The voxel positions of cell `cell`: [lo, hi] per axis.
void cellBox(glm::ivec3 cell, int32_t size, glm::dvec3& lo, glm::dvec3& hi) {
    lo = glm::dvec3(cell) * double(size);
    hi = lo + double(size - 1);
}

double boxDistance(glm::dvec3 p, glm::dvec3 lo, glm::dvec3 hi) {
    return glm::length(glm::max(glm::max(lo - p, p - hi), glm::dvec3(0.0)));
}

double segmentPointDistance(const PointSetSegment& s, glm::dvec3 p) {
    const glm::dvec3 a(s.from), d(s.delta);
    const double len2 = glm::dot(d, d);
    const double t = len2 > 0 ? std::clamp(glm::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * d));
}

// Whether a segment may come within `reach` of the box [lo, hi]: its distance to the box's
// centre against the reach plus the box's half diagonal.
bool segmentNearBox(const PointSetSegment& s, glm::dvec3 lo, glm::dvec3 hi, double reach) {
    const glm::dvec3 centre = (lo + hi) * 0.5;
    return segmentPointDistance(s, centre) <= reach + kListSlack + glm::length(hi - centre);
}

bool centreNearBox(glm::vec3 c, glm::dvec3 lo, glm::dvec3 hi, double reach) {
    return boxDistance(glm::dvec3(c), lo, hi) <= reach + kListSlack;
}

// Cells lo .. hi (inclusive, clipped to the bins) of the world box [boxLo, boxHi].
bool cellRange(const PointBins& bins, glm::dvec3 boxLo, glm::dvec3 boxHi, glm::ivec3& lo, glm::ivec3& hi) {
    for (int a = 0; a < 3; ++a) {
        const double first = std::floor(boxLo[a] / bins.cellSize), last = std::floor(boxHi[a] / bins.cellSize);
        const double gridFirst = bins.firstCell[a], gridLast = double(bins.firstCell[a]) + bins.cellCount[a] - 1;
        if (!(last >= gridFirst && first <= gridLast)) return false;
        lo[a] = int32_t(std::max(first, gridFirst));
        hi[a] = int32_t(std::min(last, gridLast));
    }
    return true;
}

size_t cellIndex(const PointBins& bins, glm::ivec3 cell) {
    const glm::ivec3 i = cell - bins.firstCell;
    return size_t(i.x) + size_t(bins.cellCount.x) * (size_t(i.y) + size_t(bins.cellCount.y) * size_t(i.z));
}

// Fills one kind's CSR lists: `near(item, lo, hi)` decides per cell of the item's bounding box.
template <typename Bounds, typename Near>
void fillLists(PointBins& bins, size_t count, Bounds bounds, Near near, std::vector<uint32_t>& start,
               std::vector<uint32_t>& items, uint64_t& entries, uint64_t maxEntries, uint32_t maxPerCell) {
    const size_t cells = size_t(bins.cells());
    std::vector<uint32_t> perCell(cells, 0);
    const auto visit = [&](auto&& onCell) {
        for (size_t item = 0; item < count; ++item) {
            glm::dvec3 boxLo, boxHi;
            bounds(item, boxLo, boxHi);
            glm::ivec3 lo, hi;
            if (!cellRange(bins, boxLo, boxHi, lo, hi)) continue;
            for (int z = lo.z; z <= hi.z; ++z)
                for (int y = lo.y; y <= hi.y; ++y)
                    for (int x = lo.x; x <= hi.x; ++x) {
                        glm::dvec3 cLo, cHi;
                        cellBox({x, y, z}, bins.cellSize, cLo, cHi);
                        if (near(item, cLo, cHi)) onCell(cellIndex(bins, {x, y, z}), uint32_t(item));
                    }
        }
    };
    visit([&](size_t cell, uint32_t) {
        if (++entries > maxEntries) throw PointSetLimitError{"entries", entries, maxEntries};
        if (++perCell[cell] > maxPerCell) throw PointSetLimitError{"perCell", perCell[cell], maxPerCell};
    });
    start.assign(cells + 1, 0);
    for (size_t i = 0; i < cells; ++i) start[i + 1] = start[i] + perCell[i];
    items.resize(start[cells]);
    std::vector<uint32_t> next(start.begin(), start.end() - 1);
    visit([&](size_t cell, uint32_t item) { items[next[cell]++] = item; });
}

} // namespace

uint32_t PointBins::largestList() const {
    uint32_t most = 0;
    for (size_t i = 0; i + 1 < centreStart.size(); ++i) most = std::max(most, centreStart[i + 1] - centreStart[i]);
    for (size_t i = 0; i + 1 < segmentStart.size(); ++i) most = std::max(most, segmentStart[i + 1] - segmentStart[i]);
    return most;
}

float centreDistanceSquared(glm::vec3 p, glm::vec3 centre) {
    const float dx = p.x - centre.x, dy = p.y - centre.y, dz = p.z - centre.z;
    return dx * dx + dy * dy + dz * dz;
}

float segmentDistanceSquared(glm::vec3 p, const PointSetSegment& s) {
    const float px = p.x - s.from.x, py = p.y - s.from.y, pz = p.z - s.from.z;
    const float along = (px * s.delta.x + py * s.delta.y + pz * s.delta.z) * s.inverseLengthSquared;
    const float t = along < 0.0f ? 0.0f : (along > 1.0f ? 1.0f : along);
    const float dx = px - t * s.delta.x, dy = py - t * s.delta.y, dz = pz - t * s.delta.z;
    return dx * dx + dy * dy + dz * dz;
}

PointBins binPointSet(const PointSet& set, glm::ivec3 firstCell, glm::ivec3 cellCount, int32_t cellSize,
                      uint64_t maxEntries, uint32_t maxPerCell) {
    PointBins bins;
    bins.firstCell = firstCell;
    bins.cellCount = cellCount;
    bins.cellSize = cellSize;
    uint64_t entries = 0;
    const double centreReach = set.centreReach, segmentReach = set.segmentReach;
    fillLists(
        bins, set.centres.size(),
        [&](size_t i, glm::dvec3& lo, glm::dvec3& hi) {
            lo = glm::dvec3(set.centres[i]) - (centreReach + kListSlack);
            hi = glm::dvec3(set.centres[i]) + (centreReach + kListSlack);
        },
        [&](size_t i, glm::dvec3 lo, glm::dvec3 hi) { return centreNearBox(set.centres[i], lo, hi, centreReach); },
        bins.centreStart, bins.centreItems, entries, maxEntries, maxPerCell);
    fillLists(
        bins, set.segments.size(),
        [&](size_t i, glm::dvec3& lo, glm::dvec3& hi) {
            const glm::dvec3 a(set.segments[i].from), b = a + glm::dvec3(set.segments[i].delta);
            lo = glm::min(a, b) - (segmentReach + kListSlack);
            hi = glm::max(a, b) + (segmentReach + kListSlack);
        },
        [&](size_t i, glm::dvec3 lo, glm::dvec3 hi) { return segmentNearBox(set.segments[i], lo, hi, segmentReach); },
        bins.segmentStart, bins.segmentItems, entries, maxEntries, maxPerCell);
    return bins;
}

glm::vec2 pointSetDistances(const PointSet& set, const PointBins& bins, glm::vec3 p) {
    glm::ivec3 cell;
    for (int a = 0; a < 3; ++a) {
        cell[a] = int32_t(floorDiv(int64_t(std::floor(p[a])), bins.cellSize));
        if (cell[a] < bins.firstCell[a] || cell[a] >= bins.firstCell[a] + bins.cellCount[a])
            return {set.centreReach, set.segmentReach};
    }
    const size_t index = cellIndex(bins, cell);
    float nearestCentre = std::numeric_limits<float>::max(), nearestSegment = std::numeric_limits<float>::max();
    for (uint32_t i = bins.centreStart[index]; i < bins.centreStart[index + 1]; ++i) {
        const float d2 = centreDistanceSquared(p, set.centres[bins.centreItems[i]]);
        nearestCentre = d2 < nearestCentre ? d2 : nearestCentre;
    }
    for (uint32_t i = bins.segmentStart[index]; i < bins.segmentStart[index + 1]; ++i) {
        const float d2 = segmentDistanceSquared(p, set.segments[bins.segmentItems[i]]);
        nearestSegment = d2 < nearestSegment ? d2 : nearestSegment;
    }
    const float centre = std::sqrt(nearestCentre), segment = std::sqrt(nearestSegment);
    return {centre < set.centreReach ? centre : set.centreReach, segment < set.segmentReach ? segment : set.segmentReach};
}

glm::bvec2 pointSetReaches(const PointSet& set, glm::dvec3 lo, glm::dvec3 hi) {
    const PointBins& bins = set.bins;
    glm::ivec3 cellLo, cellHi;
    bool covered = cellRange(bins, lo, hi, cellLo, cellHi);
    for (int a = 0; a < 3 && covered; ++a) // the box must lie inside the bins' cells for them to decide
        covered = lo[a] >= double(bins.firstCell[a]) * bins.cellSize &&
                  hi[a] <= (double(bins.firstCell[a]) + bins.cellCount[a]) * bins.cellSize - 1;
    if (covered) {
        glm::bvec2 reaches(false);
        for (int z = cellLo.z; z <= cellHi.z; ++z)
            for (int y = cellLo.y; y <= cellHi.y; ++y)
                for (int x = cellLo.x; x <= cellHi.x; ++x) {
                    const size_t i = cellIndex(bins, {x, y, z});
                    reaches.x = reaches.x || bins.centreStart[i + 1] > bins.centreStart[i];
                    reaches.y = reaches.y || bins.segmentStart[i + 1] > bins.segmentStart[i];
                }
        return reaches;
    }
    glm::bvec2 reaches(false);
    for (glm::vec3 c : set.centres) reaches.x = reaches.x || centreNearBox(c, lo, hi, set.centreReach);
    for (const PointSetSegment& s : set.segments) reaches.y = reaches.y || segmentNearBox(s, lo, hi, set.segmentReach);
    return reaches;
}

std::vector<int32_t> pointSetWords(std::span<const std::shared_ptr<const PointSet>> sets, glm::ivec3 firstChunk,
                                   glm::ivec3 chunkCount, int32_t chunkSize) {
    constexpr uint64_t kMaxWords = uint64_t(1) << 31;
    std::vector<int32_t> words(sets.size(), 0);
    const auto append = [&](int32_t value) {
        if (words.size() + 1 > kMaxWords) throw PointSetLimitError{"words", words.size() + 1, kMaxWords};
        words.push_back(value);
    };
    const auto appendFloat = [&](float value) { append(std::bit_cast<int32_t>(value)); };
    uint64_t entries = 0;
    for (size_t s = 0; s < sets.size(); ++s) {
        const PointSet& set = *sets[s];
        const PointBins bins = binPointSet(set, firstChunk, chunkCount, chunkSize, kMaxPointSetListEntries - entries,
                                           kMaxPointSetPerCell);
        entries += bins.centreItems.size() + bins.segmentItems.size();
        const size_t header = words.size();
        words[s] = int32_t(header);
        for (int i = 0; i < 5; ++i) append(0);
        words[header] = int32_t(words.size());
        for (glm::vec3 c : set.centres) appendFloat(c.x), appendFloat(c.y), appendFloat(c.z);
        words[header + 1] = int32_t(words.size());
        for (const PointSetSegment& g : set.segments) {
            for (int a = 0; a < 3; ++a) appendFloat(g.from[a]);
            for (int a = 0; a < 3; ++a) appendFloat(g.delta[a]);
            appendFloat(g.inverseLengthSquared);
        }
        const size_t centreItems = words.size();
        for (uint32_t item : bins.centreItems) append(int32_t(item));
        const size_t segmentItems = words.size();
        for (uint32_t item : bins.segmentItems) append(int32_t(item));
        words[header + 2] = int32_t(words.size());
        for (size_t cell = 0; cell < size_t(bins.cells()); ++cell) {
            append(int32_t(centreItems + bins.centreStart[cell]));
            append(int32_t(bins.centreStart[cell + 1] - bins.centreStart[cell]));
            append(int32_t(segmentItems + bins.segmentStart[cell]));
            append(int32_t(bins.segmentStart[cell + 1] - bins.segmentStart[cell]));
        }
        words[header + 3] = std::bit_cast<int32_t>(set.centreReach);
        words[header + 4] = std::bit_cast<int32_t>(set.segmentReach);
    }
    if (words.empty()) words.push_back(0); // a storage buffer may not be empty
    return words;
}

} // namespace voxc
