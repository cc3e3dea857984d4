// `material NAME { id = N; color = [r, g, b]; }` blocks and the material namespace.
#include "Materials.h"

#include "Context.h"
#include "Suggest.h"
#include "Values.h"

#include <fmt/format.h>
#include <map>

namespace voxc::check {

namespace {

constexpr std::string_view kNone = "none";
constexpr int kMaxMaterialId = 255;

} // namespace

void MaterialNames::declare(const std::string& name, uint8_t id) {
    for (const auto& [known, knownId] : names_)
        if (known == name) return;
    names_.emplace_back(name, id);
}

std::optional<uint8_t> MaterialNames::resolve(Diagnostics& diagnostics, std::string_view name, SourceLoc loc) const {
    if (name == kNone) return kMaterialNone;
    for (const auto& [known, id] : names_)
        if (known == name) return id;
    std::vector<std::string_view> candidates{kNone};
    for (const auto& [known, id] : names_) candidates.push_back(known);
    diagnostics.error("E0002", loc,
                      fmt::format("unknown material '{}'{}", name,
                                  names_.empty() ? "; declare it with 'material " + std::string(name) + " { }'"
                                                 : didYouMean(name, candidates)));
    return std::nullopt;
}

std::optional<uint8_t> MaterialNames::resolve(Diagnostics& diagnostics, const ast::Expr& expr,
                                              std::string_view what) const {
    if (expr.kind != ast::Expr::Kind::Name) {
        diagnostics.error("E0010", expr.loc, fmt::format("{} expects a material name, as in 'rock' or 'none'", what));
        return std::nullopt;
    }
    return resolve(diagnostics, expr.name, expr.loc);
}

std::optional<uint8_t> readMaterialKey(Context& context, const ast::Assignment& a) {
    const std::string what = fmt::format("'{}'", a.key);
    if (a.value.isList()) {
        context.diagnostics.error("E0010", a.value.loc,
                                  fmt::format("{} expects a material name, as in 'rock' or 'none'", what));
        return std::nullopt;
    }
    return context.materials.resolve(context.diagnostics, *a.value.scalar, what);
}

namespace {

struct MaterialBlock {
    const ast::Block* block;
    Material material;
    bool explicitId = false;
    SourceLoc idLoc;
};

// Keys and name of one block; the id is left at its default, which checkMaterials resolves.
std::optional<MaterialBlock> checkMaterial(Context& context, const ast::Block& block, size_t index) {
    static constexpr std::string_view kKeys[] = {"id", "color"};
    if (!block.label) {
        context.diagnostics.error("E0009", block.loc, "'material' needs a name, as in 'material rock { ... }'");
        return std::nullopt;
    }
    const std::string where = fmt::format("material '{}'", *block.label);
    rejectUnexpectedMembers(context, block, where, {});
    BlockKeys keys(context, block, where, kKeys);
    const int errorsBefore = context.diagnostics.errorCount();

    MaterialBlock out{&block, {}, false, block.labelLoc};
    out.material.name = *block.label;
    out.material.loc = block.labelLoc;
    if (index < size_t(kMaxMaterialId)) out.material.id = uint8_t(index + 1);
    if (const ast::Assignment* a = keys.find("id")) {
        out.explicitId = true;
        out.idLoc = a->value.loc;
        if (auto id = readInteger(context, *a, 1, kMaxMaterialId)) out.material.id = uint8_t(*id);
    }
    if (const ast::Assignment* a = keys.find("color"))
        if (auto color = readNumberVec3(context, *a, 0.0, 1.0))
            out.material.color = glm::vec3(float((*color)[0]), float((*color)[1]), float((*color)[2]));
    if (context.diagnostics.errorCount() != errorsBefore) return std::nullopt;
    return out;
}

} // namespace

std::vector<Material> checkMaterials(Context& context, const ast::File& file) {
    std::vector<MaterialBlock> checked;
    std::map<std::string, SourceLoc> names;
    size_t index = 0;
    for (const ast::Block& block : file.blocks) {
        if (block.kind != "material") continue;
        const size_t position = index++;
        if (block.label && *block.label == kNone) {
            context.diagnostics.error("E0003", block.labelLoc,
                                      "'none' is the builtin material 0 (every voxel's material until something "
                                      "writes one) and cannot be declared");
            continue;
        }
        bool duplicate = false;
        if (block.label) {
            auto [it, inserted] = names.emplace(*block.label, block.labelLoc);
            duplicate = !inserted;
            if (duplicate)
                context.diagnostics.error("E0003", block.labelLoc,
                                          fmt::format("a material named '{}' already exists", *block.label),
                                          {{it->second, "first declared here"}});
        }
        auto material = checkMaterial(context, block, position);
        if (duplicate) continue; // its id would only repeat the complaint
        if (material && position >= size_t(kMaxMaterialId) && !material->explicitId) {
            context.diagnostics.error("E0012", block.labelLoc,
                                      fmt::format("material '{}' is the {}th material; at most {} fit in the 8-bit "
                                                  "material ids",
                                                  *block.label, position + 1, kMaxMaterialId));
            material.reset();
        }
        if (block.label) context.materials.declare(*block.label, material ? material->material.id : kMaterialNone);
        if (material) checked.push_back(std::move(*material));
    }

    // Ids are unique: an explicit id may collide with another's explicit or default id.
    std::map<uint8_t, const MaterialBlock*> ids;
    std::vector<Material> materials;
    for (const MaterialBlock& entry : checked) {
        auto [it, inserted] = ids.emplace(entry.material.id, &entry);
        if (inserted) {
            materials.push_back(entry.material);
            continue;
        }
        const MaterialBlock& first = *it->second;
        const auto describe = [](const MaterialBlock& m) {
            return m.explicitId ? fmt::format("material '{}' has id {}", m.material.name, m.material.id)
                                : fmt::format("material '{}' has the default id {} (1 + its position among the "
                                              "materials)",
                                              m.material.name, m.material.id);
        };
        context.diagnostics.error("E0003", entry.idLoc,
                                  fmt::format("{}, which '{}' already uses{}", describe(entry), first.material.name,
                                              entry.explicitId ? "" : "; give it an explicit 'id'"),
                                  {{first.idLoc, describe(first)}});
    }
    return materials;
}

} // namespace voxc::check
