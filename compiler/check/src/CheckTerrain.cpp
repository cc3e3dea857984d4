// The `terrain` block: keys and ranges with located errors here, then the generator's own checks
// (terrain::validateTerrain: unstable erosion, bounds on work), located at the block. The block is
// kept as a terrain::TerrainBlock; a run generates and voxelises it (stages::solveBlocks) into a
// SolveTable that the curves stage kind combines, so checking a file never generates a map.
#include "CheckTerrain.h"

#include "Materials.h"
#include "Suggest.h"
#include "Values.h"

#include "voxc/generators/terrain/Block.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace voxc::check {

namespace {

constexpr int32_t kMaxLevel = 12;              // 4096^2 cells, the generator's largest level

constexpr std::string_view kTerrainKeys[] = {"origin",   "size",  "levels",     "base",  "max_height",
                                           "ramp",     "preset", "steps_scale", "material",
                                           "deposit_material", "deposit_threshold"};
constexpr std::string_view kNoiseKeys[] = {"amplitude", "scale", "seed"};
constexpr std::string_view kSplineKeys[] = {"points",          "levels",    "radius",    "left",
                                            "right",           "hardness",  "noise_amplitude",
                                            "roughness",       "warp_low",  "warp_high", "rain",
                                            "capacity"};
// A `meta { at = U; ... }` block: one meta point at U in [0, pieces], its other keys the spline's.
constexpr std::string_view kMetaKeys[] = {"at",        "radius",   "left",     "right", "hardness", "noise_amplitude",
                                          "roughness", "warp_low", "warp_high", "rain", "capacity"};

using terrain::TerrainBlock;

void number(Context& context, const BlockKeys& keys, std::string_view key, double lo, double hi, double& out, bool& ok) {
    if (const ast::Assignment* a = keys.find(key)) {
        const std::optional<double> v = readNumber(context, *a, lo, hi);
        ok = ok && v.has_value();
        if (v) out = *v;
    }
}

// A key of blockKeys(block) (voxc/check/KeyRanges.h) within its range.
void keyNumber(Context& context, const BlockKeys& keys, std::string_view block, std::string_view key, double& out,
               bool& ok) {
    if (const ast::Assignment* a = keys.find(key)) {
        const std::optional<double> v = readKey(context, *a, block);
        ok = ok && v.has_value();
        if (v) out = *v;
    }
}

std::optional<std::array<int32_t, 2>> readLevels(Context& context, const ast::Assignment& a) {
    const std::optional<std::array<double, 2>> v = readRange(context, a);
    if (!v) return std::nullopt;
    if ((*v)[0] != std::floor((*v)[0]) || (*v)[1] != std::floor((*v)[1]) || (*v)[0] < 1 || (*v)[1] > kMaxLevel) {
        context.diagnostics.error("E0007", a.value.loc,
                                  fmt::format("'{}' is a range [low, high] of whole levels in 1..{}", a.key, kMaxLevel));
        return std::nullopt;
    }
    return std::array<int32_t, 2>{int32_t((*v)[0]), int32_t((*v)[1])};
}

// `[a, b]` of numbers, each in [lo, hi] (in any order, unlike readRange).
std::optional<glm::dvec2> readPair(Context& context, const ast::Assignment& a, double lo, double hi) {
    const ast::Value& value = a.value;
    if (!value.isList() || value.elements.size() != 2 || value.elements[0].isList() || value.elements[1].isList()) {
        context.diagnostics.error("E0010", value.loc, fmt::format("'{}' expects two numbers [a, b]", a.key));
        return std::nullopt;
    }
    glm::dvec2 out;
    for (int i = 0; i < 2; ++i) {
        const ast::Value& element = value.elements[size_t(i)];
        const std::optional<double> v = context.constants.evaluate(*element.scalar, fmt::format("'{}'", a.key));
        if (!v) return std::nullopt;
        if (!(*v >= lo && *v <= hi)) {
            context.diagnostics.error("E0007", element.loc, fmt::format("'{}' values must lie in [{}, {}]", a.key, lo, hi));
            return std::nullopt;
        }
        out[i] = *v;
    }
    return out;
}

// `points = [[x, y, z], ...]`: 3k + 1 control points of k cubic Bezier pieces.
bool readControlPoints(Context& context, const ast::Assignment& a, std::vector<glm::dvec3>& out) {
    const ast::Value& value = a.value;
    const size_t n = value.isList() ? value.elements.size() : 0;
    if (n < 4 || (n - 1) % 3 != 0) {
        context.diagnostics.error("E0004", value.loc,
                                  fmt::format("'points' lists 3k + 1 control points [x, y, z] (k cubic pieces), "
                                              "found {}", n));
        return false;
    }
    for (const ast::Value& element : value.elements) {
        if (!element.isList() || element.elements.size() != 3) {
            context.diagnostics.error("E0010", element.loc, "'points' expects points [x, y, z]");
            return false;
        }
        glm::dvec3 p;
        for (int i = 0; i < 3; ++i) {
            const ast::Value& c = element.elements[size_t(i)];
            const std::optional<double> v = c.isList() ? std::nullopt : context.constants.evaluate(*c.scalar);
            if (!v) {
                if (c.isList()) context.diagnostics.error("E0010", c.loc, "a coordinate must be a number");
                return false;
            }
            if (!(std::fabs(*v) <= kMaxCoordinate)) {
                context.diagnostics.error("E0007", c.loc, fmt::format("a coordinate must lie within ±{}", kMaxCoordinate));
                return false;
            }
            p[i] = *v;
        }
        out.push_back(p);
    }
    return true;
}

// Table 3.1's attributes of a meta point, over what `meta` already holds.
void readMetaKeys(Context& context, const BlockKeys& keys, terrain::MetaPoint& meta, bool& ok) {
    keyNumber(context, keys, "spline", "radius", meta.radius, ok);
    for (auto [key, side] : {std::pair{"left", &meta.left}, std::pair{"right", &meta.right}})
        if (const ast::Assignment* a = keys.find(key)) {
            std::optional<glm::dvec2> v = readPair(context, *a, -1e6, 1e6);
            if (v && v->x < 0) { // the band's width; its rise may be negative
                context.diagnostics.error("E0007", a->value.elements[0].loc,
                                          fmt::format("'{}' is [width, rise]: the width must be >= 0", key));
                v.reset();
            }
            ok = ok && v.has_value();
            if (v) *side = *v;
        }
    keyNumber(context, keys, "spline", "hardness", meta.hardness, ok);
    // The generator's own bound (terrain::kMaxMetaFactor, through KeyRanges), so the error is here
    // at the key, not at the block.
    keyNumber(context, keys, "spline", "noise_amplitude", meta.noiseAmplitude, ok);
    keyNumber(context, keys, "spline", "roughness", meta.noiseRoughness, ok);
    keyNumber(context, keys, "spline", "warp_low", meta.warpLow, ok);
    keyNumber(context, keys, "spline", "warp_high", meta.warpHigh, ok);
    keyNumber(context, keys, "spline", "rain", meta.rain, ok);
    keyNumber(context, keys, "spline", "capacity", meta.capacity, ok);
}

// The spline's own keys are one meta point, constant along it; `meta` blocks instead place meta
// points along it (ascending `at`), each starting from the spline's keys, and the generator
// interpolates between them.
std::optional<terrain::Spline> readSpline(Context& context, const ast::Block& block, const terrain::Domain& domain) {
    const std::string where = fmt::format("spline '{}'", block.label.value_or(""));
    rejectUnexpectedMembers(context, block, where, {.blocks = true});
    BlockKeys keys(context, block, where, kSplineKeys);
    terrain::Spline spline;
    spline.minLevel = domain.minLevel;
    spline.maxLevel = domain.maxLevel;
    bool ok = true;
    if (const ast::Assignment* a = keys.require("points"))
        ok = readControlPoints(context, *a, spline.controlPoints) && ok;
    else
        ok = false;
    if (const ast::Assignment* a = keys.find("levels")) {
        const auto levels = readLevels(context, *a);
        ok = ok && levels.has_value();
        if (levels) spline.minLevel = (*levels)[0], spline.maxLevel = (*levels)[1];
    }
    terrain::MetaPoint base;
    readMetaKeys(context, keys, base, ok);
    const double pieces = spline.controlPoints.empty() ? 0.0 : double(spline.controlPoints.size() - 1) / 3.0;
    for (const ast::Block& metaBlock : block.blocks) {
        if (metaBlock.kind != "meta") {
            context.diagnostics.error("E0008", metaBlock.loc,
                                      fmt::format("unknown block '{}' in {}; a spline holds 'meta' blocks",
                                                  metaBlock.kind, where));
            ok = false;
            continue;
        }
        const std::string metaWhere = fmt::format("a meta point of {}", where);
        rejectUnexpectedMembers(context, metaBlock, metaWhere, {});
        BlockKeys metaKeys(context, metaBlock, metaWhere, kMetaKeys);
        terrain::MetaPoint meta = base;
        const ast::Assignment* at = metaKeys.require("at");
        const double lowest = spline.metaPoints.empty() ? 0.0 : spline.metaPoints.back().u;
        if (at) {
            const std::optional<double> u = readNumber(context, *at, 0.0, 1e9);
            if (u && (*u > pieces || (!spline.metaPoints.empty() && *u <= lowest))) {
                context.diagnostics.error(
                    "E0007", at->value.loc,
                    fmt::format("'at' places a meta point on the spline's pieces, in [0, {}] and after the previous "
                                "one ({}); got {}",
                                formatNumber(pieces), formatNumber(lowest), formatNumber(*u)));
                ok = false;
            }
            if (u) meta.u = *u;
            ok = ok && u.has_value();
        } else {
            ok = false;
        }
        readMetaKeys(context, metaKeys, meta, ok);
        spline.metaPoints.push_back(meta);
    }
    if (!ok) return std::nullopt;
    if (spline.metaPoints.empty()) spline.metaPoints = {base};
    // A side band's gradient is held with weight beta, which falls from the hardness h at the
    // band's inner edge (B2.9): with h = 0 everywhere the bands constrain nothing.
    bool bands = false, soft = true;
    for (const terrain::MetaPoint& meta : spline.metaPoints) {
        bands = bands || meta.left.x > 0.0 || meta.right.x > 0.0;
        soft = soft && meta.hardness == 0.0;
    }
    if (bands && soft) {
        const ast::Assignment* side = keys.find("left") ? keys.find("left") : keys.find("right");
        context.diagnostics.warning("W0211", side ? side->value.loc : block.labelLoc,
                                    fmt::format("{} has side gradient bands but hardness 0, so they hold nothing "
                                                "(their weight falls from the hardness; docs/terrain.md); give "
                                                "hardness in (0, 1]",
                                                where));
    }
    return spline;
}

// The preset's Table 5.3 schedule is for levels 8..11 (256^2 to 2048^2); it is moved so its
// finest level is the map's, levels that fall below the map's coarsest dropped.
terrain::ErosionSettings shiftedPreset(const std::string& name, int32_t minLevel, int32_t maxLevel, double scale) {
    terrain::ErosionSettings preset = terrain::presetSettings(name);
    const int32_t shift = maxLevel - preset.levelSteps.rbegin()->first;
    std::map<int32_t, uint32_t> steps;
    for (const auto& [level, count] : preset.levelSteps)
        if (level + shift >= minLevel) steps[level + shift] = uint32_t(std::lround(count * scale));
    preset.levelSteps = steps;
    return preset;
}

std::optional<TerrainBlock> readTerrain(Context& context, const ast::Block& block, const World& world) {
    const std::string where = fmt::format("terrain '{}'", *block.label);
    rejectUnexpectedMembers(context, block, where, {.blocks = true});
    BlockKeys keys(context, block, where, kTerrainKeys);
    TerrainBlock out;
    terrain::Domain& domain = out.map.domain;
    bool ok = true;
    domain.origin = {double(world.origin.x), double(world.origin.z)};
    domain.size = double(std::max(world.size.x, world.size.z));
    domain.maxHeight = double(world.size.y);
    out.base = double(world.origin.y);
    if (const ast::Assignment* a = keys.find("origin")) {
        const std::optional<glm::dvec2> v = readPair(context, *a, -kMaxCoordinate, kMaxCoordinate);
        ok = ok && v.has_value();
        if (v) domain.origin = *v;
    }
    number(context, keys, "size", 1, 1e6, domain.size, ok);
    number(context, keys, "base", -kMaxCoordinate, kMaxCoordinate, out.base, ok);
    keyNumber(context, keys, "terrain", "max_height", domain.maxHeight, ok);
    keyNumber(context, keys, "terrain", "ramp", out.ramp, ok);
    // By default the finest level has about one cell per voxel.
    domain.maxLevel = std::clamp(int32_t(std::ceil(std::log2(domain.size))), 2, kMaxLevel);
    domain.minLevel = std::min(2, domain.maxLevel);
    if (const ast::Assignment* a = keys.find("levels")) {
        const auto levels = readLevels(context, *a);
        ok = ok && levels.has_value();
        if (levels) domain.minLevel = (*levels)[0], domain.maxLevel = (*levels)[1];
    }
    double stepsScale = 1.0;
    keyNumber(context, keys, "terrain", "steps_scale", stepsScale, ok);
    if (const ast::Assignment* a = keys.find("material")) {
        out.material = readMaterialKey(context, *a);
        ok = ok && out.material.has_value();
    }
    if (const ast::Assignment* a = keys.find("deposit_material")) {
        out.depositMaterial = readMaterialKey(context, *a);
        ok = ok && out.depositMaterial.has_value();
    }
    keyNumber(context, keys, "terrain", "deposit_threshold", out.depositThreshold, ok);
    for (const ast::Block& nested : block.blocks) {
        if (nested.kind == "spline") {
            if (!checkLabel(context, nested, true)) {
                ok = false;
                continue;
            }
            std::optional<terrain::Spline> spline = readSpline(context, nested, domain);
            ok = ok && spline.has_value();
            if (spline) out.map.splines.push_back(std::move(*spline));
        } else if (nested.kind == "noise") {
            checkLabel(context, nested, false);
            rejectUnexpectedMembers(context, nested, "'noise' block", {});
            BlockKeys noise(context, nested, "'noise' block", kNoiseKeys);
            keyNumber(context, noise, "noise", "amplitude", out.map.noise.amplitude, ok);
            keyNumber(context, noise, "noise", "scale", out.map.noise.scale, ok);
            if (const ast::Assignment* a = noise.find("seed")) {
                const std::optional<double> v = readKey(context, *a, "noise");
                ok = ok && v.has_value();
                if (v) out.map.noise.seed = uint32_t(*v);
            }
        } else {
            constexpr std::string_view kNested[] = {"spline", "noise"};
            context.diagnostics.error("E0008", nested.loc,
                                      fmt::format("unknown block '{}' in {}{}", nested.kind, where,
                                                  didYouMean(nested.kind, kNested)));
            ok = false;
        }
    }
    if (const ast::Assignment* a = keys.find("preset")) {
        const ast::Expr* expr = a->value.isList() ? nullptr : a->value.scalar.get();
        std::vector<std::string_view> names{"none"};
        for (const terrain::Preset& preset : terrain::presets()) names.push_back(preset.name);
        const bool known = expr && expr->kind == ast::Expr::Kind::Name &&
                           std::find(names.begin(), names.end(), expr->name) != names.end();
        if (!known) {
            context.diagnostics.error("E0011", a->value.loc,
                                      fmt::format("'preset' must be one of {}{}", fmt::join(names, ", "),
                                                  expr && expr->kind == ast::Expr::Kind::Name
                                                      ? didYouMean(expr->name, names)
                                                      : std::string()));
            ok = false;
        } else if (ok && expr->name != "none") {
            out.erosion = shiftedPreset(expr->name, domain.minLevel, domain.maxLevel, stepsScale);
            out.erosion->params.seed = world.seed;
        }
    }
    if (!ok) return std::nullopt;
    return out;
}

} // namespace

std::vector<CurvesBlock> checkTerrains(Context& context, const ast::File& file, const World& world,
                                       const std::vector<std::string>& usedNames) {
    std::vector<CurvesBlock> blocks;
    std::map<std::string, SourceLoc> names;
    // All terrain blocks together: their tables are uploaded whole (two words per cell).
    uint64_t cellBudget = uint64_t(context.limits.maxTerrainCells);
    terrain::Limits limits;
    limits.maxDiffusionCellUpdates = uint64_t(context.limits.maxTerrainWork);
    limits.maxErosionCellSteps = uint64_t(context.limits.maxTerrainWork);
    for (const ast::Block& block : file.blocks) {
        if (block.kind != "terrain") continue;
        if (!checkLabel(context, block, true) || !block.label) continue;
        CurvesBlock out;
        out.name = *block.label;
        out.loc = block.loc;
        out.source = "terrain";
        if (!claimStageName(context, block, names, usedNames)) {
            blocks.push_back(std::move(out));
            continue;
        }
        if (context.maps.contains(*block.label)) {
            context.diagnostics.error("E0003", block.labelLoc,
                                      fmt::format("'{}' is already the name of a heightmap or mesh", *block.label));
            blocks.push_back(std::move(out));
            continue;
        }
        context.maps[*block.label] = nullptr; // until its map is made
        const uint64_t cells = uint64_t(world.size.x) * uint64_t(world.size.y) * uint64_t(world.size.z);
        if (world.unbounded.x || world.unbounded.z) {
            context.diagnostics.error("E0012", block.labelLoc,
                                      fmt::format("terrain '{}' is solved over the whole world, which is unbounded; "
                                                  "give the world's size a number in x and z",
                                                  *block.label));
            blocks.push_back(std::move(out));
            continue;
        }
        if (cells > cellBudget) {
            context.diagnostics.error("E0012", block.labelLoc,
                                      fmt::format("terrain '{}' would voxelise {} cells, past what is left of the "
                                                  "{} all terrain blocks may use",
                                                  *block.label, cells, context.limits.maxTerrainCells));
            blocks.push_back(std::move(out));
            continue;
        }
        if (std::optional<TerrainBlock> terrainBlock = readTerrain(context, block, world)) {
            try {
                terrain::validateTerrain(terrainBlock->map, terrainBlock->erosion, limits);
                terrainBlock->name = *block.label;
                terrainBlock->worldOrigin = world.origin;
                terrainBlock->worldSize = world.size;
                terrainBlock->limits = limits;
                out.size = world.size;
                for (const std::optional<uint8_t>& material : {terrainBlock->material, terrainBlock->depositMaterial})
                    if (material) out.materials.push_back(*material);
                out.writesMaterials = !out.materials.empty();
                std::sort(out.materials.begin(), out.materials.end());
                out.materials.erase(std::unique(out.materials.begin(), out.materials.end()), out.materials.end());
                context.maps[*block.label] = terrain::declaredMap(*terrainBlock);
                out.terrain = std::make_shared<const TerrainBlock>(std::move(*terrainBlock));
                cellBudget -= cells;
            } catch (const terrain::LimitError& e) {
                // e.what() starts "terrain: ", which the block's name replaces.
                context.diagnostics.error("E0012", block.labelLoc,
                                          fmt::format("terrain '{}': {} is {}, over the limit of {}", *block.label,
                                                      e.quantity, e.value, e.limit));
            } catch (const terrain::ParameterError& e) {
                context.diagnostics.error("E0007", block.labelLoc,
                                          fmt::format("terrain '{}': {} = {} is invalid: {}", *block.label, e.parameter,
                                                      e.value, e.requirement));
            }
        }
        blocks.push_back(std::move(out));
    }
    return blocks;
}

} // namespace voxc::check
