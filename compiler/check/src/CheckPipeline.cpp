// `pipeline { start; caves; overhang; }`
#include "Sections.h"
#include "Suggest.h"
#include "Values.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::check {

std::vector<Stage> checkPipeline(Context& context, const ast::Block& block,
                                 const std::vector<std::string>& grammarNames) {
    const std::string where = "'pipeline' block";
    checkLabel(context, block, false);
    rejectUnexpectedMembers(context, block, where, {.names = true});
    for (const ast::Assignment& a : block.assignments)
        context.diagnostics.error("E0008", a.loc,
                                  fmt::format("unexpected key '{}' in {}; it lists stages as 'start; NAME;'", a.key,
                                              where));
    if (block.names.empty() || block.names.front().name != "start")
        context.diagnostics.error("E0009", block.loc, "the pipeline must begin with 'start'");

    std::vector<std::string_view> known{"start"};
    for (const std::string& name : grammarNames) known.push_back(name);
    std::vector<Stage> stages;
    for (size_t i = 0; i < block.names.size(); ++i) {
        const ast::NameStatement& entry = block.names[i];
        if (entry.name == "start") {
            if (i != 0)
                context.diagnostics.error("E0007", entry.loc, "'start' can only be the first stage of the pipeline");
            continue;
        }
        auto found = std::find(grammarNames.begin(), grammarNames.end(), entry.name);
        if (found == grammarNames.end()) {
            context.diagnostics.error("E0002", entry.loc,
                                      fmt::format("unknown grammar '{}' in the pipeline{}", entry.name,
                                                  didYouMean(entry.name, known)));
            continue;
        }
        stages.push_back({Stage::Kind::Grammar, uint32_t(found - grammarNames.begin())});
    }
    return stages;
}

} // namespace voxc::check
