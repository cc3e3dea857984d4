// W0206-W0208: declarations the pipeline never uses. Each is work the user wrote that has no
// effect on the result, most often a stage left out of the pipeline or a misspelt material.
#include "Sections.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::check {

namespace {

// Material ids anything in the program tests or writes.
std::vector<bool> usedMaterials(const Program& program) {
    std::vector<bool> used(256, false);
    auto use = [&](std::optional<uint8_t> id) {
        if (id) used[*id] = true;
    };
    for (const StartShape& shape : program.start) use(shape.material);
    for (const Grammar& grammar : program.grammars)
        for (const Rule& rule : grammar.rules) {
            for (const SymbolCell& cell : rule.symbol)
                for (const MaterialPredicate& predicate : cell.materialPredicates) use(predicate.material);
            for (const TransformCell& cell : rule.transform) use(cell.material);
            for (const Stamp& stamp : rule.stamps) use(stamp.material);
        }
    for (const Stage& stage : program.pipeline) use(stage.material);
    // A curves stage writes the materials its constraint points name (a terrain stage, those its table holds).
    for (const Stage& stage : program.pipeline)
        if (stage.kind == Stage::Kind::Curves)
            for (uint8_t id : program.curves.at(stage.index).materials) used[id] = true;
    return used;
}

} // namespace

void warnUnused(Context& context, const ast::File& file, const Program& program, bool hasPipelineBlock) {
    std::vector<bool> grammarRuns(program.grammars.size(), false);
    std::vector<bool> fieldRuns(program.fields.size(), false);
    for (const Stage& stage : program.pipeline) {
        if (stage.kind == Stage::Kind::Grammar) grammarRuns[stage.index] = true;
        if (stage.kind == Stage::Kind::Field) fieldRuns[stage.index] = true;
    }
    // A field a running grammar stamps runs too; by name, as a stamp of an lsystem_cave reads a
    // copy of it.
    for (size_t g = 0; g < program.grammars.size(); ++g)
        for (const Rule& rule : program.grammars[g].rules)
            for (const Stamp& stamp : rule.stamps)
                for (size_t i = 0; i < program.fields.size(); ++i)
                    if (grammarRuns[g] && program.fields[i].name == stamp.fieldName) fieldRuns[i] = true;
    const std::string why = hasPipelineBlock ? "the pipeline does not name it"
                                             : "there is no 'pipeline' block, so only the grammars run";
    // program.fields holds the declared fields, then the features, as the pipeline indexes them,
    // then the stamps' copies of lsystem_caves (named like their feature, which speaks for them).
    const size_t declared = file.fields.size() + std::count_if(file.features.begin(), file.features.end(),
                                                               [](const ast::FeatureDecl& feature) {
                                                                   return feature.body.kind != kSpeleothemsGenerator;
                                                               });
    for (size_t i = 0; i < std::min(declared, program.fields.size()); ++i) {
        if (fieldRuns[i]) continue;
        const bool isFeature = i >= file.fields.size();
        context.diagnostics.warning("W0206", program.fields[i].loc,
                                    fmt::format("{} '{}' is never used: {}", isFeature ? "feature" : "field",
                                                program.fields[i].name, why));
    }
    for (size_t i = 0; i < program.grammars.size(); ++i)
        if (!grammarRuns[i])
            context.diagnostics.warning("W0207", program.grammars[i].loc,
                                        fmt::format("grammar '{}' is never used: the pipeline does not name it",
                                                    program.grammars[i].name));
    for (size_t i = 0; i < program.speleothems.size(); ++i)
        if (std::none_of(program.pipeline.begin(), program.pipeline.end(), [&](const Stage& stage) {
                return stage.kind == Stage::Kind::Speleothems && stage.index == i;
            }))
            context.diagnostics.warning("W0206", program.speleothems[i].loc,
                                        fmt::format("feature '{}' is never used: {}", program.speleothems[i].name, why));
    // A terrain whose map a field samples is used, whether or not the pipeline names it.
    const auto sampled = [&](const std::string& name) {
        return std::any_of(program.fields.begin(), program.fields.end(), [&](const Field& field) {
            return std::any_of(field.nodes.begin(), field.nodes.end(), [&](const FieldNode& node) {
                return node.kind == FieldNode::Kind::Map && node.map->name == name;
            });
        });
    };
    for (size_t i = 0; i < program.curves.size(); ++i)
        if (std::none_of(program.pipeline.begin(), program.pipeline.end(),
                         [&](const Stage& stage) { return stage.kind == Stage::Kind::Curves && stage.index == i; }) &&
            !sampled(program.curves[i].name))
            context.diagnostics.warning("W0206", program.curves[i].loc,
                                        fmt::format("{} '{}' is never used: {}", program.curves[i].source,
                                                    program.curves[i].name, why));
    const std::vector<bool> used = usedMaterials(program);
    for (const Material& material : program.materials)
        if (!used[material.id])
            context.diagnostics.warning("W0208", material.loc,
                                        fmt::format("material '{}' is never used: no shape, rule or stage tests or "
                                                    "writes it",
                                                    material.name));
}

} // namespace voxc::check
