// The `world` block and the `start` block's shapes.
#include "Materials.h"
#include "Sections.h"
#include "Suggest.h"
#include "Values.h"

#include "voxc/builtins/Shapes.h"

#include <algorithm>
#include <fmt/format.h>
#include <limits>

namespace voxc::check {

namespace {

constexpr int64_t kMaxAxisVoxels = 1 << 20;
constexpr int64_t kMaxOrigin = 1 << 30;

bool isPowerOfTwo(int64_t v) { return v > 0 && (v & (v - 1)) == 0; }

constexpr std::string_view kUnbounded = "unbounded";

bool isUnbounded(const ast::Value& value) {
    return !value.isList() && value.scalar->kind == ast::Expr::Kind::Name && value.scalar->name == kUnbounded;
}

// `size = [X, Y, Z]` where X and Z may be `unbounded` (docs/language.md, "world"): such an axis
// gets the largest size, kMaxAxisVoxels voxels from the origin, and World::unbounded says so.
std::optional<glm::ivec3> readWorldSize(Context& context, const ast::Assignment& a, World& world) {
    const bool mentionsUnbounded = a.value.isList() && a.value.elements.size() == 3 &&
                                   std::ranges::any_of(a.value.elements, isUnbounded);
    if (!mentionsUnbounded) return readIntegerVec3(context, a, 1, kMaxAxisVoxels);
    glm::ivec3 size(0);
    bool ok = true;
    for (int axis = 0; axis < 3; ++axis) {
        const ast::Value& element = a.value.elements[size_t(axis)];
        if (!isUnbounded(element)) {
            const std::optional<int64_t> v = readIntegerElement(context, a, element, 1, kMaxAxisVoxels);
            ok = ok && v.has_value();
            if (v) size[axis] = int32_t(*v);
        } else if (axis == 1) {
            context.diagnostics.error("E0007", element.loc,
                                      "only x and z may be unbounded: the world's height (y) needs a size");
            ok = false;
        } else {
            world.unbounded[axis] = true;
            size[axis] = int32_t(kMaxAxisVoxels);
        }
    }
    return ok ? std::optional(size) : std::nullopt;
}

} // namespace

std::optional<World> checkWorld(Context& context, const ast::Block& block) {
    static constexpr std::string_view kKeys[] = {"size", "origin", "chunk", "seed"};
    const std::string where = "'world' block";
    checkLabel(context, block, false);
    rejectUnexpectedMembers(context, block, where, {});
    BlockKeys keys(context, block, where, kKeys);

    World world;
    bool sizeOk = false;
    if (const ast::Assignment* a = keys.require("size")) {
        if (auto size = readWorldSize(context, *a, world)) {
            world.size = *size;
            sizeOk = true;
            int64_t voxels = int64_t(size->x) * size->y * size->z;
            // A run of a region runs the region's grid, which checkWork bounds.
            if ((world.unbounded.x || world.unbounded.z) && !context.region)
                context.diagnostics.error("E0012", a->value.loc,
                                          "the world is unbounded, so it cannot run as one grid: give a box of it "
                                          "with --region (voxc run, interp, check, world)");
            else if (voxels > context.limits.maxVoxels && !context.region)
                context.diagnostics.error("E0012", a->value.loc,
                                          fmt::format("a {} grid has {} voxels, more than the limit of {}",
                                                      formatVec(*size), voxels, context.limits.maxVoxels));
        }
    }
    if (const ast::Assignment* a = keys.find("origin"))
        if (auto origin = readIntegerVec3(context, *a, -kMaxOrigin, kMaxOrigin)) world.origin = *origin;
    if (const ast::Assignment* a = keys.find("chunk")) {
        if (auto chunk = readInteger(context, *a, 8, 64)) {
            if (isPowerOfTwo(*chunk))
                world.chunkSize = int32_t(*chunk);
            else
                context.diagnostics.error("E0007", a->value.loc,
                                          fmt::format("'chunk' must be a power of two (8, 16, 32 or 64), got {}", *chunk));
        }
    }
    if (const ast::Assignment* a = keys.find("seed"))
        if (auto seed = readInteger(context, *a, 0, std::numeric_limits<uint32_t>::max())) world.seed = uint32_t(*seed);

    // Grammars check their bounds against the size, so a world with other errors still returns.
    if (!sizeOk) return std::nullopt;
    return world;
}

namespace {

std::optional<std::array<double, 3>> readKey(Context& context, const ast::Assignment& a, const KeySpec& spec) {
    switch (spec.type) {
    case KeyType::Number:
        if (auto v = readNumber(context, a, spec.min, spec.max)) return std::array<double, 3>{*v, 0, 0};
        return std::nullopt;
    case KeyType::Integer:
        if (auto v = readInteger(context, a, int64_t(spec.min), int64_t(spec.max)))
            return std::array<double, 3>{double(*v), 0, 0};
        return std::nullopt;
    case KeyType::Vec3: return readNumberVec3(context, a, spec.min, spec.max);
    case KeyType::Axis:
        if (auto v = readAxis(context, a)) return std::array<double, 3>{double(*v), 0, 0};
        return std::nullopt;
    }
    return std::nullopt;
}

// One shape: its keys come from the Shapes registry, never from this file, and every shape also
// takes `material = NAME;` (kMaterialKey): materials are a property of the start block, not of
// one shape.
std::optional<StartShape> checkShape(Context& context, const ast::Block& block) {
    std::optional<ShapeKind> kind = findShape(block.kind);
    if (!kind) {
        std::vector<std::string_view> names;
        for (const ShapeInfo& info : shapes()) names.push_back(info.name);
        context.diagnostics.error("E0002", block.loc,
                                  fmt::format("unknown shape '{}'{}", block.kind, suggestOrList(block.kind, names)));
        return std::nullopt;
    }
    const ShapeInfo& info = shapeInfo(*kind);
    const std::string where = fmt::format("'{}' shape", info.name);
    checkLabel(context, block, false);
    rejectUnexpectedMembers(context, block, where, {});
    std::vector<std::string_view> keyNames;
    for (const KeySpec& spec : info.keys) keyNames.push_back(spec.name);
    keyNames.push_back(kMaterialKey);
    BlockKeys keys(context, block, where, keyNames);

    StartShape shape;
    shape.kind = *kind;
    shape.loc = block.loc;
    bool ok = true;
    if (const ast::Assignment* a = keys.find(kMaterialKey)) {
        shape.material = readMaterialKey(context, *a);
        ok = shape.material.has_value();
    }
    for (const KeySpec& spec : info.keys) {
        const ast::Assignment* a = spec.required ? keys.require(spec.name) : keys.find(spec.name);
        if (a == nullptr) {
            ok = ok && !spec.required;
            continue;
        }
        auto values = readKey(context, *a, spec);
        if (values)
            spec.set(shape, values->data());
        else
            ok = false;
    }
    return ok ? std::optional(shape) : std::nullopt;
}

} // namespace

std::vector<StartShape> checkStart(Context& context, const ast::Block& block) {
    checkLabel(context, block, false);
    rejectUnexpectedMembers(context, block, "'start' block", {.blocks = true});
    for (const ast::Assignment& a : block.assignments)
        context.diagnostics.error("E0008", a.loc,
                                  fmt::format("unexpected key '{}' in 'start' block; it holds shapes such as "
                                              "'box {{ ... }}'",
                                              a.key));
    // All shapes compile into the one start kernel (2000 shapes take seconds to compile).
    if (block.blocks.size() > size_t(context.limits.maxStartShapes)) {
        context.diagnostics.error("E0012", block.blocks[size_t(context.limits.maxStartShapes)].loc,
                                  fmt::format("the start state has {} shapes, more than the limit of {}",
                                              block.blocks.size(), context.limits.maxStartShapes));
        return {};
    }
    std::vector<StartShape> shapes;
    for (const ast::Block& shapeBlock : block.blocks)
        if (auto shape = checkShape(context, shapeBlock)) shapes.push_back(*shape);
    return shapes;
}

} // namespace voxc::check
