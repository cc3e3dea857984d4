// `pipeline { start; caves; subtract tunnel; overhang; }`
#include "Sections.h"
#include "Suggest.h"
#include "Values.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::check {

namespace {

constexpr std::string_view kModeNames[] = {"set", "union", "subtract", "intersect"};
constexpr FieldMode kModes[] = {FieldMode::Set, FieldMode::Union, FieldMode::Subtract, FieldMode::Intersect};

std::optional<FieldMode> parseMode(Context& context, const ast::NameStatement& entry) {
    for (size_t i = 0; i < std::size(kModeNames); ++i)
        if (*entry.mode == kModeNames[i]) return kModes[i];
    context.diagnostics.error("E0011", entry.modeLoc,
                              fmt::format("unknown field mode '{}'{}", *entry.mode,
                                          suggestOrList(*entry.mode, kModeNames)));
    return std::nullopt;
}

} // namespace

std::vector<Stage> checkPipeline(Context& context, const ast::Block& block,
                                 const std::vector<std::string>& grammarNames,
                                 const std::vector<std::string>& fieldNames) {
    const std::string where = "'pipeline' block";
    checkLabel(context, block, false);
    rejectUnexpectedMembers(context, block, where, {.names = true});
    for (const ast::Assignment& a : block.assignments)
        context.diagnostics.error("E0008", a.loc,
                                  fmt::format("unexpected key '{}' in {}; it lists stages as 'start; NAME;'", a.key,
                                              where));
    if (block.names.empty() || block.names.front().name != "start" || block.names.front().mode)
        context.diagnostics.error("E0009", block.loc, "the pipeline must begin with 'start'");

    std::vector<std::string_view> known{"start"};
    for (const std::string& name : grammarNames) known.push_back(name);
    for (const std::string& name : fieldNames) known.push_back(name);
    std::vector<Stage> stages;
    for (size_t i = 0; i < block.names.size(); ++i) {
        const ast::NameStatement& entry = block.names[i];
        if (entry.name == "start") {
            if (i != 0 || entry.mode)
                context.diagnostics.error("E0007", entry.loc, "'start' can only be the first stage of the pipeline");
            continue;
        }
        auto grammar = std::find(grammarNames.begin(), grammarNames.end(), entry.name);
        auto field = std::find(fieldNames.begin(), fieldNames.end(), entry.name);
        if (grammar != grammarNames.end()) {
            if (entry.mode)
                context.diagnostics.error("E0010", entry.modeLoc,
                                          fmt::format("'{}' is a grammar; only field stages take a mode", entry.name));
            else
                stages.push_back({Stage::Kind::Grammar, uint32_t(grammar - grammarNames.begin()), FieldMode::Set, entry.loc});
        } else if (field != fieldNames.end()) {
            if (!entry.mode) {
                context.diagnostics.error("E0009", entry.loc,
                                          fmt::format("field stage '{}' needs a mode: 'set {}', 'union {}', "
                                                      "'subtract {}' or 'intersect {}'",
                                                      entry.name, entry.name, entry.name, entry.name, entry.name));
            } else if (std::optional<FieldMode> mode = parseMode(context, entry)) {
                Stage stage{Stage::Kind::Field, uint32_t(field - fieldNames.begin()), *mode, entry.loc};
                stages.push_back(stage);
            }
        } else {
            context.diagnostics.error("E0002", entry.loc,
                                      fmt::format("unknown grammar or field '{}' in the pipeline{}", entry.name,
                                                  didYouMean(entry.name, known)));
        }
    }
    return stages;
}

} // namespace voxc::check
