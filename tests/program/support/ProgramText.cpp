#include "ProgramText.h"

#include "voxc/builtins/Ops.h"

#include <cmath>
#include <fmt/format.h>
#include <sstream>
#include <stdexcept>

namespace voxc::test {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
    std::vector<std::string_view> parts;
    size_t start = 0;
    for (size_t i = 0; i <= s.size(); ++i) {
        if (i == s.size() || s[i] == sep) {
            parts.push_back(trim(s.substr(start, i - start)));
            start = i + 1;
        }
    }
    return parts;
}

// "OP" or "OP value" -> name and optional value text.
std::pair<std::string, std::string> splitOperator(std::string_view text) {
    text = trim(text);
    const size_t space = text.find(' ');
    if (space == std::string_view::npos) return {std::string(text), ""};
    return {std::string(text.substr(0, space)), std::string(trim(text.substr(space + 1)))};
}

float parseFloat(const std::string& text) {
    size_t used = 0;
    const float v = std::stof(text, &used);
    if (used != text.size()) throw std::invalid_argument("bad number: " + text);
    return v;
}

// Rows in printed layout -> layers of rows, with the grid extent they imply.
struct Layout {
    glm::ivec3 size{0};
    std::vector<std::vector<std::vector<std::string_view>>> layers; // [z][printed row][x]
};

Layout parseLayout(const std::vector<std::string>& rows, char sep) {
    Layout layout;
    layout.layers.emplace_back();
    for (const std::string& row : rows) {
        if (trim(row) == "---") {
            layout.layers.emplace_back();
            continue;
        }
        std::vector<std::string_view> cells;
        for (std::string_view cell : split(row, sep))
            if (!cell.empty() || sep == ',') cells.push_back(cell);
        layout.layers.back().push_back(cells);
    }
    layout.size.z = int(layout.layers.size());
    layout.size.y = int(layout.layers.front().size());
    layout.size.x = layout.size.y ? int(layout.layers.front().front().size()) : 0;
    for (const auto& layer : layout.layers) {
        if (int(layer.size()) != layout.size.y) throw std::invalid_argument("ragged layers");
        for (const auto& row : layer)
            if (int(row.size()) != layout.size.x) throw std::invalid_argument("ragged rows");
    }
    return layout;
}

// Visits every cell with its window coordinates (printed row 0 is y = J-1).
template <typename F>
void forEachCell(const Layout& layout, F&& f) {
    for (int z = 0; z < layout.size.z; ++z)
        for (int row = 0; row < layout.size.y; ++row)
            for (int x = 0; x < layout.size.x; ++x) f(glm::ivec3(x, layout.size.y - 1 - row, z), layout.layers[z][row][x]);
}

} // namespace

SymbolCell parseSymbolCell(std::string_view text) {
    SymbolCell cell;
    for (std::string_view part : split(text, '&')) {
        auto [name, value] = splitOperator(part);
        if (const auto materialOp = findMaterialOp(name)) { // "MAT 3": material ids are numbers here
            cell.materialPredicates.push_back({*materialOp, uint8_t(std::stoi(value))});
            continue;
        }
        const auto op = findSymbolOp(name);
        if (!op) throw std::invalid_argument("unknown symbol operator: " + name);
        if (*op == SymbolOp::IGN) continue; // IGN is the empty predicate list
        if (symbolOpInfo(*op).takesValue != !value.empty()) throw std::invalid_argument("arity: " + std::string(part));
        cell.predicates.push_back(Predicate{*op, value.empty() ? 0.0f : parseFloat(value)});
    }
    return cell;
}

TransformCell parseTransformCell(std::string_view text) {
    TransformCell cell;
    for (std::string_view part : split(text, '&')) {
        auto [name, value] = splitOperator(part);
        if (name == "MAT") {
            cell.material = uint8_t(std::stoi(value));
            continue;
        }
        const auto op = findTransformOp(name);
        if (!op) throw std::invalid_argument("unknown transform operator: " + name);
        if (transformOpInfo(*op).takesValue != !value.empty()) throw std::invalid_argument("arity: " + std::string(part));
        cell.op = *op;
        cell.value = value.empty() ? 0.0f : parseFloat(value);
    }
    return cell;
}

Rule makeRule(std::string name, const std::vector<std::string>& symbolRows,
              const std::vector<std::string>& transformRows) {
    const Layout symbol = parseLayout(symbolRows, ',');
    const Layout transform = parseLayout(transformRows, ',');
    if (symbol.size != transform.size) throw std::invalid_argument("symbol and transform sizes differ");
    Rule rule;
    rule.name = std::move(name);
    rule.size = symbol.size;
    const size_t cells = size_t(rule.size.x) * rule.size.y * rule.size.z;
    rule.symbol.resize(cells);
    rule.transform.resize(cells);
    forEachCell(symbol, [&](glm::ivec3 p, std::string_view text) {
        rule.symbol[size_t(cellIndex(rule.size, p.x, p.y, p.z))] = parseSymbolCell(text);
    });
    forEachCell(transform, [&](glm::ivec3 p, std::string_view text) {
        rule.transform[size_t(cellIndex(rule.size, p.x, p.y, p.z))] = parseTransformCell(text);
    });
    return rule;
}

void setWeight(Rule& rule, float weight) {
    rule.weight = weight;
    rule.weightUnits = uint32_t(std::lround(double(weight) * kWeightUnitsPerOne));
}

void setProbability(Rule& rule, float probability) {
    rule.probability = probability;
    rule.probabilityUnits = uint32_t(std::llround(double(probability) * kProbabilityOne));
}

Grammar makeGrammar(std::string name, glm::ivec3 worldSize, std::vector<Rule> rules) {
    Grammar grammar;
    grammar.name = std::move(name);
    grammar.boundsMax = worldSize;
    grammar.rules = std::move(rules);
    return grammar;
}

Program makeProgram(glm::ivec3 worldSize, std::vector<Grammar> grammars, uint32_t seed) {
    Program program;
    program.world.size = worldSize;
    program.world.seed = seed;
    program.grammars = std::move(grammars);
    program.pipeline.push_back(Stage{Stage::Kind::Start, 0});
    for (uint32_t g = 0; g < program.grammars.size(); ++g) program.pipeline.push_back(Stage{Stage::Kind::Grammar, g});
    return program;
}

DenseGrid gridFromRows(const std::vector<std::string>& rows) {
    const Layout layout = parseLayout(rows, ' ');
    DenseGrid grid(layout.size);
    forEachCell(layout, [&](glm::ivec3 p, std::string_view text) { grid.at(p) = parseFloat(std::string(text)); });
    return grid;
}

std::vector<std::string> gridRows(const DenseGrid& grid) {
    const glm::ivec3 size = grid.size();
    std::vector<std::string> rows;
    for (int z = 0; z < size.z; ++z) {
        if (z > 0) rows.push_back("---");
        for (int y = size.y - 1; y >= 0; --y) {
            std::string row;
            for (int x = 0; x < size.x; ++x) row += fmt::format("{}{}", x ? " " : "", grid.at({x, y, z}));
            rows.push_back(row);
        }
    }
    return rows;
}

} // namespace voxc::test
