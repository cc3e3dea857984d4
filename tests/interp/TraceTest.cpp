// Trace events, their filter and text form, and the firing counts.
#include "ProgramText.h"
#include "voxc/core/Errors.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"

#include <gtest/gtest.h>

namespace voxc {
namespace trace_test {

using test::makeGrammar;
using test::makeProgram;
using test::makeRule;

// Two sweeps: a 2x2 rule that fires everywhere (phases 0..3 on a 3x3 grid, x fastest), then a
// 1x1 rule that fires only where the 2x2 rule left exactly 1 (the corners).
Program tinyProgram() {
    Grammar g = makeGrammar("tiny", {3, 3, 1},
                            {makeRule("dot", {"EQ 1"}, {"SET 5"}),
                             makeRule("block", {"IGN, IGN", "IGN, IGN"}, {"ADD 1, ADD 1", "ADD 1, ADD 1"})});
    g.iterations = 2;
    return makeProgram({3, 3, 1}, {g});
}

// A filter on a rule name, a grammar name or both (the other fields unset).
TraceFilter namesFilter(std::optional<std::string> rule, std::optional<std::string> grammar = std::nullopt) {
    TraceFilter filter;
    filter.rule = std::move(rule);
    filter.grammar = std::move(grammar);
    return filter;
}

std::vector<std::string> traceOf(const Program& program, const TraceFilter& filter = {}) {
    std::vector<std::string> lines;
    InterpOptions options;
    options.onFire = [&](const TraceEvent& e) {
        if (traceFilterAccepts(program, filter, e)) lines.push_back(formatTraceEvent(program, e));
    };
    interpret(program, options);
    return lines;
}

TEST(interp_Trace, EventsOfATinyGrammar) {
    // Iteration 0: block adds 1 per covering window: corners 1, edges 2, centre 4; dot then fires
    // at the four corners. Iteration 1: block again (corners become 6), dot finds no 1.
    const std::vector<std::string> expected = {
        "iter 0 sweep 0 phase 0 anchor (0,0,0) grammar tiny rule block",
        "iter 0 sweep 0 phase 1 anchor (1,0,0) grammar tiny rule block",
        "iter 0 sweep 0 phase 2 anchor (0,1,0) grammar tiny rule block",
        "iter 0 sweep 0 phase 3 anchor (1,1,0) grammar tiny rule block",
        "iter 0 sweep 1 phase 0 anchor (0,0,0) grammar tiny rule dot",
        "iter 0 sweep 1 phase 0 anchor (2,0,0) grammar tiny rule dot",
        "iter 0 sweep 1 phase 0 anchor (0,2,0) grammar tiny rule dot",
        "iter 0 sweep 1 phase 0 anchor (2,2,0) grammar tiny rule dot",
        "iter 1 sweep 0 phase 0 anchor (0,0,0) grammar tiny rule block",
        "iter 1 sweep 0 phase 1 anchor (1,0,0) grammar tiny rule block",
        "iter 1 sweep 0 phase 2 anchor (0,1,0) grammar tiny rule block",
        "iter 1 sweep 0 phase 3 anchor (1,1,0) grammar tiny rule block",
    };
    EXPECT_EQ(traceOf(tinyProgram()), expected);
    EXPECT_EQ(test::gridRows(interpret(tinyProgram())), (std::vector<std::string>{"6 4 6", "4 8 4", "6 4 6"}));
}

TEST(interp_Trace, EventFields) {
    std::vector<TraceEvent> events;
    InterpOptions options;
    options.onFire = [&](const TraceEvent& e) { events.push_back(e); };
    interpret(tinyProgram(), options);
    ASSERT_EQ(events.size(), 12u);
    const TraceEvent& e = events[7];
    EXPECT_EQ(e.grammar, 0u);
    EXPECT_EQ(e.iteration, 0u);
    EXPECT_EQ(e.sweep, 1u);
    EXPECT_EQ(e.phase, 0u);
    EXPECT_EQ(e.anchor, glm::ivec3(2, 2, 0));
    EXPECT_EQ(e.rule, 0u); // "dot" is declared first
}

TEST(interp_Trace, FilterByRuleAndIteration) {
    TraceFilter byRule;
    byRule.rule = "dot";
    EXPECT_EQ(traceOf(tinyProgram(), byRule).size(), 4u);
    TraceFilter byIteration;
    byIteration.iteration = 1;
    EXPECT_EQ(traceOf(tinyProgram(), byIteration),
              (std::vector<std::string>{"iter 1 sweep 0 phase 0 anchor (0,0,0) grammar tiny rule block",
                                        "iter 1 sweep 0 phase 1 anchor (1,0,0) grammar tiny rule block",
                                        "iter 1 sweep 0 phase 2 anchor (0,1,0) grammar tiny rule block",
                                        "iter 1 sweep 0 phase 3 anchor (1,1,0) grammar tiny rule block"}));
    TraceFilter both = byRule;
    both.iteration = 1;
    EXPECT_TRUE(traceOf(tinyProgram(), both).empty());
}

TEST(interp_Trace, FilterByGrammarAndAnchorBox) {
    TraceFilter byGrammar;
    byGrammar.grammar = "other";
    EXPECT_TRUE(traceOf(tinyProgram(), byGrammar).empty());
    byGrammar.grammar = "tiny";
    EXPECT_EQ(traceOf(tinyProgram(), byGrammar).size(), 12u);
    TraceFilter box;
    box.anchors = TraceFilter::AnchorBox{{1, 0, 0}, {3, 1, 1}}; // half-open: x 1..2, y 0
    EXPECT_EQ(traceOf(tinyProgram(), box),
              (std::vector<std::string>{"iter 0 sweep 0 phase 1 anchor (1,0,0) grammar tiny rule block",
                                        "iter 0 sweep 1 phase 0 anchor (2,0,0) grammar tiny rule dot",
                                        "iter 1 sweep 0 phase 1 anchor (1,0,0) grammar tiny rule block"}));
}

TEST(interp_Trace, FireStatsCountPerRule) {
    const Program program = tinyProgram();
    FireStats stats;
    InterpOptions options;
    options.stats = &stats;
    interpret(program, options);
    ASSERT_EQ(stats.firings.size(), 1u);
    EXPECT_EQ(stats.firings[0], (std::vector<uint64_t>{4, 8}));
    EXPECT_EQ(stats.anchors[0], 2u * (4 + 9)); // per iteration: 4 block anchors, 9 dot anchors
    EXPECT_EQ(formatFireStats(program, stats), "grammar tiny: 26 anchors tested, 12 firings\n  dot 4\n  block 8\n");
}

TEST(interp_Trace, StatsSkipGrammarsThatDidNotRun) {
    Program program = tinyProgram();
    program.grammars.push_back(program.grammars[0]);
    program.grammars[1].name = "unused";
    FireStats stats;
    InterpOptions options;
    options.stats = &stats;
    interpret(program, options);
    EXPECT_EQ(formatFireStats(program, stats), "grammar tiny: 26 anchors tested, 12 firings\n  dot 4\n  block 8\n");
}

// `symmetry` names variants WRITTEN@ELEMENT: a written name picks them all, NAME@ELEMENT one.
TEST(interp_Trace, RuleFilterCoversSymmetryVariants) {
    EXPECT_TRUE(ruleFilterMatches("chip", "chip"));
    EXPECT_TRUE(ruleFilterMatches("chip", "chip@rot90y"));
    EXPECT_TRUE(ruleFilterMatches("chip@rot90y", "chip@rot90y"));
    EXPECT_FALSE(ruleFilterMatches("chip@rot90y", "chip"));
    EXPECT_FALSE(ruleFilterMatches("chip@rot90y", "chip@rot180y"));
    EXPECT_FALSE(ruleFilterMatches("chi", "chip@rot90y"));
    EXPECT_FALSE(ruleFilterMatches("chip", "chip_edge@rot90y"));

    Program program = tinyProgram();
    program.grammars[0].rules[0].name = "dot@mirx"; // as the checker names a variant
    const std::vector<std::string> all = traceOf(program, namesFilter("dot"));
    const std::vector<std::string> variant = traceOf(program, namesFilter("dot@mirx"));
    EXPECT_EQ(all.size(), 4u);
    EXPECT_EQ(all, variant);
}

std::string filterError(const Program& program, const TraceFilter& filter) {
    try {
        checkTraceFilter(program, filter);
    } catch (const UserError& error) {
        return error.what();
    }
    return "";
}

TEST(interp_Trace, UnknownNamesInAFilterAreErrorsListingTheNames) {
    Program program = tinyProgram();
    program.grammars[0].rules.push_back(program.grammars[0].rules[0]);
    program.grammars[0].rules[0].name = "dot@rot90y";
    program.grammars[0].rules.back().name = "dot";
    EXPECT_EQ(filterError(program, namesFilter("dot")), "");
    EXPECT_EQ(filterError(program, namesFilter("dot@rot90y")), "");
    EXPECT_EQ(filterError(program, namesFilter("blokc")),
              "--trace-rule 'blokc': no rule of that name in any grammar (the rules are: dot, block); did you mean "
              "'block'?");
    EXPECT_EQ(filterError(program, namesFilter("dot@rot9y")),
              "--trace-rule 'dot@rot9y': rule 'dot' has no such variant (its variants are: dot@rot90y); did you "
              "mean 'dot@rot90y'?");
    EXPECT_EQ(filterError(program, namesFilter("block@mirx")),
              "--trace-rule 'block@mirx': rule 'block' has no such variant (it has no symmetry variants)");
    EXPECT_EQ(filterError(program, namesFilter(std::nullopt, "tniy")),
              "--trace-grammar 'tniy': no grammar of that name (the grammars are: tiny); did you mean 'tiny'?");
    EXPECT_EQ(filterError(program, namesFilter("dot", "tiny")), "");
}

} // namespace trace_test
} // namespace voxc
