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

// A lower bound of a segment's distance to the box [lo, hi]: its distance to the box's centre
// less the half diagonal.
double segmentBoxLowerBound(const PointSetSegment& s, glm::dvec3 lo, glm::dvec3 hi) {
    const glm::dvec3 centre = (lo + hi) * 0.5;
    return std::max(0.0, segmentPointDistance(s, centre) - glm::length(hi - centre));
}

// The lower bound as stored: shrunk below every float computation of a distance the backends
// can make (relative error far below 1e-5 of the coordinates involved), squared, rounded down.
float storedLowerBound(double distance, double magnitude) {
    const double shrunk = std::max(0.0, distance * (1.0 - 1e-5) - 1e-4 * (1.0 + magnitude));
    const float squared = float(shrunk * shrunk);
    return double(squared) > shrunk * shrunk ? std::nextafter(squared, 0.0f) : squared;
}

double magnitudeOf(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const auto largest = [](glm::dvec3 v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); };
    return largest(a) + largest(b) + largest(c);
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

// The boxes outside which centre (segment) i of `set` cannot reach, widened by `slack`.
void centreBox(const PointSet& set, size_t i, double slack, glm::dvec3& lo, glm::dvec3& hi) {
    const double reach = double(set.centreReach) / set.centreScales[i] + slack;
    lo = glm::dvec3(set.centres[i]) - reach;
    hi = glm::dvec3(set.centres[i]) + reach;
}

void segmentBox(const PointSet& set, size_t i, double slack, glm::dvec3& lo, glm::dvec3& hi) {
    const glm::dvec3 a(set.segments[i].from), b = a + glm::dvec3(set.segments[i].delta);
    lo = glm::min(a, b) - (double(set.segmentReach) + slack);
    hi = glm::max(a, b) + (double(set.segmentReach) + slack);
}

size_t cellIndex(const PointBins& bins, glm::ivec3 cell) {
    const glm::ivec3 i = cell - bins.firstCell;
    return size_t(i.x) + size_t(bins.cellCount.x) * (size_t(i.y) + size_t(bins.cellCount.y) * size_t(i.z));
}

// Fills one kind's CSR lists: `bounds` gives an item's bounding box (reach included), `lowerBound`
// its distance bound to a cell box, listed when within reach (plus slack); lists sorted.
template <typename Bounds, typename LowerBound, typename Scale>
void fillLists(PointBins& bins, size_t count, double reach, Bounds bounds, LowerBound lowerBound, Scale scaleOf,
               std::vector<uint32_t>& start, std::vector<PointListItem>& items, uint64_t& entries,
               uint64_t maxEntries, uint32_t maxPerCell) {
    const size_t cells = size_t(bins.cells());
    // The cells tested, counted from the bounding boxes before testing any: a long diagonal
    // segment's box holds far more cells than it lists, so entries alone would not bound the work.
    uint64_t tests = 0;
    for (size_t item = 0; item < count; ++item) {
        glm::dvec3 boxLo, boxHi;
        bounds(item, boxLo, boxHi);
        glm::ivec3 lo, hi;
        if (!cellRange(bins, boxLo, boxHi, lo, hi)) continue;
        tests += uint64_t(hi.x - lo.x + 1) * uint64_t(hi.y - lo.y + 1) * uint64_t(hi.z - lo.z + 1);
        if (tests > kMaxPointSetCellTests) throw PointSetLimitError{"cellTests", tests, kMaxPointSetCellTests};
    }
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
                        const double scale = scaleOf(item);
                        const double bound = lowerBound(item, cLo, cHi);
                        if (bound * scale <= reach + kListSlack * scale)
                            onCell(cellIndex(bins, {x, y, z}), uint32_t(item), bound * scale,
                                   magnitudeOf(boxLo, boxHi, cLo) * std::max(scale, 1.0));
                    }
        }
    };
    visit([&](size_t cell, uint32_t, double, double) {
        if (++entries > maxEntries) throw PointSetLimitError{"entries", entries, maxEntries};
        if (++perCell[cell] > maxPerCell) throw PointSetLimitError{"perCell", perCell[cell], maxPerCell};
    });
    start.assign(cells + 1, 0);
    for (size_t i = 0; i < cells; ++i) start[i + 1] = start[i] + perCell[i];
    items.resize(start[cells]);
    std::vector<uint32_t> next(start.begin(), start.end() - 1);
    visit([&](size_t cell, uint32_t item, double bound, double magnitude) {
        items[next[cell]++] = {item, storedLowerBound(bound, magnitude)};
    });
    for (size_t i = 0; i < cells; ++i)
        std::sort(items.begin() + start[i], items.begin() + start[i + 1], [](const PointListItem& a, const PointListItem& b) {
            return a.lowerBoundSquared != b.lowerBoundSquared ? a.lowerBoundSquared < b.lowerBoundSquared : a.index < b.index;
        });
}

// The nearest squared distance over one sorted list: a point whose lower bound is not below the
// nearest so far cannot be nearer (the bound is below its float distance), nor can any after it.
template <typename Distance>
float nearestSquared(const std::vector<PointListItem>& items, uint32_t begin, uint32_t end, Distance distance) {
    float nearest = std::numeric_limits<float>::max();
    for (uint32_t i = begin; i < end; ++i) {
        if (items[i].lowerBoundSquared >= nearest) break;
        const float d2 = distance(items[i].index);
        nearest = d2 < nearest ? d2 : nearest;
    }
    return nearest;
}

} // namespace

float centreDistanceSquared(glm::vec3 p, glm::vec3 centre, float scale) {
    const float dx = p.x - centre.x, dy = p.y - centre.y, dz = p.z - centre.z;
    return (dx * dx + dy * dy + dz * dz) * (scale * scale);
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
    const uint64_t cells = uint64_t(cellCount.x) * uint64_t(cellCount.y) * uint64_t(cellCount.z);
    if (cells > kMaxPointSetCells) throw PointSetLimitError{"cells", cells, kMaxPointSetCells};
    PointBins bins;
    bins.firstCell = firstCell;
    bins.cellCount = cellCount;
    bins.cellSize = cellSize;
    uint64_t entries = 0;
    const double centreReach = set.centreReach, segmentReach = set.segmentReach;
    fillLists(
        bins, set.centres.size(), centreReach,
        [&](size_t i, glm::dvec3& lo, glm::dvec3& hi) { centreBox(set, i, kListSlack, lo, hi); },
        [&](size_t i, glm::dvec3 lo, glm::dvec3 hi) { return boxDistance(glm::dvec3(set.centres[i]), lo, hi); },
        [&](size_t i) { return double(set.centreScales[i]); }, bins.centreStart, bins.centreItems, entries,
        maxEntries, maxPerCell);
    fillLists(
        bins, set.segments.size(), segmentReach,
        [&](size_t i, glm::dvec3& lo, glm::dvec3& hi) { segmentBox(set, i, kListSlack, lo, hi); },
        [&](size_t i, glm::dvec3 lo, glm::dvec3 hi) { return segmentBoxLowerBound(set.segments[i], lo, hi); },
        [](size_t) { return 1.0; }, bins.segmentStart, bins.segmentItems, entries, maxEntries, maxPerCell);
    return bins;
}

PointBins binPointSetOverGrid(const PointSet& set, glm::ivec3 gridOrigin, glm::ivec3 gridSize, uint64_t maxEntries,
                              uint32_t maxPerCell) {
    glm::ivec3 first, count;
    for (int a = 0; a < 3; ++a) {
        first[a] = int32_t(floorDiv(gridOrigin[a], kPointSetCellSize));
        count[a] = int32_t(floorDiv(int64_t(gridOrigin[a]) + gridSize[a] - 1, kPointSetCellSize) - first[a] + 1);
    }
    return binPointSet(set, first, count, kPointSetCellSize, maxEntries, maxPerCell);
}

glm::vec2 pointSetDistances(const PointSet& set, const PointBins& bins, glm::vec3 p) {
    glm::ivec3 cell;
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
        cell[a] = int32_t(floorDiv(int64_t(std::floor(p[a])), bins.cellSize));
        inside = inside && cell[a] >= bins.firstCell[a] && cell[a] < bins.firstCell[a] + bins.cellCount[a];
    }
    float nearestCentre = std::numeric_limits<float>::max(), nearestSegment = nearestCentre;
    if (inside) {
        const size_t index = cellIndex(bins, cell);
        nearestCentre = nearestSquared(bins.centreItems, bins.centreStart[index], bins.centreStart[index + 1],
                                       [&](uint32_t i) { return centreDistanceSquared(p, set.centres[i], set.centreScales[i]); });
        nearestSegment = nearestSquared(bins.segmentItems, bins.segmentStart[index], bins.segmentStart[index + 1],
                                        [&](uint32_t i) { return segmentDistanceSquared(p, set.segments[i]); });
    } else { // outside the binned grid (a grid changed after checking): every point, the same floats
        for (size_t i = 0; i < set.centres.size(); ++i) {
            const float d2 = centreDistanceSquared(p, set.centres[i], set.centreScales[i]);
            nearestCentre = d2 < nearestCentre ? d2 : nearestCentre;
        }
        for (const PointSetSegment& s : set.segments) {
            const float d2 = segmentDistanceSquared(p, s);
            nearestSegment = d2 < nearestSegment ? d2 : nearestSegment;
        }
    }
    const float centre = std::sqrt(nearestCentre), segment = std::sqrt(nearestSegment);
    return {centre < set.centreReach ? centre : set.centreReach, segment < set.segmentReach ? segment : set.segmentReach};
}

bool pointSetClearance(const PointSet& set, glm::vec3 p) {
    return pointSetDistances(set, set.bins, p).y < set.clearance;
}

glm::bvec2 pointSetReaches(const PointSet& set, glm::dvec3 lo, glm::dvec3 hi) {
    const PointBins& bins = set.bins;
    glm::ivec3 cellLo, cellHi;
    bool covered = cellRange(bins, lo, hi, cellLo, cellHi);
    for (int a = 0; a < 3 && covered; ++a) // the box must lie inside the bins' cells for them to decide
        covered = lo[a] >= double(bins.firstCell[a]) * bins.cellSize &&
                  hi[a] <= (double(bins.firstCell[a]) + bins.cellCount[a]) * bins.cellSize - 1;
    glm::bvec2 reaches(false);
    if (covered) {
        for (int z = cellLo.z; z <= cellHi.z; ++z)
            for (int y = cellLo.y; y <= cellHi.y; ++y)
                for (int x = cellLo.x; x <= cellHi.x; ++x) {
                    const size_t i = cellIndex(bins, {x, y, z});
                    reaches.x = reaches.x || bins.centreStart[i + 1] > bins.centreStart[i];
                    reaches.y = reaches.y || bins.segmentStart[i + 1] > bins.segmentStart[i];
                }
        return reaches;
    }
    for (size_t i = 0; i < set.centres.size(); ++i)
        reaches.x = reaches.x || boxDistance(glm::dvec3(set.centres[i]), lo, hi) * set.centreScales[i] <=
                                     set.centreReach + kListSlack * set.centreScales[i];
    for (const PointSetSegment& s : set.segments)
        reaches.y = reaches.y || segmentBoxLowerBound(s, lo, hi) <= set.segmentReach + kListSlack;
    return reaches;
}

std::shared_ptr<PointSet> movedPointSet(const PointSet& set, glm::dvec3 by) {
    auto moved = std::make_shared<PointSet>(set);
    moved->bins = {};
    for (glm::vec3& centre : moved->centres) centre = glm::vec3(glm::dvec3(centre) + by);
    for (PointSetSegment& segment : moved->segments) segment.from = glm::vec3(glm::dvec3(segment.from) + by);
    return moved;
}

bool pointSetSupport(const PointSet& set, glm::dvec3& lo, glm::dvec3& hi) {
    lo = glm::dvec3(std::numeric_limits<double>::max());
    hi = -lo;
    const auto widen = [&](glm::dvec3 itemLo, glm::dvec3 itemHi) { lo = glm::min(lo, itemLo), hi = glm::max(hi, itemHi); };
    glm::dvec3 itemLo, itemHi;
    for (size_t i = 0; i < set.centres.size(); ++i) centreBox(set, i, 0.0, itemLo, itemHi), widen(itemLo, itemHi);
    for (size_t i = 0; i < set.segments.size(); ++i) segmentBox(set, i, 0.0, itemLo, itemHi), widen(itemLo, itemHi);
    return !set.centres.empty() || !set.segments.empty();
}

std::vector<int32_t> pointSetWords(std::span<const std::shared_ptr<const PointSet>> sets, glm::ivec3 gridOrigin,
                                   glm::ivec3 gridSize) {
    constexpr uint64_t kMaxWords = uint64_t(1) << 31;
    constexpr int kHeaderWords = 13;
    std::vector<int32_t> words(sets.size(), 0);
    const auto append = [&](int32_t value) {
        if (words.size() + 1 > kMaxWords) throw PointSetLimitError{"words", words.size() + 1, kMaxWords};
        words.push_back(value);
    };
    const auto appendFloat = [&](float value) { append(std::bit_cast<int32_t>(value)); };
    uint64_t entries = 0;
    for (size_t s = 0; s < sets.size(); ++s) {
        const PointSet& set = *sets[s];
        const PointBins bins =
            set.binnedInFrame
                ? set.bins
                : binPointSetOverGrid(set, gridOrigin, gridSize, kMaxPointSetListEntries - entries, kMaxPointSetPerCell);
        entries += bins.centreItems.size() + bins.segmentItems.size();
        if (entries > kMaxPointSetListEntries) throw PointSetLimitError{"entries", entries, kMaxPointSetListEntries};
        const size_t header = words.size();
        words[s] = int32_t(header);
        for (int i = 0; i < kHeaderWords; ++i) append(0);
        words[header] = int32_t(words.size());
        for (size_t i = 0; i < set.centres.size(); ++i) {
            for (int a = 0; a < 3; ++a) appendFloat(set.centres[i][a]);
            appendFloat(set.centreScales[i]);
        }
        words[header + 1] = int32_t(words.size());
        for (const PointSetSegment& g : set.segments) {
            for (int a = 0; a < 3; ++a) appendFloat(g.from[a]);
            for (int a = 0; a < 3; ++a) appendFloat(g.delta[a]);
            appendFloat(g.inverseLengthSquared);
        }
        const size_t centreItems = words.size();
        for (const PointListItem& item : bins.centreItems) append(int32_t(item.index)), appendFloat(item.lowerBoundSquared);
        const size_t segmentItems = words.size();
        for (const PointListItem& item : bins.segmentItems) append(int32_t(item.index)), appendFloat(item.lowerBoundSquared);
        words[header + 2] = int32_t(words.size());
        for (size_t cell = 0; cell < size_t(bins.cells()); ++cell) {
            append(int32_t(centreItems + 2 * bins.centreStart[cell]));
            append(int32_t(bins.centreStart[cell + 1] - bins.centreStart[cell]));
            append(int32_t(segmentItems + 2 * bins.segmentStart[cell]));
            append(int32_t(bins.segmentStart[cell + 1] - bins.segmentStart[cell]));
        }
        words[header + 3] = std::bit_cast<int32_t>(set.centreReach);
        words[header + 4] = std::bit_cast<int32_t>(set.segmentReach);
        words[header + 12] = std::bit_cast<int32_t>(set.clearance);
        words[header + 5] = std::countr_zero(uint32_t(bins.cellSize));
        for (int a = 0; a < 3; ++a) {
            words[header + 6 + a] = bins.firstCell[a];
            words[header + 9 + a] = bins.cellCount[a];
        }
    }
    if (words.empty()) words.push_back(0); // a storage buffer may not be empty
    return words;
}

uint64_t pointSetLookupIterations(const PointBins& bins, uint32_t block) {
    uint64_t centres = 0, segments = 0;
    for (size_t cell = 0; cell + 1 < bins.centreStart.size(); ++cell)
        centres = std::max<uint64_t>(centres, bins.centreStart[cell + 1] - bins.centreStart[cell]);
    for (size_t cell = 0; cell + 1 < bins.segmentStart.size(); ++cell)
        segments = std::max<uint64_t>(segments, bins.segmentStart[cell + 1] - bins.segmentStart[cell]);
    return (centres + block - 1) / block + 1 + (segments + block - 1) / block + 1;
}

} // namespace voxc
