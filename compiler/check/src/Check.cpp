#include "voxc/check/Check.h"

#include "CheckCurves.h"
#include "CheckInputs.h"
#include "CheckTerrain.h"
#include "Materials.h"
#include "CheckKernelBounds.h"
#include "CheckStamps.h"
#include "Sections.h"
#include "voxc/stages/StageKind.h"
#include "Suggest.h"

#include "voxc/syntax/Parser.h"

#include <fmt/format.h>
#include <algorithm>
#include <map>
#include <set>

namespace voxc {

bool CheckResult::hasErrors() const {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

std::string CheckResult::rendered() const { return renderAll(diagnostics, source); }

namespace check {
namespace {

constexpr std::string_view kTopLevelBlocks[] = {"world", "start", "grammar", "pipeline", "material", "lsystem", "curves", "terrain", "heightmap", "mesh"};

// The first block of a kind that may appear once; later ones are E0003.
const ast::Block* uniqueBlock(Context& context, const ast::File& file, std::string_view kind) {
    const ast::Block* first = nullptr;
    for (const ast::Block& block : file.blocks) {
        if (block.kind != kind) continue;
        if (first)
            context.diagnostics.error("E0003", block.loc, fmt::format("a second '{}' block", kind),
                                      {{first->loc, "the first one is here"}});
        else
            first = &block;
    }
    return first;
}

// The W0209s of lsystem_cave features a pipeline stage carves (`staged`: the field stages'
// names), or that nothing stamps.
void warnCarvesNothing(Context& context, const Program& program, const std::set<std::string>& staged) {
    for (const Context::CarveWarning& warning : context.carveWarnings) {
        bool stamped = false;
        for (const Grammar& grammar : program.grammars)
            for (const Rule& rule : grammar.rules)
                for (const Stamp& stamp : rule.stamps) stamped = stamped || stamp.fieldName == warning.feature;
        if (staged.contains(warning.feature) || !stamped) context.diagnostics.warning("W0209", warning.loc, warning.message);
    }
}

void reportUnknownBlocks(Context& context, const ast::File& file) {
    for (const ast::Block& block : file.blocks) {
        if (std::find(std::begin(kTopLevelBlocks), std::end(kTopLevelBlocks), block.kind) != std::end(kTopLevelBlocks))
            continue;
        context.diagnostics.error("E0008", block.loc,
                                  fmt::format("unknown block '{}'{}", block.kind, didYouMean(block.kind, kTopLevelBlocks)));
    }
}

// Grammars in declaration order with unique names (E0003); `start` names the start stage.
std::vector<CheckedGrammar> checkGrammars(Context& context, const ast::File& file, const World* world) {
    std::vector<CheckedGrammar> grammars;
    std::map<std::string, SourceLoc> names;
    for (const ast::Block& block : file.blocks) {
        if (block.kind != "grammar") continue;
        if (block.label) {
            if (*block.label == "start")
                context.diagnostics.error("E0003", block.labelLoc,
                                          "a grammar cannot be named 'start': the pipeline uses that name for the "
                                          "start state");
            auto [it, inserted] = names.emplace(*block.label, block.labelLoc);
            if (!inserted)
                context.diagnostics.error("E0003", block.labelLoc,
                                          fmt::format("a grammar named '{}' already exists", *block.label),
                                          {{it->second, "first declared here"}});
        }
        if (auto grammar = checkGrammar(context, block, world)) grammars.push_back(std::move(*grammar));
    }
    return grammars;
}

Program checkProgram(Context& context, const ast::File& file, const std::string& path,
                     std::vector<CheckedLsystem>& lsystems) {
    for (const ast::ConstDecl& decl : file.constants) context.constants.declare(decl);
    context.constants.reportUnknownOverrides();
    reportUnknownBlocks(context, file);

    Program program;
    program.sourcePath = path;
    // First: every other block may name a material.
    program.materials = checkMaterials(context, file);
    std::optional<World> world;
    if (const ast::Block* block = uniqueBlock(context, file, "world"))
        world = checkWorld(context, *block);
    else
        context.diagnostics.error("E0009", {}, "missing the required 'world' block, e.g. 'world { size = [64, 64, 64]; }'");
    if (world && context.seed) world->seed = *context.seed;
    if (world) program.world = *world;
    if (const ast::Block* block = uniqueBlock(context, file, "start")) program.start = checkStart(context, *block);

    std::vector<CheckedGrammar> grammars = checkGrammars(context, file, world ? &*world : nullptr);
    for (const CheckedGrammar& grammar : grammars) program.grammars.push_back(grammar.grammar);

    std::vector<std::string> grammarNames;
    for (const ast::Block& grammarBlock : file.blocks)
        if (grammarBlock.kind == "grammar" && grammarBlock.label) grammarNames.push_back(*grammarBlock.label);
    lsystems = checkLsystems(context, file, path);
    std::vector<std::string> lsystemNames;
    for (const ast::Block& block : file.blocks)
        if (block.kind == "lsystem" && block.label) lsystemNames.push_back(*block.label);
    std::vector<std::string> stageNames = grammarNames;
    for (const ast::FieldDecl& field : file.fields) stageNames.push_back(field.name);
    for (const ast::FeatureDecl& feature : file.features) stageNames.push_back(feature.name);
    // Heightmap and mesh files, read and made maps before the curves blocks that voxelise them
    // and the fields that sample them.
    program.inputs = checkInputs(context, file, path);
    program.curves = checkCurves(context, file, program.world, stageNames);
    // Terrain blocks are solve blocks too: their tables run on the curves stage kind. They are
    // generated before the fields are lowered, which may sample their maps (context.maps).
    for (const CurvesBlock& block : program.curves) stageNames.push_back(block.name);
    for (CurvesBlock& block : checkTerrains(context, file, program.world, stageNames))
        program.curves.push_back(std::move(block));
    program.fields = checkFields(context, file, grammarNames);
    CheckedFeatures features = checkFeatures(context, file, grammarNames, program.world, lsystems);
    std::vector<std::optional<Field>> stampFields(program.fields.size()); // the plain fields have none
    for (std::optional<Field>& stampField : features.stampFields) stampFields.push_back(std::move(stampField));
    for (Field& feature : features.fields) program.fields.push_back(std::move(feature));
    resolveStampFields(context, program.grammars, grammars, program.fields, stampFields);
    for (const CurvesBlock& block : program.curves) {
        context.curvesNames.push_back(block.name);
        context.curvesKinds.push_back(block.source);
    }
    program.speleothems = std::move(features.speleothems);
    checkKernelBounds(context, program, grammars);

    program.pipeline.push_back({Stage::Kind::Start, 0, FieldMode::Set, {}, std::nullopt});
    const ast::Block* pipelineBlock = uniqueBlock(context, file, "pipeline");
    std::set<std::string> stagedFields; // the fields and features the pipeline runs as stages
    if (const ast::Block* block = pipelineBlock) {
        std::vector<std::string> fieldNames;
        for (const ast::FieldDecl& field : file.fields) fieldNames.push_back(field.name);
        std::vector<std::string> speleothemNames;
        std::vector<std::optional<uint8_t>> speleothemMaterials;
        for (const ast::FeatureDecl& feature : file.features)
            (feature.body.kind == kSpeleothemsGenerator ? speleothemNames : fieldNames).push_back(feature.name);
        for (const SpeleothemStage& speleothem : program.speleothems)
            speleothemMaterials.push_back(speleothem.params.material);
        std::vector<std::optional<uint8_t>> fieldMaterials(file.fields.size()); // plain fields name none
        fieldMaterials.insert(fieldMaterials.end(), features.materials.begin(), features.materials.end());
        for (const Stage& stage : checkPipeline(context, *block, grammarNames, fieldNames, fieldMaterials, lsystemNames,
                                                speleothemNames, speleothemMaterials)) {
            if (stage.kind == Stage::Kind::Field) stagedFields.insert(fieldNames.at(stage.index));
            program.pipeline.push_back(stage);
        }
    } else {
        for (uint32_t i = 0; i < program.grammars.size(); ++i) program.pipeline.push_back({Stage::Kind::Grammar, i, FieldMode::Set, {}, std::nullopt});
    }
    warnCarvesNothing(context, program, stagedFields);
    // The estimate and the warnings only make sense about a program that is otherwise correct.
    if (!context.diagnostics.hasErrors()) {
        stages::describePipeline(program);
        checkWork(context, program);
    }
    if (!context.diagnostics.hasErrors()) {
        for (const CheckedGrammar& grammar : grammars) analyseGrammar(context, grammar);
        warnUnused(context, file, program, pipelineBlock != nullptr);
    }
    return program;
}

} // namespace
} // namespace check

CheckResult checkSource(const SourceFile& source, const Limits& limits) {
    return checkSource(source, CheckOptions{limits, {}});
}

CheckResult checkSource(const SourceFile& source, const CheckOptions& options) {
    Diagnostics diagnostics;
    CheckResult result;
    result.source = source;
    if (!reportIfNotText(source, diagnostics)) {
        ast::File file = parse(source, diagnostics, uint32_t(options.limits.maxNesting));
        if (!diagnostics.hasErrors()) {
            check::Context context{diagnostics, options.limits, check::Constants(diagnostics, options.constOverrides), {}};
            context.seed = options.seed;
            context.region = options.region;
            context.readRuleFile = options.readRuleFile;
            context.readInputFile = options.readInputFile;
            std::vector<CheckedLsystem> lsystems;
            Program program = check::checkProgram(context, file, source.path(), lsystems);
            if (!diagnostics.hasErrors()) {
                result.program = std::move(program);
                result.lsystems = std::move(lsystems);
            }
        }
    }
    result.diagnostics = diagnostics.take();
    addSuggestionFixIts(result.diagnostics, source);
    return result;
}

CheckResult checkFile(const std::string& path, const Limits& limits) {
    return checkFile(path, CheckOptions{limits, {}});
}

CheckResult checkFile(const std::string& path, const CheckOptions& options) {
    Diagnostics diagnostics;
    std::optional<SourceFile> source = loadSourceFile(path, diagnostics, size_t(options.limits.maxSourceBytes));
    if (!source) {
        CheckResult result;
        result.source = SourceFile(path, "");
        result.diagnostics = diagnostics.take();
        return result;
    }
    return checkSource(*source, options);
}

} // namespace voxc
