#pragma once
#include "voxc/check/Check.h"

#include <string>
#include <vector>

namespace voxc::test {

inline CheckResult check(const std::string& text) { return checkSource(SourceFile("test.vox", text)); }

// The codes of every diagnostic, in report order.
inline std::vector<std::string> codes(const CheckResult& result) {
    std::vector<std::string> out;
    for (const Diagnostic& d : result.diagnostics) out.push_back(d.code);
    return out;
}

// A valid file with one [I, J, K] rule whose symbol and transform bodies are given.
inline std::string oneRule(const std::string& size, const std::string& symbol, const std::string& transform,
                           const std::string& ruleExtras = "", const std::string& grammarExtras = "") {
    return "world { size = [16, 16, 16]; }\n"
           "grammar g {\n" +
           grammarExtras +
           "\n  rule r {\n    size = " + size + ";\n" + ruleExtras + "\n    symbol { " + symbol +
           " }\n    transform { " + transform + " }\n  }\n}\n";
}

// Drops the first line (the world block) of a oneRule text.
inline std::string withoutWorld(const std::string& text) { return text.substr(text.find('\n') + 1); }

} // namespace voxc::test
