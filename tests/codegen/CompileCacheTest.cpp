// The SPIR-V cache: a second compile of the same kernel is read back, equal to the first; an entry
// that fails its check is compiled again and rewritten; a cache that cannot be written costs
// only speed.
#include "voxc/codegen/CompileCache.h"
#include "voxc/codegen/Spirv.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

namespace voxc::codegen {
namespace compile_cache_test {

namespace fs = std::filesystem;

const std::string kKernel = R"(#version 450
layout(local_size_x = 1) in;
layout(std430, set = 0, binding = 0) buffer Data { float values[]; };
void main() { values[gl_GlobalInvocationID.x] *= 2.0; }
)";

class CompileCache : public ::testing::Test {
protected:
    void SetUp() override {
        directory = fs::temp_directory_path() / ("voxc-cache-test-" + std::to_string(::getpid()));
        fs::remove_all(directory);
        setCompileCacheDirectory(directory);
    }
    void TearDown() override {
        setCompileCacheDirectory(std::nullopt);
        fs::remove_all(directory);
    }
    std::vector<fs::path> entries() const {
        std::vector<fs::path> out;
        if (fs::exists(directory / "spirv"))
            for (const auto& entry : fs::directory_iterator(directory / "spirv")) out.push_back(entry.path());
        return out;
    }
    fs::path directory;
};

TEST_F(CompileCache, SecondCompileIsReadBack) {
    const CompileCacheCounts before = compileCacheCounts();
    const std::vector<uint32_t> first = compileComputeShader("double", kKernel);
    const std::vector<uint32_t> second = compileComputeShader("double", kKernel);
    const CompileCacheCounts after = compileCacheCounts();
    EXPECT_EQ(first, second);
    EXPECT_EQ(after.compiled - before.compiled, 1u);
    EXPECT_EQ(after.hits - before.hits, 1u);
    EXPECT_EQ(entries().size(), 1u);
    // Another source (or another kernel name) is another entry.
    compileComputeShader("double", kKernel + "\n");
    compileComputeShader("twice", kKernel);
    EXPECT_EQ(entries().size(), 3u);
}

TEST_F(CompileCache, DamagedEntriesAreCompiledAgain) {
    const std::vector<uint32_t> reference = compileComputeShader("double", kKernel);
    ASSERT_EQ(entries().size(), 1u);
    const fs::path entry = entries()[0];
    const auto damage = [&](const std::function<void(std::string&)>& edit) {
        std::ifstream in(entry, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        in.close();
        edit(bytes);
        std::ofstream(entry, std::ios::binary | std::ios::trunc) << bytes;
    };
    const std::function<void(std::string&)> edits[] = {
        [](std::string& b) { b[b.size() - 3] ^= 0x40; },    // a flipped bit in the SPIR-V
        [](std::string& b) { b.resize(b.size() - 2); },       // truncated
        [](std::string& b) { b = "not an entry"; },           // foreign contents
        [](std::string& b) { b.clear(); },                    // empty
    };
    for (const auto& edit : edits) {
        damage(edit);
        const CompileCacheCounts before = compileCacheCounts();
        EXPECT_EQ(compileComputeShader("double", kKernel), reference);
        const CompileCacheCounts after = compileCacheCounts();
        EXPECT_EQ(after.corrupted - before.corrupted, 1u);
        EXPECT_EQ(after.hits - before.hits, 0u);
        // Rewritten whole: the next compile reads it back.
        EXPECT_EQ(compileComputeShader("double", kKernel), reference);
        EXPECT_EQ(compileCacheCounts().hits - after.hits, 1u);
    }
}

TEST_F(CompileCache, UnwritableCacheOnlyCostsSpeed) {
    fs::create_directories(directory);
    std::ofstream(directory / "spirv") << "a file where the cache's directory should be";
    const CompileCacheCounts before = compileCacheCounts();
    EXPECT_FALSE(compileComputeShader("double", kKernel).empty());
    EXPECT_FALSE(compileComputeShader("double", kKernel).empty());
    EXPECT_EQ(compileCacheCounts().compiled - before.compiled, 2u);
}

TEST_F(CompileCache, OffByDefault) {
    setCompileCacheDirectory(std::nullopt);
    compileComputeShader("double", kKernel);
    EXPECT_FALSE(fs::exists(directory));
}

// libvoxc's per-program memo: with the cache directory off, a kernel compiled inside a scope of
// the memo is not compiled again inside a later one; outside, or with other GLSL, it is.
TEST(SpirvMemoScopes, CompileAKernelOncePerMemo) {
    setCompileCacheDirectory(std::nullopt);
    SpirvMemo memo;
    const CompileCacheCounts before = compileCacheCounts();
    std::vector<uint32_t> first;
    {
        const SpirvMemoScope scope(memo);
        first = compileComputeShader("double", kKernel);
    }
    {
        const SpirvMemoScope scope(memo);
        EXPECT_EQ(compileComputeShader("double", kKernel), first);
        // Other GLSL is compiled (to the same SPIR-V: only a comment differs).
        EXPECT_EQ(compileComputeShader("double", kKernel + "// another comment\n"), first);
    }
    const CompileCacheCounts inScopes = compileCacheCounts();
    EXPECT_EQ(inScopes.compiled - before.compiled, 2u);
    EXPECT_EQ(inScopes.remembered - before.remembered, 1u);
    ASSERT_NE(memo.find("double", kKernel), nullptr);
    EXPECT_EQ(memo.find("triple", kKernel), nullptr);

    EXPECT_EQ(compileComputeShader("double", kKernel), first);
    EXPECT_EQ(compileCacheCounts().compiled - inScopes.compiled, 1u) << "no memo outside its scopes";
}

} // namespace compile_cache_test
} // namespace voxc::codegen
