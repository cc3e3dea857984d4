// `pipeline { start; caves; subtract tunnel material sand; paint low material rock; overhang; }`
#include "Sections.h"
#include "Suggest.h"
#include "Values.h"

#include <algorithm>
#include <functional>
#include <fmt/format.h>
#include <unordered_map>

namespace voxc::check {

namespace {

constexpr std::string_view kModeNames[] = {"set", "union", "subtract", "intersect", "paint"};
constexpr FieldMode kModes[] = {FieldMode::Set, FieldMode::Union, FieldMode::Subtract, FieldMode::Intersect,
                                FieldMode::Paint};
constexpr std::string_view kClauses[] = {"material"};

std::optional<FieldMode> parseMode(Context& context, const ast::NameStatement& entry) {
    for (size_t i = 0; i < std::size(kModeNames); ++i)
        if (*entry.mode == kModeNames[i]) return kModes[i];
    context.diagnostics.error("E0011", entry.modeLoc,
                              fmt::format("unknown field mode '{}'{}", *entry.mode,
                                          suggestOrList(*entry.mode, kModeNames)));
    return std::nullopt;
}

// Only field and speleothem stages take a clause (E0010 on `start` and grammars, as for a mode word).
bool rejectClause(Context& context, const ast::NameStatement& entry, std::string_view why) {
    if (!entry.clause) return true;
    context.diagnostics.error("E0010", entry.clause->wordLoc,
                              fmt::format("'{}' {}; only field and speleothem stages take a '{}' clause", entry.name, why,
                                          entry.clause->word));
    return false;
}

// The material of a field stage: its own `material NAME` clause, else the feature's key.
// Nothing when the clause has an error (reported) or neither names one; `ok` says which.
std::optional<uint8_t> stageMaterial(Context& context, const ast::NameStatement& entry,
                                     std::optional<uint8_t> fieldMaterial, bool& ok) {
    ok = true;
    if (!entry.clause) return fieldMaterial;
    const ast::StageClause& clause = *entry.clause;
    if (clause.word != kClauses[0]) {
        context.diagnostics.error("E0008", clause.wordLoc,
                                  fmt::format("unknown clause '{}' after stage '{}'{}", clause.word, entry.name,
                                              suggestOrList(clause.word, kClauses)));
        ok = false;
        return std::nullopt;
    }
    std::optional<uint8_t> material = context.materials.resolve(context.diagnostics, clause.operand, clause.operandLoc);
    ok = material.has_value();
    return material;
}

// `union cliffs;`: a solve stage (a curves or terrain block) takes a combining mode; its materials
// are the block's own.
void checkCurvesEntry(Context& context, const ast::NameStatement& entry, uint32_t index, std::vector<Stage>& stages) {
    const std::string& kind = context.curvesKinds.at(index);
    const std::string materialKeys = kind == "terrain" ? "the block's 'material' and 'deposit_material' keys"
                                                       : "its constraint points' 'material' keys";
    if (!entry.mode) {
        context.diagnostics.error("E0009", entry.loc,
                                  fmt::format("{1} stage '{0}' needs a mode: 'set {0}', 'union {0}', 'subtract "
                                              "{0}' or 'intersect {0}'",
                                              entry.name, kind));
        return;
    }
    const std::optional<FieldMode> mode = parseMode(context, entry);
    if (!mode) return;
    if (*mode == FieldMode::Paint) {
        context.diagnostics.error("E0010", entry.modeLoc,
                                  fmt::format("'{}' is a {} block; it takes 'set', 'union', 'subtract' or "
                                              "'intersect' (its materials come from {})",
                                              entry.name, kind, materialKeys));
        return;
    }
    if (entry.clause) {
        context.diagnostics.error("E0010", entry.clause->wordLoc,
                                  fmt::format("'{}' is a {} block: its materials come from {}, not a '{}' clause",
                                              entry.name, kind, materialKeys, entry.clause->word));
        return;
    }
    stages.push_back({Stage::Kind::Curves, index, *mode, entry.loc, std::nullopt});
}

// A `;` missing between two entries on separate lines makes them parse as one (`weather` then
// `subtract tunnel;` reads as stage `weather` with the clause `subtract tunnel`). Such an entry
// splits, at a line break, into words that are a whole entry on their own and words that begin
// one (a mode or a stage's name): E0001 at the end of the first part, with ';' as the fix-it.
bool reportMissingSemicolon(Context& context, const ast::NameStatement& entry,
                            const std::function<bool(std::string_view)>& isStage,
                            const std::function<bool(std::string_view)>& takesMode) {
    struct Word {
        std::string_view text;
        SourceLoc loc;
    };
    std::vector<Word> words;
    if (entry.mode) words.push_back({*entry.mode, entry.modeLoc});
    words.push_back({entry.name, entry.loc});
    if (entry.clause) {
        words.push_back({entry.clause->word, entry.clause->wordLoc});
        words.push_back({entry.clause->operand, entry.clause->operandLoc});
    }
    const auto isMode = [](std::string_view word) {
        return std::find(std::begin(kModeNames), std::end(kModeNames), word) != std::end(kModeNames);
    };
    for (size_t split = 1; split < words.size(); ++split) {
        const Word& last = words[split - 1];
        const Word& next = words[split];
        if (next.loc.line <= last.loc.line) continue;
        const bool wholeEntry = split == 1 ? isStage(words[0].text) && !takesMode(words[0].text)
                                           : split == 2 && isMode(words[0].text) && takesMode(words[1].text);
        if (!wholeEntry || !(isMode(next.text) || isStage(next.text))) continue;
        SourceLoc at = last.loc;
        at.column += at.length;
        at.length = 1;
        SourceLoc insert = at;
        insert.length = 0;
        context.diagnostics.error("E0001", at, fmt::format("expected ';' after '{}'", last.text), {}, {{insert, ";"}});
        return true;
    }
    return false;
}

} // namespace

std::vector<Stage> checkPipeline(Context& context, const ast::Block& block,
                                 const std::vector<std::string>& grammarNames,
                                 const std::vector<std::string>& fieldNames,
                                 const std::vector<std::optional<uint8_t>>& fieldMaterials,
                                 const std::vector<std::string>& lsystemNames,
                                 const std::vector<std::string>& speleothemNames,
                                 const std::vector<std::optional<uint8_t>>& speleothemMaterials) {
    const std::string where = "'pipeline' block";
    checkLabel(context, block, false);
    rejectUnexpectedMembers(context, block, where, {.names = true});
    for (const ast::Assignment& a : block.assignments)
        context.diagnostics.error("E0008", a.loc,
                                  fmt::format("unexpected key '{}' in {}; it lists stages as 'start; NAME;'", a.key,
                                              where));
    // `start` then a stage without the ';' between them still begins with start (reported below).
    if (block.names.empty() || block.names.front().mode.value_or(block.names.front().name) != "start")
        context.diagnostics.error("E0009", block.loc, "the pipeline must begin with 'start'");

    std::vector<std::string_view> known{"start"};
    for (const std::string& name : grammarNames) known.push_back(name);
    for (const std::string& name : fieldNames) known.push_back(name);
    for (const std::string& name : context.curvesNames) known.push_back(name);
    for (const std::string& name : speleothemNames) known.push_back(name);
    // The first declaration of each name, found by lookup: a pipeline may name thousands of stages.
    std::unordered_map<std::string_view, uint32_t> grammarIndex, fieldIndex;
    for (size_t i = 0; i < grammarNames.size(); ++i) grammarIndex.emplace(grammarNames[i], uint32_t(i));
    for (size_t i = 0; i < fieldNames.size(); ++i) fieldIndex.emplace(fieldNames[i], uint32_t(i));
    const auto isStage = [&](std::string_view name) {
        return name == "start" || grammarIndex.count(name) != 0 || fieldIndex.count(name) != 0 ||
               std::find(context.curvesNames.begin(), context.curvesNames.end(), name) != context.curvesNames.end() ||
               std::find(speleothemNames.begin(), speleothemNames.end(), name) != speleothemNames.end();
    };
    const auto takesMode = [&](std::string_view name) {
        return fieldIndex.count(name) != 0 ||
               std::find(context.curvesNames.begin(), context.curvesNames.end(), name) != context.curvesNames.end();
    };
    std::vector<Stage> stages;
    for (size_t i = 0; i < block.names.size(); ++i) {
        const ast::NameStatement& entry = block.names[i];
        if (reportMissingSemicolon(context, entry, isStage, takesMode)) continue;
        // Three words parse as a stage and a clause; `subtract cave material;` is a clause
        // missing its name.
        if (entry.clause && !entry.mode && entry.clause->operand == kClauses[0]) {
            context.diagnostics.error("E0009", entry.clause->operandLoc,
                                      fmt::format("'material' needs a material name, as in '{} {} material rock;'",
                                                  entry.name, entry.clause->word));
            continue;
        }
        if (entry.name == "start") {
            if (i != 0 || entry.mode)
                context.diagnostics.error("E0007", entry.loc, "'start' can only be the first stage of the pipeline");
            else
                rejectClause(context, entry, "is the start state (give its shapes a 'material' key instead)");
            continue;
        }
        auto grammar = grammarIndex.find(entry.name);
        auto field = fieldIndex.find(entry.name);
        if (grammar != grammarIndex.end()) {
            if (entry.mode)
                context.diagnostics.error("E0010", entry.modeLoc,
                                          fmt::format("'{}' is a grammar; only field stages take a mode", entry.name));
            else if (rejectClause(context, entry, "is a grammar"))
                stages.push_back({Stage::Kind::Grammar, grammar->second, FieldMode::Set, entry.loc, std::nullopt});
        } else if (field != fieldIndex.end()) {
            const size_t index = field->second;
            if (!entry.mode) {
                context.diagnostics.error("E0009", entry.loc,
                                          fmt::format("field stage '{}' needs a mode: 'set {}', 'union {}', "
                                                      "'subtract {}', 'intersect {}' or 'paint {} material NAME'",
                                                      entry.name, entry.name, entry.name, entry.name, entry.name,
                                                      entry.name));
            } else if (std::optional<FieldMode> mode = parseMode(context, entry)) {
                bool ok = true;
                std::optional<uint8_t> fieldMaterial = index < fieldMaterials.size() ? fieldMaterials[index] : std::nullopt;
                std::optional<uint8_t> material = stageMaterial(context, entry, fieldMaterial, ok);
                if (ok && *mode == FieldMode::Paint && !entry.clause) {
                    context.diagnostics.error("E0009", entry.loc,
                                              fmt::format("'paint {0}' only writes materials, so it needs a "
                                                          "material clause: 'paint {0} material NAME;'",
                                                          entry.name));
                    ok = false;
                }
                if (ok) {
                    Stage stage{Stage::Kind::Field, uint32_t(index), *mode, entry.loc, material};
                    stages.push_back(stage);
                }
            }
        } else if (auto speleothem = std::find(speleothemNames.begin(), speleothemNames.end(), entry.name);
                   speleothem != speleothemNames.end()) {
            const size_t index = size_t(speleothem - speleothemNames.begin());
            bool ok = true;
            std::optional<uint8_t> declared = index < speleothemMaterials.size() ? speleothemMaterials[index] : std::nullopt;
            std::optional<uint8_t> material = stageMaterial(context, entry, declared, ok);
            if (entry.mode)
                context.diagnostics.error("E0010", entry.modeLoc,
                                          fmt::format("'{}' is a speleothem stage; it grows into the grid as it is "
                                                      "and takes no mode: write '{};'",
                                                      entry.name, entry.name));
            else if (ok)
                stages.push_back({Stage::Kind::Speleothems, uint32_t(index), FieldMode::Set, entry.loc, material});
        } else if (auto curves = std::find(context.curvesNames.begin(), context.curvesNames.end(), entry.name);
                   curves != context.curvesNames.end()) {
            checkCurvesEntry(context, entry, uint32_t(curves - context.curvesNames.begin()), stages);
        } else if (std::find(lsystemNames.begin(), lsystemNames.end(), entry.name) != lsystemNames.end()) {
            context.diagnostics.error("E0013", entry.loc,
                                      fmt::format("'{}' is an lsystem; carving it takes a feature: 'feature NAME = "
                                                  "lsystem_cave {{ lsystem = {}; }}', then 'subtract NAME;' here",
                                                  entry.name, entry.name));
        } else {
            context.diagnostics.error("E0002", entry.loc,
                                      fmt::format("unknown grammar or field '{}' in the pipeline{}", entry.name,
                                                  errorsStillShown(context.diagnostics)
                                                      ? didYouMean(entry.name, known)
                                                      : std::string()));
        }
    }
    return stages;
}

} // namespace voxc::check
