#include "Cases.h"

#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"

#include <fmt/format.h>

namespace voxc::bench {

const std::vector<Case>& grammarCases() {
    static const std::vector<Case> cases = {
        {"overhang", "examples/overhang.vox"},
        {"cave", "examples/cave_grammar.vox"},
    };
    return cases;
}

const std::vector<Case>& featureCases() {
    static const std::vector<Case> cases = {
        {"feature_arch", "examples/arch.vox"},
        {"feature_cave", "examples/cave.vox"},
        {"feature_overhang", "examples/cliff.vox"},
    };
    return cases;
}

const std::vector<Case>& symmetryCases() {
    static const std::vector<Case> cases = {
        {"symmetry_square", "bench/grammars/ledge_square.vox"},
        {"symmetry_expanded", "bench/grammars/ledge_expanded.vox"},
    };
    return cases;
}

const std::vector<Case>& stampCases() {
    static const std::vector<Case> cases = {
        {"arches_between_cliffs", "examples/arches_between_cliffs.vox"},
        {"sea_caves", "examples/sea_caves.vox"},
    };
    return cases;
}

namespace {

Program loadResized(const Case& benchCase, int n) {
    const std::string path = fmt::format("{}/{}", VOXC_SOURCE_DIR, benchCase.example);
    CheckResult result = checkFile(path);
    if (result.hasErrors() || !result.program) throw UserError(fmt::format("{} does not check", path));
    Program program = std::move(*result.program);
    program.world.size = glm::ivec3(n);
    return program;
}

} // namespace

Program loadExampleProgram(const std::string& example) {
    const std::string path = fmt::format("{}/{}", VOXC_SOURCE_DIR, example);
    CheckResult result = checkFile(path);
    if (result.hasErrors() || !result.program) throw UserError(fmt::format("{} does not check", path));
    return std::move(*result.program);
}

Program loadFeatureProgram(const Case& benchCase, int n) { return loadResized(benchCase, n); }

Program loadCaseProgram(const Case& benchCase, int n) {
    Program program = loadResized(benchCase, n);
    program.world.origin = glm::ivec3(0);
    for (Grammar& grammar : program.grammars) {
        grammar.boundsMin = glm::ivec3(0);
        grammar.boundsMax = glm::ivec3(n);
        grammar.stride = glm::ivec3(1);
        grammar.iterations = 1;
    }
    return program;
}

} // namespace voxc::bench
