#include "CheckAggregates.h"

#include "Values.h"

#include "voxc/core/Errors.h"

#include <cmath>
#include <limits>
#include <fmt/format.h>

namespace voxc::check {

namespace {

// The counts a fraction range allows over n cells; products are rounded to 9 decimals first, so
// 0.4 * 15 is 6, not 6.000000000000001.
uint32_t fewestCells(double low, int64_t n) { return uint32_t(std::ceil(std::round(low * double(n) * 1e9) / 1e9)); }
uint32_t mostCells(double high, int64_t n) { return uint32_t(std::floor(std::round(high * double(n) * 1e9) / 1e9)); }

// The largest bound b with float(b * scale) finite: the largest float over scale, rounded down to
// a double whose product with scale stays at or below the largest float.
double largestFiniteBound(double scale) {
    const double largest = std::numeric_limits<float>::max();
    double bound = largest / scale;
    while (bound * scale > largest) bound = std::nextafter(bound, 0.0);
    return bound;
}

// `[low, high]` with low <= high, each within [min, max] (E0010 for another shape, E0007 out of range).
std::optional<std::array<double, 2>> readBounds(Context& context, const ast::Assignment& a,
                                                const std::vector<const ast::Value*>& values, double min, double max,
                                                std::string_view why = "") {
    std::array<double, 2> bounds{};
    for (size_t i = 0; i < 2; ++i) {
        const ast::Value& value = *values[i];
        if (value.isList()) {
            context.diagnostics.error("E0010", value.loc, fmt::format("'{}' expects numbers here", a.key));
            return std::nullopt;
        }
        auto number = context.constants.evaluate(*value.scalar, fmt::format("'{}'", a.key));
        if (!number) return std::nullopt;
        if (!(*number >= min && *number <= max)) {
            context.diagnostics.error("E0007", value.loc,
                                      fmt::format("'{}' bounds lie in [{}, {}]{}, got {}", a.key, formatNumber(min),
                                                  formatNumber(max), why, formatNumber(*number)));
            return std::nullopt;
        }
        bounds[i] = *number;
    }
    if (bounds[0] > bounds[1]) {
        context.diagnostics.error("E0007", a.value.loc,
                                  fmt::format("'{}' is empty: low {} is above high {}", a.key, formatNumber(bounds[0]),
                                              formatNumber(bounds[1])));
        return std::nullopt;
    }
    return bounds;
}

// The elements of a list value, or E0010 naming the expected shape.
std::optional<std::vector<const ast::Value*>> listOf(Context& context, const ast::Assignment& a, size_t count,
                                                     std::string_view shape) {
    if (!a.value.isList() || a.value.elements.size() != count) {
        context.diagnostics.error("E0010", a.value.loc, fmt::format("'{}' expects {}", a.key, shape));
        return std::nullopt;
    }
    std::vector<const ast::Value*> out;
    for (const ast::Value& element : a.value.elements) out.push_back(&element);
    return out;
}

} // namespace

std::vector<AggregateTest> checkWhereBlock(Context& context, const ast::Block& block, glm::ivec3 windowSize,
                                           const std::string& rule) {
    static constexpr std::string_view kKeys[] = {"box", "mean", "min", "max", "solid_fraction", "material_fraction"};
    const std::string where = block.label ? fmt::format("'where {}' of {}", *block.label, rule)
                                          : fmt::format("'where' of {}", rule);
    rejectUnexpectedMembers(context, block, where, {});
    BlockKeys keys(context, block, where, kKeys);

    AggregateTest base;
    base.boxMax = windowSize;
    if (const ast::Assignment* a = keys.find("box")) {
        auto box = readBox(context, *a);
        if (!box) return {};
        const auto [lo, hi] = *box;
        for (int axis = 0; axis < 3; ++axis)
            if (lo[axis] < 0 || hi[axis] > windowSize[axis] || lo[axis] >= hi[axis]) {
                context.diagnostics.error("E0007", a->value.loc,
                                          fmt::format("'box' [{}, {}] must be a non-empty box of the window [[0, 0, 0], {}]",
                                                      formatVec(lo), formatVec(hi), formatVec(windowSize)));
                return {};
            }
        base.boxMin = lo;
        base.boxMax = hi;
    }
    const glm::ivec3 extent = base.boxMax - base.boxMin;
    const int64_t cells = int64_t(extent.x) * extent.y * extent.z;

    std::vector<AggregateTest> tests;
    const auto valueRange = [&](std::string_view key, AggregateKind kind) {
        const ast::Assignment* a = keys.find(key);
        if (!a) return;
        auto values = listOf(context, *a, 2, "[low, high]");
        if (!values) return;
        // The mean's bounds bound the sum of the box's cells: low * n and high * n must be floats
        // too (finite once rounded), so a mean's bounds lie within the largest float over n.
        const double scale = kind == AggregateKind::Mean ? double(cells) : 1.0;
        const double limit = largestFiniteBound(scale);
        const std::string why =
            kind == AggregateKind::Mean
                ? fmt::format(" (their products with the box's {} cells, which bound its sum, must be floats)", cells)
                : std::string();
        auto bounds = readBounds(context, *a, *values, -limit, limit, why);
        if (!bounds) return;
        AggregateTest test = base;
        test.kind = kind;
        test.low = float((*bounds)[0] * scale);
        test.high = float((*bounds)[1] * scale);
        VOXC_ASSERT(std::isfinite(test.low) && std::isfinite(test.high));
        tests.push_back(test);
    };
    valueRange("mean", AggregateKind::Mean);
    valueRange("min", AggregateKind::Min);
    valueRange("max", AggregateKind::Max);
    if (const ast::Assignment* a = keys.find("solid_fraction"))
        if (auto values = listOf(context, *a, 2, "[low, high], fractions of the box's cells"))
            if (auto bounds = readBounds(context, *a, *values, 0.0, 1.0)) {
                AggregateTest test = base;
                test.kind = AggregateKind::SolidFraction;
                test.minCount = fewestCells((*bounds)[0], cells);
                test.maxCount = mostCells((*bounds)[1], cells);
                tests.push_back(test);
            }
    if (const ast::Assignment* a = keys.find("material_fraction"))
        if (auto values = listOf(context, *a, 3, "[material, low, high]")) {
            const ast::Value& name = *(*values)[0];
            std::optional<uint8_t> material =
                name.isList() ? std::nullopt : context.materials.resolve(context.diagnostics, *name.scalar, "a material");
            if (name.isList())
                context.diagnostics.error("E0010", name.loc, "'material_fraction' expects a material name first");
            auto bounds = readBounds(context, *a, {(*values)[1], (*values)[2]}, 0.0, 1.0);
            if (material && bounds) {
                AggregateTest test = base;
                test.kind = AggregateKind::MaterialFraction;
                test.material = *material;
                test.minCount = fewestCells((*bounds)[0], cells);
                test.maxCount = mostCells((*bounds)[1], cells);
                tests.push_back(test);
            }
        }
    if (tests.empty() && block.assignments.size() == (keys.find("box") ? 1u : 0u))
        context.diagnostics.error("E0009", block.loc, fmt::format("{} tests nothing: give mean, min, max, "
                                                                  "solid_fraction or material_fraction", where));
    return tests;
}

} // namespace voxc::check
