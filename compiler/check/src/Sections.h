#pragma once
// One function per top-level block kind. Each reports its own errors and returns what it
// could check; the caller assembles the Program only when no error was reported.
#include "Context.h"

#include "voxc/check/Check.h"
#include "voxc/program/Program.h"
#include "voxc/syntax/Ast.h"

#include <optional>
#include <vector>

namespace voxc::check {

// Locations the warning analyses need, which Program does not keep.
struct RuleSyntax {
    SourceLoc sizeLoc;
    SourceLoc symbolLoc;
    std::vector<SourceLoc> symbolCells; // in Program's cell order (cellIndex)
    std::vector<SourceLoc> stampReachLocs; // per Rule::stamps entry: its `reach` value
    std::vector<SourceLoc> stampOffsetLocs; // per Rule::stamps entry: its `offset` value, else its name
    // The declared rule this one is (index among the grammar's declared rules); a symmetry
    // variant shares it with its original, so warnings are reported once per declared rule.
    size_t declaredIndex = 0;
    bool isVariant = false;
};

struct CheckedRule {
    Rule rule;
    RuleSyntax syntax;
};

struct CheckedGrammar {
    Grammar grammar;
    std::vector<RuleSyntax> rules; // parallel to grammar.rules
};

// Nothing when `size` is missing or invalid; errors in other keys are reported but the
// world is still returned, so that grammar bounds can be checked against its size.
std::optional<World> checkWorld(Context& context, const ast::Block& block);

std::vector<StartShape> checkStart(Context& context, const ast::Block& block);

// `world` is null when the world block is missing or invalid; bounds are then not checked
// against the grid.
std::optional<CheckedGrammar> checkGrammar(Context& context, const ast::Block& block, const World* world);

// Every `lsystem NAME { ... }` block that checks, in declaration order; `sourcePath` locates
// rule files (`rules = "caves.rules";`), which are read relative to it.
std::vector<CheckedLsystem> checkLsystems(Context& context, const ast::File& file, const std::string& sourcePath);

// The stages after Start, as indices into `grammarNames` / `fieldNames`: every grammar and
// field declared, in order, including those with errors, so that their names are not
// reported as unknown as well. Field stages need a mode word: `subtract cave;`, and may name
// a material: `subtract cave material sand;`; without one a stage writes the material in
// `fieldMaterials` (parallel to fieldNames: a feature's `material` key), if any. A stage
// naming one of `lsystemNames` is E0013: L-systems cannot be carved yet. A stage naming one of
// `speleothemNames` (indices into Program::speleothems) takes no mode and may name a material.
std::vector<Stage> checkPipeline(Context& context, const ast::Block& block,
                                 const std::vector<std::string>& grammarNames,
                                 const std::vector<std::string>& fieldNames,
                                 const std::vector<std::optional<uint8_t>>& fieldMaterials,
                                 const std::vector<std::string>& lsystemNames,
                                 const std::vector<std::string>& speleothemNames,
                                 const std::vector<std::optional<uint8_t>>& speleothemMaterials);

// User functions and fields: every field's DAG in declaration order. Field names must differ
// from each other, from `start` and from `grammarNames` (one namespace for pipeline stages).
std::vector<Field> checkFields(Context& context, const ast::File& file, const std::vector<std::string>& grammarNames);

struct CheckedFeatures {
    std::vector<Field> fields;                    // the field features that checked, declaration order
    // Parallel to `fields`: the field a stamp of the feature reads instead, where it differs (an
    // lsystem_cave's carve measured from the stamp's frame).
    std::vector<std::optional<Field>> stampFields;
    std::vector<std::optional<uint8_t>> materials; // each declared field feature's `material` key
    std::vector<SpeleothemStage> speleothems;      // the speleothem features that checked, declaration order
};

// The generator name of speleothem features, which are pipeline stages of their own, not fields.
constexpr std::string_view kSpeleothemsGenerator = "speleothems";

// One `feature NAME = speleothems { ... }`; `fieldsAbove`: the features checked before it, where
// `keep_clear` finds its lsystem_cave.
std::optional<SpeleothemStage> checkSpeleothems(Context& context, const ast::FeatureDecl& decl,
                                                const std::vector<Field>& fieldsAbove);

// Features (`feature name = arch { ... }`), each expanded into a field, in declaration order.
// Their names share the namespace of fields and of `stageNames` (grammars); `world` gives the
// seed for generators that draw noise at check time and the chunk grid an lsystem_cave bins
// its points on; `lsystems` are the checked lsystem blocks an lsystem_cave names.
CheckedFeatures checkFeatures(Context& context, const ast::File& file, const std::vector<std::string>& stageNames,
                              const World& world, const std::vector<CheckedLsystem>& lsystems);

// E0012 at the stage where the pipeline's estimated work (docs/language.md, "Work estimate")
// passes Limits::maxWork, or its distinct kernels pass Limits::maxKernels. Call on a program
// without errors.
void checkWork(Context& context, const Program& program);

// W0206-W0208: fields and features, grammars and materials the pipeline never uses. Call on a
// program without errors; `hasPipelineBlock` is false when the pipeline is the default one.
void warnUnused(Context& context, const ast::File& file, const Program& program, bool hasPipelineBlock);

// W0201-W0204 for one checked grammar.
void analyseGrammar(Context& context, const CheckedGrammar& grammar);

} // namespace voxc::check
