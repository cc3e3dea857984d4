// The `curves` block: keys and ranges with located errors here, then the voxelisation, whose
// remaining errors (a degenerate bitangent, a bound on work) are located at the curve or block they
// come from. The solve itself runs only when the program runs (stages::solveBlocks), so checking a
// file (voxc check, the language server) costs the voxelisation at most.
#include "CheckCurves.h"

#include "Materials.h"
#include "Suggest.h"
#include "Values.h"

#include "voxc/generators/curves/Scene.h"
#include "voxc/program/SampledMap.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <regex>

namespace voxc::check {

namespace {

// All curves blocks together: a run solves every box (about 2 s of CPU per million cells on the
// host), and its tables are uploaded whole (two words per cell).

constexpr std::string_view kCurvesKeys[] = {"box",        "normals",         "k",
                                           "sweeps",     "smoothing",       "noise_frequency",
                                           "noise_seed", "inputs",          "dead_zone",
                                           "input_amplitude", "input_roughness", "input_material"};
constexpr std::string_view kCurveKeys[] = {"points", "seed"};
constexpr std::string_view kConstraintKeys[] = {"t", "left", "right", "amplitude", "roughness", "material"};
constexpr std::string_view kNormalModes[] = {"laplace", "perona_malik"};
constexpr std::string_view kBooleans[] = {"true", "false"};

// A bare name among `choices` (its index), or E0010.
std::optional<size_t> readChoice(Context& context, const ast::Assignment& a, std::span<const std::string_view> choices) {
    const ast::Expr* expr = a.value.isList() ? nullptr : a.value.scalar.get();
    if (expr && expr->kind == ast::Expr::Kind::Name)
        for (size_t i = 0; i < choices.size(); ++i)
            if (expr->name == choices[i]) return i;
    std::string list;
    for (std::string_view c : choices) list += fmt::format("{}'{}'", list.empty() ? "" : " or ", c);
    context.diagnostics.error("E0010", a.value.loc, fmt::format("'{}' expects {}", a.key, list));
    return std::nullopt;
}

std::optional<glm::dvec3> readPoint(Context& context, const ast::Assignment& a, const ast::Value& value,
                                    double limit) {
    if (!value.isList() || value.elements.size() != 3 ||
        std::any_of(value.elements.begin(), value.elements.end(), [](const ast::Value& e) { return e.isList(); })) {
        context.diagnostics.error("E0010", value.loc, fmt::format("'{}' expects points [x, y, z]", a.key));
        return std::nullopt;
    }
    glm::dvec3 p;
    for (int i = 0; i < 3; ++i) {
        const std::optional<double> v = context.constants.evaluate(*value.elements[i].scalar, fmt::format("'{}'", a.key));
        if (!v) return std::nullopt;
        if (!(std::fabs(*v) <= limit)) {
            context.diagnostics.error("E0007", value.elements[i].loc,
                                      fmt::format("'{}' coordinate {} is outside [-{}, {}]", a.key, formatNumber(*v),
                                                  formatNumber(limit), formatNumber(limit)));
            return std::nullopt;
        }
        p[i] = *v;
    }
    return p;
}

std::optional<curves::ConstraintPoint> readConstraint(Context& context, const ast::Block& block,
                                                      const std::string& where, double limit, SourceLoc& tLoc) {
    checkLabel(context, block, false);
    rejectUnexpectedMembers(context, block, where, {});
    BlockKeys keys(context, block, where, kConstraintKeys);
    curves::ConstraintPoint point;
    bool ok = true;
    if (const ast::Assignment* a = keys.require("t")) {
        tLoc = a->value.loc;
        const std::optional<double> t = readNumber(context, *a, 0, 1);
        ok = ok && t.has_value();
        if (t) point.t = *t;
    } else {
        ok = false;
    }
    for (const char* side : {"left", "right"})
        if (const ast::Assignment* a = keys.find(side)) {
            const std::optional<glm::dvec3> v = readPoint(context, *a, a->value, limit);
            ok = ok && v.has_value();
            if (v) (std::string_view(side) == "left" ? point.left : point.right) = *v;
        }
    if (const ast::Assignment* a = keys.find("amplitude")) {
        const std::optional<double> v = readKey(context, *a, "constraint");
        ok = ok && v.has_value();
        if (v) point.amplitude = *v;
    }
    if (const ast::Assignment* a = keys.find("roughness")) {
        const std::optional<double> v = readKey(context, *a, "constraint");
        ok = ok && v.has_value();
        if (v) point.roughness = *v;
    }
    if (const ast::Assignment* a = keys.find("material")) {
        const std::optional<uint8_t> m = readMaterialKey(context, *a);
        ok = ok && m.has_value();
        if (m) point.material = *m;
    }
    if (!ok) return std::nullopt;
    return point;
}

// Where a sampling error about "<curve> constraint N left|right ..." points: that constraint's
// key, else the constraint block, else the curve.
SourceLoc parameterLoc(const std::string& parameter, const ast::Block& curve,
                       const std::vector<const ast::Block*>& constraints) {
    static const std::regex pattern(R"( constraint (\d+) (left|right))");
    std::smatch match;
    if (!std::regex_search(parameter, match, pattern)) return curve.loc;
    const size_t index = std::stoul(match[1].str());
    if (index >= constraints.size()) return curve.loc;
    for (const ast::Assignment& a : constraints[index]->assignments)
        if (a.key == match[2].str()) return a.value.loc;
    return constraints[index]->loc;
}

// The curve's keys, constraint points and their t order, then its sampling (degenerate
// bitangents and tangents, segment bounds) located at the curve.
std::optional<curves::FeatureCurve> readCurve(Context& context, const ast::Block& block, const std::string& name,
                                              const curves::Limits& limits) {
    const std::string where = name;
    rejectUnexpectedMembers(context, block, where, {.blocks = true});
    BlockKeys keys(context, block, where, kCurveKeys);
    curves::FeatureCurve curve;
    bool ok = true;
    if (const ast::Assignment* a = keys.require("points")) {
        if (!a->value.isList() || a->value.elements.size() < 4 || a->value.elements.size() > limits.maxControlPoints) {
            context.diagnostics.error("E0007", a->value.loc,
                                      fmt::format("'points' expects a list of 4 to {} control points [x, y, z] (a "
                                                  "cubic B-spline)",
                                                  limits.maxControlPoints));
            ok = false;
        } else {
            for (const ast::Value& element : a->value.elements) {
                const std::optional<glm::dvec3> p = readPoint(context, *a, element, limits.maxCoordinate);
                ok = ok && p.has_value();
                if (p) curve.points.push_back(*p);
            }
        }
    } else {
        ok = false;
    }
    if (const ast::Assignment* a = keys.find("seed")) {
        const std::optional<size_t> choice = readChoice(context, *a, kBooleans);
        ok = ok && choice.has_value();
        curve.seed = choice != size_t(1);
    }
    std::vector<SourceLoc> tLocs;
    std::vector<const ast::Block*> constraintBlocks;
    for (const ast::Block& member : block.blocks) {
        if (member.kind != "constraint") {
            context.diagnostics.error("E0008", member.loc,
                                      fmt::format("unknown block '{}' in {}; a curve holds 'constraint' blocks",
                                                  member.kind, where));
            ok = false;
            continue;
        }
        SourceLoc tLoc = member.loc;
        const std::optional<curves::ConstraintPoint> point =
            readConstraint(context, member, fmt::format("a constraint of {}", where), limits.maxCoordinate, tLoc);
        ok = ok && point.has_value();
        if (point) curve.constraints.push_back(*point);
        tLocs.push_back(tLoc);
        constraintBlocks.push_back(&member);
    }
    if (!ok) return std::nullopt;
    if (curve.constraints.size() < 2 || curve.constraints.size() > limits.maxConstraintPoints) {
        context.diagnostics.error("E0009", block.loc,
                                  fmt::format("{} needs 2 to {} 'constraint' blocks (the first at t = 0, the last at "
                                              "t = 1); it has {}",
                                              where, limits.maxConstraintPoints, curve.constraints.size()));
        return std::nullopt;
    }
    const auto& cps = curve.constraints;
    for (size_t i = 0; i < cps.size(); ++i) {
        std::string problem;
        if (i == 0 && cps[i].t != 0.0) problem = "the first constraint must be at t = 0";
        else if (i + 1 == cps.size() && cps[i].t != 1.0) problem = "the last constraint must be at t = 1";
        else if (i > 0 && !(cps[i].t > cps[i - 1].t))
            problem = fmt::format("constraints must be in increasing t; the previous one is at t = {}",
                                  formatNumber(cps[i - 1].t));
        if (problem.empty()) continue;
        context.diagnostics.error("E0007", tLocs[i], fmt::format("t = {}: {}", formatNumber(cps[i].t), problem));
        return std::nullopt;
    }
    try {
        curves::sampleCurve(curve, limits, name);
    } catch (const curves::LimitError& e) {
        context.diagnostics.error("E0012", block.loc, e.what());
        return std::nullopt;
    } catch (const curves::ParameterError& e) {
        context.diagnostics.error("E0007", parameterLoc(e.parameter, block, constraintBlocks), e.what());
        return std::nullopt;
    }
    return curve;
}

// `inputs = [ridge, boulder];`: heightmap and mesh blocks (checked before the curves blocks)
// turned into box-local surfaces: a heightmap's heights at the box's columns and one more on
// every side, sampled as a field samples NAME(wx, wz); a mesh's placed triangles that can reach
// the box. A block with errors of its own fails quietly (they are reported).
bool readInputs(Context& context, const ast::File& file, const ast::Assignment& a, const World& world,
                curves::Scene& scene) {
    std::vector<const ast::Value*> names;
    if (a.value.isList())
        for (const ast::Value& element : a.value.elements) names.push_back(&element);
    else
        names.push_back(&a.value);
    bool ok = true;
    std::vector<std::string> seen;
    for (const ast::Value* value : names) {
        const ast::Expr* expr = value->isList() ? nullptr : value->scalar.get();
        if (!expr || expr->kind != ast::Expr::Kind::Name) {
            context.diagnostics.error("E0010", value->loc,
                                      "'inputs' expects names of heightmap and mesh blocks, as in 'inputs = [ridge, "
                                      "boulder];'");
            ok = false;
            continue;
        }
        const std::string& name = expr->name;
        if (std::find(seen.begin(), seen.end(), name) != seen.end()) {
            context.diagnostics.error("E0003", value->loc, fmt::format("'{}' is listed twice in 'inputs'", name));
            ok = false;
            continue;
        }
        seen.push_back(name);
        const ast::Block* block = nullptr;
        std::vector<std::string_view> candidates;
        for (const ast::Block& b : file.blocks) {
            if (!b.label) continue;
            if (*b.label == name && !block) block = &b;
            if (b.kind == "heightmap" || b.kind == "mesh") candidates.push_back(*b.label);
        }
        const bool isField = std::any_of(file.fields.begin(), file.fields.end(),
                                         [&](const ast::FieldDecl& f) { return f.name == name; });
        if (!block || (block->kind != "heightmap" && block->kind != "mesh")) {
            if (block || isField)
                context.diagnostics.error("E0010", value->loc,
                                          fmt::format("'{}' is a {}; 'inputs' takes heightmap and mesh blocks", name,
                                                      block ? block->kind + " block" : std::string("field")));
            else
                context.diagnostics.error("E0002", value->loc,
                                          fmt::format("unknown heightmap or mesh '{}'{}", name,
                                                      suggestOrList(name, candidates)));
            ok = false;
            continue;
        }
        const auto map = context.maps.find(name);
        if (map == context.maps.end() || !map->second) {
            ok = false; // the block's own errors are reported
            continue;
        }
        auto surface = std::make_shared<curves::InputSurface>();
        surface->name = name;
        const glm::dvec3 base = glm::dvec3(world.origin) + glm::dvec3(scene.box.min);
        if (block->kind == "heightmap") {
            surface->kind = curves::InputSurface::Kind::Heightmap;
            surface->heights.reserve(size_t(scene.box.size.x + 2) * size_t(scene.box.size.z + 2));
            for (int32_t z = -1; z <= scene.box.size.z; ++z)
                for (int32_t x = -1; x <= scene.box.size.x; ++x)
                    surface->heights.push_back(
                        double(sampleMap(*map->second, float(base.x + x), float(base.z + z))) - base.y);
        } else {
            const auto mesh = context.placedMeshes.find(name);
            if (mesh == context.placedMeshes.end()) {
                ok = false;
                continue;
            }
            surface->kind = curves::InputSurface::Kind::Mesh;
            const glm::dvec3 lo(-1.0), hi = glm::dvec3(scene.box.size);
            for (const glm::uvec3& t : mesh->second->triangles) {
                const std::array<glm::dvec3, 3> p = {mesh->second->points[t.x] - base, mesh->second->points[t.y] - base,
                                                     mesh->second->points[t.z] - base};
                const glm::dvec3 tlo = glm::min(p[0], glm::min(p[1], p[2])), thi = glm::max(p[0], glm::max(p[1], p[2]));
                if (glm::all(glm::lessThanEqual(tlo, hi)) && glm::all(glm::greaterThanEqual(thi, lo)))
                    surface->triangles.push_back(p);
            }
        }
        scene.inputs.push_back(std::move(surface));
    }
    return ok;
}

// The options, the curves and the box.
std::optional<curves::Scene> readScene(Context& context, const ast::File& file, const ast::Block& block,
                                       const World& world, uint64_t& cellBudget, const curves::Limits& limits) {
    const std::string where = fmt::format("curves '{}'", *block.label);
    rejectUnexpectedMembers(context, block, where, {.blocks = true});
    BlockKeys keys(context, block, where, kCurvesKeys);
    curves::Scene scene;
    bool ok = true, boxRead = false;
    if (const ast::Assignment* a = keys.require("box")) {
        const std::optional<std::array<glm::ivec3, 2>> box = readBox(context, *a);
        ok = ok && box.has_value();
        if (box) {
            const glm::ivec3 lo = (*box)[0], hi = (*box)[1];
            if (glm::any(glm::greaterThan(lo, hi)) || glm::any(glm::lessThan(lo, glm::ivec3(0))) ||
                glm::any(glm::greaterThanEqual(hi, world.size))) {
                context.diagnostics.error("E0007", a->value.loc,
                                          fmt::format("the box {} to {} (inclusive, grid-local voxels) must be "
                                                      "non-empty and inside the grid, [0, 0, 0] to {}",
                                                      formatVec(lo), formatVec(hi), formatVec(world.size - 1)));
                ok = false;
            } else {
                scene.box = {lo, hi - lo + 1};
                if (scene.box.cellCount() > cellBudget) {
                    context.diagnostics.error(
                        "E0012", a->value.loc,
                        fmt::format("the box has {} cells; the curves blocks of a file may solve {} cells in all "
                                    "({} left for this one)",
                                    scene.box.cellCount(), context.limits.maxSolveCells, cellBudget));
                    ok = false;
                } else {
                    cellBudget -= scene.box.cellCount();
                    boxRead = true;
                }
            }
        }
    } else {
        ok = false;
    }
    if (const ast::Assignment* a = keys.find("normals")) {
        const std::optional<size_t> mode = readChoice(context, *a, kNormalModes);
        ok = ok && mode.has_value();
        if (mode == size_t(1)) scene.options.normals = curves::NormalMode::PeronaMalik;
    }
    if (const ast::Assignment* a = keys.find("k")) {
        const std::optional<double> k = readNumber(context, *a, 1e-6, 1);
        ok = ok && k.has_value();
        if (k) scene.options.k = float(*k);
    }
    if (const ast::Assignment* a = keys.find("sweeps")) {
        const std::optional<int64_t> sweeps = readInteger(context, *a, 1, limits.maxSweeps);
        ok = ok && sweeps.has_value();
        if (sweeps) scene.options.sweeps = uint32_t(*sweeps);
    }
    if (const ast::Assignment* a = keys.find("smoothing")) {
        const std::optional<double> passes = readKey(context, *a, "curves");
        ok = ok && passes.has_value();
        if (passes) scene.options.smoothPasses = int32_t(*passes);
    }
    if (const ast::Assignment* a = keys.find("noise_frequency")) {
        const std::optional<double> f = readKey(context, *a, "curves");
        ok = ok && f.has_value();
        if (f) scene.noiseFrequency = float(*f);
    }
    if (const ast::Assignment* a = keys.find("noise_seed")) {
        const std::optional<double> seed = readKey(context, *a, "curves");
        ok = ok && seed.has_value();
        if (seed) scene.noiseSeed = uint32_t(*seed);
    }
    if (const ast::Assignment* a = keys.find("dead_zone")) {
        const std::optional<double> radius = readKey(context, *a, "curves");
        ok = ok && radius.has_value();
        if (radius) scene.inputOptions.deadZone = int32_t(*radius);
    }
    if (const ast::Assignment* a = keys.find("input_amplitude")) {
        const std::optional<double> v = readKey(context, *a, "curves");
        ok = ok && v.has_value();
        if (v) scene.inputOptions.amplitude = *v;
    }
    if (const ast::Assignment* a = keys.find("input_roughness")) {
        const std::optional<double> v = readKey(context, *a, "curves");
        ok = ok && v.has_value();
        if (v) scene.inputOptions.roughness = *v;
    }
    if (const ast::Assignment* a = keys.find("input_material")) {
        const std::optional<uint8_t> m = readMaterialKey(context, *a);
        ok = ok && m.has_value();
        if (m) scene.inputOptions.material = *m;
    }
    // After the box, which the inputs are sampled over.
    if (const ast::Assignment* a = keys.find("inputs")) {
        const bool read = boxRead && readInputs(context, file, *a, world, scene);
        ok = ok && read;
    }
    size_t index = 0;
    for (const ast::Block& member : block.blocks) {
        if (member.kind != "curve") {
            context.diagnostics.error("E0008", member.loc,
                                      fmt::format("unknown block '{}' in {}; it holds 'curve' blocks", member.kind,
                                                  where));
            ok = false;
            continue;
        }
        ++index;
        const std::string name =
            member.label ? fmt::format("curve '{}'", *member.label) : fmt::format("curve {} of {}", index, where);
        const std::optional<curves::FeatureCurve> curve = readCurve(context, member, name, limits);
        ok = ok && curve.has_value();
        if (curve) scene.curves.push_back(*curve);
    }
    if (!ok) return std::nullopt;
    if (!scene.inputs.empty()) return scene; // the inputs are seed surfaces: curves are optional
    if (scene.curves.empty()) {
        context.diagnostics.error("E0009", block.loc,
                                  fmt::format("{} has no curve; add one, as in 'curve edge {{ points = [[0, 8, 0], "
                                              "[8, 8, 0], [16, 8, 0], [24, 8, 0]]; constraint {{ t = 0; }} "
                                              "constraint {{ t = 1; }} }}'",
                                              where));
        return std::nullopt;
    }
    if (std::none_of(scene.curves.begin(), scene.curves.end(), [](const curves::FeatureCurve& c) { return c.seed; })) {
        context.diagnostics.error("E0009", block.loc,
                                  fmt::format("{} needs at least one seed curve ('curve NAME {{ points = ...; }}' "
                                              "with 'seed' left true): guidance curves alone pin no surface",
                                              where));
        return std::nullopt;
    }
    return scene;
}

// The work a run's solve may do that the keys alone do not bound: the Perona-Malik sweeps over the
// box (E0012 at the block, as the solve would throw it).
bool checkSolveWork(Context& context, const ast::Block& block, const curves::Scene& scene, const curves::Limits& limits) {
    if (scene.options.normals != curves::NormalMode::PeronaMalik) return true;
    const glm::ivec3 size = scene.box.size;
    const uint64_t sweeps = scene.options.sweeps != 0 ? scene.options.sweeps : uint64_t(std::max({size.x, size.y, size.z}));
    if (sweeps * scene.box.cellCount() <= limits.maxSweepCellUpdates) return true;
    context.diagnostics.error(
        "E0012", block.loc,
        curves::LimitError("Perona-Malik sweep cell updates", sweeps * scene.box.cellCount(), limits.maxSweepCellUpdates)
            .what());
    return false;
}

// W0210: no seed ribbon meets a cell of the box, so no cell is pinned (Omega_S is empty), the
// surface reaches none and the table is air in every cell: a curve drawn outside the box, most
// often. (A box whose seeds the noise displacement pushes out of every cell is air too; only the
// solve can tell, so that is not warned about.)
void warnAllAir(Context& context, const ast::Block& block, const curves::GatheredConstraints& gathered) {
    if (gathered.anySurface()) return;
    context.diagnostics.warning("W0210", block.loc,
                                fmt::format("curves '{}' solves to air in every cell of its box: no seed curve's "
                                            "ribbon pins a surface inside it; move the curves into the box "
                                            "(grid-local voxels) or widen it",
                                            *block.label));
}

} // namespace

std::vector<CurvesBlock> checkCurves(Context& context, const ast::File& file, const World& world,
                                     const std::vector<std::string>& stageNames) {
    const curves::Limits limits;
    std::vector<CurvesBlock> blocks;
    std::map<std::string, SourceLoc> names;
    uint64_t cellBudget = uint64_t(context.limits.maxSolveCells);
    for (const ast::Block& block : file.blocks) {
        if (block.kind != "curves") continue;
        if (!checkLabel(context, block, true) || !block.label) continue;
        CurvesBlock out;
        out.name = *block.label;
        out.loc = block.loc;
        out.source = "curves";
        if (!claimStageName(context, block, names, stageNames)) {
            blocks.push_back(std::move(out));
            continue;
        }
        std::optional<curves::Scene> scene = readScene(context, file, block, world, cellBudget, limits);
        if (scene && checkSolveWork(context, block, *scene, limits)) {
            try {
                scene->gathered = std::make_shared<const curves::GatheredConstraints>(
                    curves::gatherConstraints(scene->curves, scene->box, scene->options.seedValue, limits, scene->inputs,
                                              scene->inputOptions));
                warnAllAir(context, block, *scene->gathered);
                out.min = scene->box.min;
                out.size = scene->box.size;
                for (const curves::FeatureCurve& curve : scene->curves)
                    for (const curves::ConstraintPoint& point : curve.constraints)
                        if (point.material != kMaterialNone) out.materials.push_back(uint8_t(point.material));
                if (!scene->inputs.empty() && scene->inputOptions.material != kMaterialNone)
                    out.materials.push_back(uint8_t(scene->inputOptions.material));
                std::sort(out.materials.begin(), out.materials.end());
                out.materials.erase(std::unique(out.materials.begin(), out.materials.end()), out.materials.end());
                out.writesMaterials = !out.materials.empty();
                out.scene = std::make_shared<const curves::Scene>(std::move(*scene));
            } catch (const curves::ParameterError& e) {
                context.diagnostics.error("E0007", block.loc, e.what());
            } catch (const curves::LimitError& e) { // bounds on the voxelisation's work
                context.diagnostics.error("E0012", block.loc, e.what());
            }
        }
        blocks.push_back(std::move(out));
    }
    return blocks;
}

} // namespace voxc::check
