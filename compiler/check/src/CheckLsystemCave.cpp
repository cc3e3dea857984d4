// `feature NAME = lsystem_cave { lsystem = NET; radius = 6; ... }` (docs/language.md, "Features";
// docs/architecture.md, "Carving"): the named lsystem is expanded, interpreted and connected here, at
// check time (as `voxc lsystem` does), and its skeleton becomes the carve's point set and field.
#include "CheckLsystemCave.h"

#include "Materials.h"
#include "Suggest.h"
#include "Values.h"

#include "voxc/generators/lsystem/Carve.h"
#include "voxc/generators/lsystem/Connect.h"
#include "voxc/generators/lsystem/Expand.h"

#include <fmt/format.h>
#include <glm/common.hpp>

namespace voxc::check {

namespace {

using lsystem::CarveParams;

struct NumberKey {
    std::string_view name;
    double min, max;
    double CarveParams::*member;
};

// Ranges as lsystem::checkCarveParams; spacing 0 means "the segment's radius", room_radius 0 "radius".
constexpr NumberKey kNumberKeys[] = {
    {"radius", 0.5, 256, &CarveParams::radius},
    {"room_radius", 0, 256, &CarveParams::roomRadius},
    {"spacing", 0, 256, &CarveParams::spacing},
    {"clearance", 0.5, 256, &CarveParams::clearance},
    {"curl_amplitude", 0, 256, &CarveParams::curlAmplitude},
    {"curl_frequency", 0, 16, &CarveParams::curlFrequency},
    {"y_limit", 0, 1, &CarveParams::yLimit},
    {"simplex_frequency", 0, 16, &CarveParams::simplexFrequency},
    {"simplex_amplitude", 0, 16, &CarveParams::simplexAmplitude},
    {"voronoi_frequency", 0, 16, &CarveParams::voronoiFrequency},
    {"voronoi_amplitude", 0, 16, &CarveParams::voronoiAmplitude},
    {"modulation_frequency", 0, 16, &CarveParams::modulationFrequency},
    {"min_scale", 0.05, 16, &CarveParams::minScale},
    {"max_scale", 0.05, 16, &CarveParams::maxScale},
};
constexpr std::string_view kLsystemKey = "lsystem";

// The lsystem block `lsystem = NAME;` names, or a located error.
const CheckedLsystem* readLsystemKey(Context& context, const ast::Assignment& a, const ast::File& file,
                                     const std::vector<CheckedLsystem>& lsystems) {
    const ast::Expr* expr = a.value.isList() ? nullptr : a.value.scalar.get();
    if (!expr || expr->kind != ast::Expr::Kind::Name) {
        context.diagnostics.error("E0010", a.value.loc, "'lsystem' expects the name of an lsystem block, as in 'net'");
        return nullptr;
    }
    for (const CheckedLsystem& checked : lsystems)
        if (checked.name == expr->name) return &checked;
    std::vector<std::string_view> names;
    for (const ast::Block& block : file.blocks)
        if (block.kind == "lsystem" && block.label) {
            if (*block.label == expr->name) return nullptr; // declared, but its errors are already reported
            names.push_back(*block.label);
        }
    context.diagnostics.error("E0002", a.value.loc,
                              fmt::format("no lsystem block named '{}'{}", expr->name, suggestOrList(expr->name, names)));
    return nullptr;
}

// W0209: no centre or segment reaches the grid, so the feature leaves every voxel as it is.
std::string carvesNothing(const std::string& name, const lsystem::Skeleton& skeleton, const World& world) {
    if (skeleton.segments.empty()) return fmt::format("lsystem '{}' draws no segment, so this carve changes nothing", name);
    glm::dvec3 lo = skeleton.segments.front().from, hi = lo;
    for (const lsystem::Segment& s : skeleton.segments)
        for (glm::dvec3 p : {s.from, s.to}) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::ivec3 last = world.origin + world.size - 1;
    return fmt::format("the skeleton of lsystem '{}' ([{}, {}, {}] to [{}, {}, {}]) is too far from the grid "
                       "([{}, {}, {}] to [{}, {}, {}]) for this carve to reach it; move its 'start'",
                       name, formatNumber(lo.x), formatNumber(lo.y), formatNumber(lo.z), formatNumber(hi.x),
                       formatNumber(hi.y), formatNumber(hi.z), world.origin.x, world.origin.y, world.origin.z, last.x,
                       last.y, last.z);
}

} // namespace

std::optional<CheckedLsystemCave> checkLsystemCave(Context& context, const ast::FeatureDecl& decl, const World& world,
                                                   const ast::File& file, const std::vector<CheckedLsystem>& lsystems) {
    const ast::Block& body = decl.body;
    const std::string where = "'lsystem_cave' feature";
    checkLabel(context, body, false);
    rejectUnexpectedMembers(context, body, where, {});
    std::vector<std::string_view> keyNames{kLsystemKey, kMaterialKey};
    for (const NumberKey& key : kNumberKeys) keyNames.push_back(key.name);
    BlockKeys keys(context, body, where, keyNames);

    CheckedLsystemCave out;
    bool ok = true;
    if (const ast::Assignment* a = keys.find(kMaterialKey)) {
        out.material = readMaterialKey(context, *a);
        ok = out.material.has_value();
    }
    const ast::Assignment* lsystemKey = keys.require(kLsystemKey);
    const CheckedLsystem* net = lsystemKey ? readLsystemKey(context, *lsystemKey, file, lsystems) : nullptr;
    ok = ok && net != nullptr;
    CarveParams params;
    for (const NumberKey& key : kNumberKeys) {
        const ast::Assignment* a = keys.find(key.name);
        if (!a) continue;
        const std::optional<double> value = readNumber(context, *a, key.min, key.max);
        if (value) params.*key.member = *value;
        ok = ok && value.has_value();
    }
    if (!ok) return std::nullopt;
    if (params.spacing != 0 && params.spacing < 0.25) {
        context.diagnostics.error("E0007", keys.find("spacing")->value.loc,
                                  fmt::format("'spacing' = {} is below 0.25 (0 means the radius)",
                                              formatNumber(params.spacing)));
        return std::nullopt;
    }
    if (params.roomRadius != 0 && params.roomRadius < 0.5) {
        context.diagnostics.error("E0007", keys.find("room_radius")->value.loc,
                                  fmt::format("'room_radius' = {} is below 0.5 (0 means 'radius')",
                                              formatNumber(params.roomRadius)));
        return std::nullopt;
    }
    if (params.maxScale < params.minScale) {
        const ast::Assignment* a = keys.find("max_scale");
        if (!a) a = keys.find("min_scale");
        context.diagnostics.error("E0007", a->value.loc,
                                  fmt::format("'max_scale' ({}) is below 'min_scale' ({})", formatNumber(params.maxScale),
                                              formatNumber(params.minScale)));
        return std::nullopt;
    }

    // Bounded work: expansion, segments and lists all throw LimitError before allocating.
    try {
        const lsystem::Definition& definition = net->definition;
        const lsystem::Expansion expansion = lsystem::expand(definition);
        lsystem::Skeleton skeleton = lsystem::interpret(definition, expansion.symbols, expansion.types);
        lsystem::connectBranches(skeleton, net->connect, definition.seed, definition.limits);
        lsystem::CarveLimits limits;
        limits.maxListEntries -= std::min(limits.maxListEntries, context.pointSetListEntries);
        auto set = lsystem::carvePointSet(skeleton, params, world.seed, world.origin, world.size, limits);
        context.pointSetListEntries += set->bins.centreItems.size() + set->bins.segmentItems.size();
        if (set->bins.centreItems.empty() && set->bins.segmentItems.empty())
            context.carveWarnings.push_back({decl.name, lsystemKey->value.loc, carvesNothing(net->name, skeleton, world)});
        // A stamp's turtle starts at its frame's origin: the network moved back by its start.
        out.stampField = lsystem::carveField(movedPointSet(*set, -definition.params.start), params, world.seed,
                                             lsystem::CarveFrame::Stamp);
        out.field = lsystem::carveField(std::move(set), params, world.seed);
    } catch (const lsystem::LimitError& e) {
        context.diagnostics.error("E0012", lsystemKey->value.loc, fmt::format("lsystem '{}': {}", net->name, e.what()));
        return std::nullopt;
    }
    for (Field* field : {&out.field, &out.stampField}) {
        field->name = decl.name;
        field->loc = decl.loc;
        for (FieldNode& node : field->nodes) node.loc = body.loc;
    }
    return out;
}

} // namespace voxc::check
