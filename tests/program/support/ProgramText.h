#pragma once
// Builds checked Programs for tests from compact strings, so a test reads like a rule file:
//   makeRule("grow", {"PRES, ABS"}, {"NOP, SET 1"})
// Rows are in printed layout (first row = top = highest y, columns along +x); a row "---"
// starts the next z layer (lowest z first). A cell joins predicates with '&'.
// The checker is bypassed, so malformed text throws std::invalid_argument.
#include "voxc/grid/Grid.h"
#include "voxc/program/Program.h"

#include <string>
#include <string_view>
#include <vector>

namespace voxc::test {

SymbolCell parseSymbolCell(std::string_view text);       // "GEQ 0.5 & LT 1.0", "IGN", "GEQ 0.5 & MAT 2"
TransformCell parseTransformCell(std::string_view text); // "ADD -0.2", "NOP", "SET 1 & MAT 2", "MAT 2"

Rule makeRule(std::string name, const std::vector<std::string>& symbolRows,
              const std::vector<std::string>& transformRows);
// Sets weight/probability together with their fixed-point units, as the checker does.
void setWeight(Rule& rule, float weight);
void setProbability(Rule& rule, float probability);

// A grammar over the whole world (bounds = [0, worldSize)), stride 1, one iteration.
Grammar makeGrammar(std::string name, glm::ivec3 worldSize, std::vector<Rule> rules);

// A program with no start shapes whose pipeline is Start then every grammar in order.
Program makeProgram(glm::ivec3 worldSize, std::vector<Grammar> grammars, uint32_t seed = 0);

// A grid from printed rows of numbers ("0.0 0.0 0.5"), same layout rules as rules.
DenseGrid gridFromRows(const std::vector<std::string>& rows);
// The grid printed back as rows of shortest round-trip floats, same layout.
std::vector<std::string> gridRows(const DenseGrid& grid);

} // namespace voxc::test
