#include "Values.h"

#include "Suggest.h"

#include "voxc/check/KeyRanges.h"
#include "voxc/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace voxc::check {

std::string formatNumber(double v) { return fmt::format("{}", v); }

std::string formatVec(glm::ivec3 v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

BlockKeys::BlockKeys(Context& context, const ast::Block& block, std::string where,
                     std::span<const std::string_view> known)
    : context_(context), block_(block), where_(std::move(where)) {
    for (const ast::Assignment& a : block.assignments) {
        bool isKnown = std::find(known.begin(), known.end(), a.key) != known.end();
        if (!isKnown) {
            context.diagnostics.error("E0008", a.loc,
                                      fmt::format("unknown key '{}' in {}{}", a.key, where_, didYouMean(a.key, known)));
            continue;
        }
        if (const ast::Assignment* first = find(a.key)) {
            context.diagnostics.error("E0003", a.loc, fmt::format("'{}' is set twice in {}", a.key, where_),
                                      {{first->loc, "first set here"}});
            continue;
        }
        assignments_.push_back(&a);
    }
}

const ast::Assignment* BlockKeys::find(std::string_view key) const {
    for (const ast::Assignment* a : assignments_)
        if (a->key == key) return a;
    return nullptr;
}

const ast::Assignment* BlockKeys::require(std::string_view key) const {
    const ast::Assignment* a = find(key);
    if (a == nullptr)
        context_.diagnostics.error("E0009", block_.loc, fmt::format("{} is missing required key '{}'", where_, key));
    return a;
}

void rejectUnexpectedMembers(Context& context, const ast::Block& block, const std::string& where, Allowed allowed) {
    if (!allowed.blocks)
        for (const ast::Block& nested : block.blocks)
            context.diagnostics.error("E0008", nested.loc, fmt::format("unexpected block '{}' in {}", nested.kind, where));
    if (!allowed.rows)
        for (const ast::Row& row : block.rows)
            context.diagnostics.error("E0008", row.loc, fmt::format("unexpected row in {}", where));
    if (!allowed.names)
        for (const ast::NameStatement& name : block.names)
            context.diagnostics.error("E0008", name.loc,
                                      fmt::format("unexpected '{};' in {}; expected 'key = value;'", name.name, where));
    if (!allowed.strings)
        for (const ast::WeightedString& entry : block.strings)
            context.diagnostics.error("E0008", entry.loc,
                                      fmt::format("unexpected string in {}; strings list L-system alternatives in "
                                                  "'production' and 'macro' blocks",
                                                  where));
}

bool checkLabel(Context& context, const ast::Block& block, bool needsLabel) {
    if (needsLabel && !block.label) {
        context.diagnostics.error("E0001", block.loc,
                                  fmt::format("'{0}' needs a name, as in '{0} NAME {{ ... }}'", block.kind));
        return false;
    }
    if (!needsLabel && block.label) {
        context.diagnostics.error("E0001", block.labelLoc,
                                  fmt::format("'{}' takes no name; remove '{}'", block.kind, *block.label));
        return false;
    }
    return true;
}

bool claimStageName(Context& context, const ast::Block& block, std::map<std::string, SourceLoc>& names,
                    const std::vector<std::string>& usedNames) {
    const bool inserted = names.emplace(*block.label, block.labelLoc).second;
    if (inserted && std::find(usedNames.begin(), usedNames.end(), *block.label) == usedNames.end() &&
        *block.label != "start")
        return true;
    context.diagnostics.error("E0003", block.labelLoc,
                              fmt::format("the name '{}' is already used by another stage", *block.label));
    return false;
}

namespace {

// Bounds at or past the int32 limits are "no bound" to the user, except the uint32 range of seeds.
std::string describeRange(double min, double max) {
    constexpr double unbounded = std::numeric_limits<int32_t>::max();
    const bool seedRange = max == double(std::numeric_limits<uint32_t>::max());
    if (max >= unbounded && !seedRange) return fmt::format("at least {}", formatNumber(min));
    if (min <= -unbounded - 1) return fmt::format("at most {}", formatNumber(max));
    return fmt::format("between {} and {}", formatNumber(min), formatNumber(max));
}

bool inRange(Context& context, const ast::Assignment& a, SourceLoc loc, double v, double min, double max) {
    if (v >= min && v <= max) return true;
    context.diagnostics.error("E0007", loc,
                              fmt::format("'{}' must be {}, got {}", a.key, describeRange(min, max), formatNumber(v)));
    return false;
}

std::optional<double> scalar(Context& context, const ast::Assignment& a, const ast::Value& value, const char* wanted) {
    if (value.isList()) {
        context.diagnostics.error("E0010", value.loc, fmt::format("'{}' expects {}, found a list", a.key, wanted));
        return std::nullopt;
    }
    return context.constants.evaluate(*value.scalar, fmt::format("'{}'", a.key));
}

bool isInteger(Context& context, const ast::Assignment& a, SourceLoc loc, double v) {
    if (v == std::floor(v)) return true;
    context.diagnostics.error("E0010", loc, fmt::format("'{}' expects an integer, got {}", a.key, formatNumber(v)));
    return false;
}

// The elements of a list of exactly `count` elements, or an E0010 naming the expected shape.
const std::vector<ast::Value>* listOf(Context& context, const ast::Assignment& a, const ast::Value& value, size_t count,
                                      const char* wanted) {
    if (value.isList() && value.elements.size() == count) return &value.elements;
    std::string found = value.isList() ? fmt::format("a list of {}", value.elements.size()) : "a single value";
    context.diagnostics.error("E0010", value.loc, fmt::format("'{}' expects {}, found {}", a.key, wanted, found));
    return nullptr;
}

std::optional<std::array<double, 3>> vec3(Context& context, const ast::Assignment& a, const ast::Value& value,
                                          bool integers, double min, double max) {
    const char* wanted = integers ? "a list of 3 integers" : "a list of 3 numbers";
    const auto* elements = listOf(context, a, value, 3, wanted);
    if (!elements) return std::nullopt;
    std::array<double, 3> out{};
    bool ok = true;
    for (size_t i = 0; i < 3; ++i) {
        const ast::Value& element = (*elements)[i];
        auto v = scalar(context, a, element, integers ? "an integer" : "a number");
        ok = ok && v && (!integers || isInteger(context, a, element.loc, *v)) &&
             inRange(context, a, element.loc, *v, min, max);
        if (v) out[i] = *v;
    }
    return ok ? std::optional(out) : std::nullopt;
}

} // namespace

std::optional<double> readNumber(Context& context, const ast::Assignment& a, double min, double max) {
    auto v = scalar(context, a, a.value, "a number");
    if (!v || !inRange(context, a, a.value.loc, *v, min, max)) return std::nullopt;
    return v;
}

std::optional<int64_t> readInteger(Context& context, const ast::Assignment& a, int64_t min, int64_t max) {
    auto v = scalar(context, a, a.value, "an integer");
    if (!v || !isInteger(context, a, a.value.loc, *v) || !inRange(context, a, a.value.loc, *v, double(min), double(max)))
        return std::nullopt;
    return int64_t(*v);
}

std::optional<std::array<double, 3>> readNumberVec3(Context& context, const ast::Assignment& a, double min,
                                                    double max) {
    return vec3(context, a, a.value, false, min, max);
}

std::optional<double> readKey(Context& context, const ast::Assignment& a, std::string_view block) {
    const std::optional<KeyRange> range = blockKeyRange(block, a.key);
    VOXC_ASSERT(range.has_value());
    if (!range->integer) return readNumber(context, a, range->min, range->max);
    const std::optional<int64_t> v = readInteger(context, a, int64_t(range->min), int64_t(range->max));
    return v ? std::optional<double>(double(*v)) : std::nullopt;
}

std::optional<int64_t> readIntegerElement(Context& context, const ast::Assignment& a, const ast::Value& element,
                                          int64_t min, int64_t max) {
    auto v = scalar(context, a, element, "an integer");
    if (!v || !isInteger(context, a, element.loc, *v) || !inRange(context, a, element.loc, *v, double(min), double(max)))
        return std::nullopt;
    return int64_t(*v);
}

std::optional<glm::ivec3> readIntegerVec3(Context& context, const ast::Assignment& a, int64_t min, int64_t max) {
    auto v = vec3(context, a, a.value, true, double(min), double(max));
    if (!v) return std::nullopt;
    return glm::ivec3(int((*v)[0]), int((*v)[1]), int((*v)[2]));
}

std::optional<std::array<double, 2>> readRange(Context& context, const ast::Assignment& a) {
    const auto* elements = listOf(context, a, a.value, 2, "a list [low, high]");
    if (!elements) return std::nullopt;
    auto lo = scalar(context, a, (*elements)[0], "a number");
    auto hi = scalar(context, a, (*elements)[1], "a number");
    if (!lo || !hi) return std::nullopt;
    // The bounds are stored as floats; one beyond the float range would become an infinity.
    for (size_t i = 0; i < 2; ++i) {
        const double v = i == 0 ? *lo : *hi;
        if (std::fabs(v) <= double(std::numeric_limits<float>::max())) continue;
        context.diagnostics.error("E0007", (*elements)[i].loc,
                                  fmt::format("'{}' bound {} does not fit in a 32-bit float", a.key, formatNumber(v)));
        return std::nullopt;
    }
    if (*lo > *hi) {
        context.diagnostics.error("E0007", a.value.loc,
                                  fmt::format("'{}' is empty: low {} is greater than high {}", a.key,
                                              formatNumber(*lo), formatNumber(*hi)));
        return std::nullopt;
    }
    return std::array<double, 2>{*lo, *hi};
}

std::optional<std::array<glm::ivec3, 2>> readBox(Context& context, const ast::Assignment& a) {
    const auto* corners = listOf(context, a, a.value, 2, "a list [[x, y, z], [x, y, z]]");
    if (!corners) return std::nullopt;
    constexpr double limit = 1 << 30;
    auto lo = vec3(context, a, (*corners)[0], true, -limit, limit);
    auto hi = vec3(context, a, (*corners)[1], true, -limit, limit);
    if (!lo || !hi) return std::nullopt;
    return std::array<glm::ivec3, 2>{glm::ivec3(int((*lo)[0]), int((*lo)[1]), int((*lo)[2])),
                                     glm::ivec3(int((*hi)[0]), int((*hi)[1]), int((*hi)[2]))};
}

std::optional<int> readAxis(Context& context, const ast::Assignment& a) {
    const ast::Expr* expr = a.value.isList() ? nullptr : a.value.scalar.get();
    if (expr && expr->kind == ast::Expr::Kind::Name && expr->name.size() == 1) {
        size_t axis = std::string_view("xyz").find(expr->name[0]);
        if (axis != std::string_view::npos) return int(axis);
    }
    context.diagnostics.error("E0010", a.value.loc, fmt::format("'{}' expects an axis: x, y or z", a.key));
    return std::nullopt;
}

std::optional<float> readFloat(Context& context, const ast::Expr& expr) {
    auto v = context.constants.evaluate(expr);
    if (!v) return std::nullopt;
    if (std::fabs(*v) > double(std::numeric_limits<float>::max())) {
        context.diagnostics.error("E0007", expr.loc,
                                  fmt::format("{} does not fit in a 32-bit float", formatNumber(*v)));
        return std::nullopt;
    }
    return float(*v);
}

} // namespace voxc::check
