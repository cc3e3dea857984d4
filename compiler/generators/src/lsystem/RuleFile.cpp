#include "voxc/generators/lsystem/RuleFile.h"

#include <charconv>
#include <cmath>
#include <fmt/format.h>

namespace voxc::lsystem {

namespace {

constexpr std::string_view kDefaultRules =
    "# voxc reconstruction of the lost Appendix VIII (Mark & Berechet 2014). Format: Symbol;SubstituteString;Type;Weight\n"
    "I;FFFFZ;tunnel;1\n"
    "I;RFFFFZ;tunnel;1\n"
    "I;LFFFFZ;tunnel;1\n"
    "C;FLFLFZ;tunnel;1\n"
    "C;FRFRFZ;tunnel;1\n"
    "C;FLFRFRFLFZ;tunnel;1\n"
    "H;FUFFDFZ;tunnel;1\n"
    "H;FUUFFDDFZ;tunnel;1\n"
    "T;FUFFD[LFLFZ][RFRFZ];tunnel;1\n"
    "T;FUUFDD[LFLFZ][RFRFZ];tunnel;1\n"
    "Q;BF[RFF][LFF][RRFF][LLFF]FFSZ;room;1\n"
    "Q;[BLLFRRFFRRFFRRFFRRF]BFFSZ;room;1\n"
    "Z;I[I][I];none;1\n";

// A field of a record: its trimmed text and the 1-based column where that text starts.
struct RecordField {
    std::string_view text;
    uint32_t column;
};

bool isBlank(char c) { return c == ' ' || c == '\t'; }

RecordField trimmed(std::string_view text, uint32_t column) {
    while (!text.empty() && isBlank(text.front())) text.remove_prefix(1), ++column;
    while (!text.empty() && isBlank(text.back())) text.remove_suffix(1);
    return {text, column};
}

SourceLoc at(uint32_t line, uint32_t column, size_t length = 1) {
    return {line, column, uint32_t(std::max<size_t>(length, 1))};
}

} // namespace

std::string_view defaultRuleFileText() { return kDefaultRules; }

std::optional<RuleSet> parseRuleFile(const SourceFile& source, Diagnostics& diagnostics, const Limits& limits) {
    bool failed = false; // not errorCount(): Diagnostics stops counting after its cap
    auto fail = [&](std::string_view code, SourceLoc loc, std::string message) {
        diagnostics.error(code, loc, std::move(message));
        failed = true;
    };
    RuleSet rules;
    for (uint32_t line = 1; line <= source.lineCount(); ++line) {
        std::string_view text = source.line(line);
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        const RecordField whole = trimmed(text, 1);
        if (whole.text.empty() || whole.text.front() == '#') continue;

        std::vector<RecordField> fields;
        size_t begin = 0;
        for (size_t i = 0; i <= text.size(); ++i)
            if (i == text.size() || text[i] == ';') {
                fields.push_back(trimmed(text.substr(begin, i - begin), uint32_t(begin + 1)));
                begin = i + 1;
            }
        if (fields.size() != 4) {
            fail("E0001", at(line, whole.column, whole.text.size()),
                              fmt::format("expected 4 fields 'Symbol;SubstituteString;Type;Weight', found {}", fields.size()));
            continue;
        }
        const RecordField& symbol = fields[0];
        const RecordField& substitute = fields[1];
        const RecordField& type = fields[2];
        const RecordField& weight = fields[3];
        bool ok = true;
        if (symbol.text.size() != 1) {
            fail("E0001", at(line, symbol.column, symbol.text.size()),
                              symbol.text.empty() ? "the Symbol field is empty" : "the Symbol field must be one character");
            ok = false;
        } else if (symbol.text[0] != 'Z' && isThesisSymbol(symbol.text[0])) {
            fail("E0003", at(line, symbol.column),
                              fmt::format("'{}' is a turtle symbol and cannot name a macro", symbol.text[0]));
            ok = false;
        }
        if (substitute.text.empty()) {
            fail("E0009", at(line, substitute.column), "the SubstituteString field is empty");
            ok = false;
        }
        const std::optional<SymbolType> parsedType = parseSymbolType(type.text);
        if (!parsedType) {
            fail("E0002", at(line, type.column, type.text.size()),
                              fmt::format("unknown type '{}' (expected none, tunnel or room)", type.text));
            ok = false;
        }
        double value = 0;
        const char* end = weight.text.data() + weight.text.size();
        const auto [stop, status] = std::from_chars(weight.text.data(), end, value);
        if (weight.text.empty() || stop != end || status == std::errc::invalid_argument) {
            fail("E0010", at(line, weight.column, weight.text.size()),
                              fmt::format("the weight '{}' is not a number", weight.text));
            ok = false;
        } else if (status == std::errc::result_out_of_range || !std::isfinite(value)) {
            fail("E0007", at(line, weight.column, weight.text.size()),
                              fmt::format("the weight '{}' is not a finite number", weight.text));
            ok = false;
        }
        if (!ok) continue;
        auto& alternatives = (symbol.text[0] == 'Z' ? rules.productions : rules.macros)[symbol.text[0]];
        if (alternatives.size() == limits.maxAlternatives) {
            fail("E0012", at(line, symbol.column),
                              fmt::format("more than {} alternatives for '{}' (Limits::maxAlternatives)",
                                          limits.maxAlternatives, symbol.text[0]));
            continue;
        }
        alternatives.push_back({std::string(substitute.text), *parsedType, value,
                                at(line, substitute.column, substitute.text.size())});
    }

    // Symbols are checked once every macro of the file is known.
    Definition alphabet;
    alphabet.macros = rules.macros;
    for (const auto* table : {&rules.productions, &rules.macros})
        for (const auto& [symbol, alternatives] : *table)
            for (const Alternative& a : alternatives) {
                const StringRole role = table == &rules.productions ? StringRole::Production : StringRole::Substitute;
                if (auto problem = checkString(alphabet, a.text, role))
                    fail(problem->code, at(a.loc.line, a.loc.column + uint32_t(problem->offset)),
                                      problem->message);
            }
    if (failed) return std::nullopt;
    return rules;
}

} // namespace voxc::lsystem
