// Runs the checker over every case in tests/diagnostics/cases and compares the rendered
// diagnostics with the case's .expected file. With VOXC_UPDATE_GOLDENS=1 in the environment
// it rewrites the .expected files instead (scripts/update-diagnostic-goldens.sh). A case with a
// NAME.json.expected file is also compared in JSON, as `--diagnostics-format json` prints it (the
// update rewrites those that exist; `touch` one to start it). A case with a
// NAME.region file ("MINX,MINY,MINZ:MAXX,MAXY,MAXZ") is checked for a run of that region.
#include "voxc/check/Check.h"
#include "voxc/core/AtomicWrite.h"
#include "voxc/syntax/DiagnosticJson.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace {

namespace fs = std::filesystem;

const fs::path kCasesDir = VOXC_DIAGNOSTIC_CASES_DIR;

// Case names: stems of NAME.vox and of NAME.expected (a case with no .vox tests a missing file).
std::vector<std::string> caseNames() {
    std::set<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(kCasesDir)) {
        const fs::path& path = entry.path();
        const std::string file = path.filename().string();
        if (file.ends_with(".json.expected")) continue; // the JSON form of a case
        if (path.extension() == ".vox" || path.extension() == ".expected") names.insert(path.stem().string());
    }
    return {names.begin(), names.end()};
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

bool updating() {
    const char* flag = std::getenv("VOXC_UPDATE_GOLDENS");
    return flag != nullptr && std::string(flag) == "1";
}

class diagnostics_golden : public testing::TestWithParam<std::string> {};

TEST_P(diagnostics_golden, MatchesExpected) {
    // Checked by relative path so the rendered output does not depend on the checkout's location.
    fs::current_path(kCasesDir);
    const std::string name = GetParam();
    voxc::CheckOptions options;
    if (fs::exists(name + ".region")) {
        glm::ivec3 lo, hi;
        const std::string region = readFile(name + ".region");
        ASSERT_EQ(std::sscanf(region.c_str(), "%d,%d,%d:%d,%d,%d", &lo.x, &lo.y, &lo.z, &hi.x, &hi.y, &hi.z), 6);
        options.region = std::pair(lo, hi);
    }
    const voxc::CheckResult result = voxc::checkFile(name + ".vox", options);
    const std::string rendered = result.rendered();
    std::string json;
    for (const voxc::Diagnostic& diagnostic : result.diagnostics) json += voxc::renderJson(diagnostic, result.source) + "\n";
    const fs::path expectedPath = kCasesDir / (name + ".expected");
    const fs::path jsonPath = kCasesDir / (name + ".json.expected");
    if (updating()) {
        voxc::writeFileAtomically(expectedPath.string(), rendered);
        if (fs::exists(jsonPath)) voxc::writeFileAtomically(jsonPath.string(), json);
        GTEST_SKIP() << "updated " << expectedPath;
    }
    if (fs::exists(jsonPath)) EXPECT_EQ(json, readFile(jsonPath));
    ASSERT_TRUE(fs::exists(expectedPath)) << "no golden file; run scripts/update-diagnostic-goldens.sh";
    EXPECT_FALSE(rendered.empty()) << "every golden case should produce at least one diagnostic";
    EXPECT_EQ(rendered, readFile(expectedPath));
}

INSTANTIATE_TEST_SUITE_P(cases, diagnostics_golden, testing::ValuesIn(caseNames()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

} // namespace
