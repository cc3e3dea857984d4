#include "DocTable.h"

#include "voxc/builtins/Functions.h"

#include <fmt/format.h>

namespace voxc::test {

namespace {

std::string cell(std::string_view text) {
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

} // namespace

std::string registryTable() {
    std::string table = kDocTableBegin;
    table += "| name | signature | computes (range) | tolerance | GLSL libraries |\n|---|---|---|---|---|\n";
    for (const FunctionInfo& f : functions()) {
        std::string libraries;
        for (std::string_view l : f.glslLibraries) libraries += (libraries.empty() ? "" : ", ") + std::string(l);
        table += fmt::format("| `{}` | `{}` | {} | {} | {} |\n", f.name, cell(f.signature), cell(f.doc),
                             f.tolerance == 0.0f ? std::string("0 (bit-exact)") : fmt::format("{:g}", f.tolerance),
                             libraries.empty() ? "-" : libraries);
    }
    return table + kDocTableEnd;
}

} // namespace voxc::test
