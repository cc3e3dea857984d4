// Generated code is compared with reviewed files in tests/golden/codegen/<program>/:
// ir.txt (the IR after all passes) and one <kernel>.comp per kernel.
// scripts/update-codegen-goldens.sh rewrites them (VOXC_UPDATE_GOLDENS=1).
#include "SamplePrograms.h"
#include "voxc/stages/Pipeline.h"

#ifdef VOXC_HAVE_CHECK
#include "voxc/check/Check.h"
#endif

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <set>
#include <sstream>

namespace voxc::codegen {
namespace golden_test {

namespace fs = std::filesystem;

bool updating() {
    const char* v = std::getenv("VOXC_UPDATE_GOLDENS");
    return v && std::string(v) == "1";
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void expectGolden(const fs::path& path, const std::string& actual) {
    if (updating()) {
        fs::create_directories(path.parent_path());
        std::ofstream(path, std::ios::binary) << actual;
        return;
    }
    ASSERT_TRUE(fs::exists(path)) << path << " is missing; run scripts/update-codegen-goldens.sh";
    EXPECT_EQ(readFile(path), actual) << "generated code differs from " << path
                                      << "; review the change and run scripts/update-codegen-goldens.sh";
}

void expectProgramGoldens(const Program& program, const std::string& goldenName) {
    std::string irText;
    CompileOptions options;
    options.afterPass = [&](std::string_view, const ir::IrModule& m) { irText = ir::printIr(m); };
    const KernelPackage package = compileProgram(program, options);
    const fs::path dir = fs::path(VOXC_GOLDEN_DIR) / goldenName;
    expectGolden(dir / "ir.txt", irText);
    std::set<std::string> expectedFiles{"ir.txt"};
    for (const Kernel& kernel : package.kernels) {
        expectGolden(dir / (kernel.name + ".comp"), kernel.glsl);
        expectedFiles.insert(kernel.name + ".comp");
    }
    // No stale goldens for kernels that no longer exist.
    if (updating() || !fs::exists(dir)) return;
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_TRUE(expectedFiles.contains(entry.path().filename().string())) << "stale golden " << entry.path();
}

TEST(codegen_Golden, SampleProgram) { expectProgramGoldens(test::sampleProgram(), "sample"); }

TEST(codegen_Golden, MaterialProgram) { expectProgramGoldens(test::materialProgram(), "materials"); }

#ifdef VOXC_HAVE_CHECK
TEST(codegen_Golden, OverhangExample) {
    const std::string path = std::string(VOXC_EXAMPLES_DIR) + "/overhang.vox";
    if (!fs::exists(path)) GTEST_SKIP() << path << " does not exist yet";
    CheckResult checked = checkFile(path);
    ASSERT_TRUE(checked.program) << checked.rendered();
    checked.program->sourcePath = "examples/overhang.vox"; // the golden must not depend on the checkout's path
    expectProgramGoldens(*checked.program, "overhang");
}

TEST(codegen_Golden, FieldsExample) {
    const std::string path = std::string(VOXC_EXAMPLES_DIR) + "/fields.vox";
    CheckResult checked = checkFile(path);
    ASSERT_TRUE(checked.program) << checked.rendered();
    checked.program->sourcePath = "examples/fields.vox";
    expectProgramGoldens(*checked.program, "fields");
}
#endif

} // namespace golden_test
} // namespace voxc::codegen
