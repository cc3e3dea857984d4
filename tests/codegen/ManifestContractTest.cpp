// The manifest is a contract: what it says each kernel declares is read back from the written
// .spv files with SPIRV-Tools' parser (independently of voxc's own reading) and compared.
#include "SamplePrograms.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/codegen/PackageWriter.h"
#ifdef VOXC_HAVE_CHECK
#include "voxc/check/Check.h"
#endif
#include "voxc/program/PointSet.h"
#include "voxc/program/SolveTable.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <glslang/SPIRV/spirv.hpp>
#include <spirv-tools/libspirv.h>

namespace voxc::codegen {
namespace manifest_contract_test {

namespace fs = std::filesystem;

// The interface of one module: set 0 bindings of its variables, and the member offsets of its
// push-constant block(s).
struct Interface {
    std::set<uint32_t> bindings;
    std::set<uint32_t> descriptorSets;
    std::vector<std::vector<uint32_t>> pushConstantOffsets; // one list per push-constant variable
};

// What the parser callback gathers; resolved into an Interface once the module is read.
struct Reflection {
    std::map<uint32_t, uint32_t> binding, descriptorSet;       // id -> decoration value
    std::map<uint32_t, std::map<uint32_t, uint32_t>> offsets;  // struct id -> member -> Offset
    std::map<uint32_t, uint32_t> pointee;                      // pointer type id -> pointee type id
    std::vector<std::pair<uint32_t, uint32_t>> variables;      // (variable id, pointer type id) by storage class
    std::vector<uint32_t> pushConstantTypes;                   // pointer type ids of push-constant variables
};

spv_result_t onInstruction(void* user, const spv_parsed_instruction_t* instruction) {
    Reflection& r = *static_cast<Reflection*>(user);
    const uint32_t* w = instruction->words;
    switch (spv::Op(instruction->opcode)) {
    case spv::OpDecorate:
        if (w[2] == spv::DecorationBinding) r.binding[w[1]] = w[3];
        if (w[2] == spv::DecorationDescriptorSet) r.descriptorSet[w[1]] = w[3];
        break;
    case spv::OpMemberDecorate:
        if (w[3] == spv::DecorationOffset) r.offsets[w[1]][w[2]] = w[4];
        break;
    case spv::OpTypePointer: r.pointee[w[1]] = w[3]; break;
    case spv::OpVariable:
        r.variables.push_back({w[2], w[1]});
        if (w[3] == spv::StorageClassPushConstant) r.pushConstantTypes.push_back(w[1]);
        break;
    default: break;
    }
    return SPV_SUCCESS;
}

Interface reflect(const std::string& bytes) {
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    Reflection r;
    spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_1);
    const spv_result_t result =
        spvBinaryParse(context, &r, words.data(), words.size(), nullptr, onInstruction, nullptr);
    spvContextDestroy(context);
    EXPECT_EQ(result, SPV_SUCCESS);
    Interface out;
    for (const auto& [variable, pointerType] : r.variables) {
        if (r.binding.contains(variable)) out.bindings.insert(r.binding.at(variable));
        if (r.descriptorSet.contains(variable)) out.descriptorSets.insert(r.descriptorSet.at(variable));
    }
    for (uint32_t pointerType : r.pushConstantTypes) {
        std::vector<uint32_t> offsets;
        for (const auto& [member, offset] : r.offsets[r.pointee.at(pointerType)])
            offsets.push_back(offset);
        out.pushConstantOffsets.push_back(offsets);
    }
    return out;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Writes `package` and checks every kernel's manifest entry against its reflected .spv.
// Returns the manifest for further checks.
nlohmann::json expectManifestMatchesSpirv(const KernelPackage& package, const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("voxc_manifest_contract_" + name);
    fs::remove_all(dir);
    writePackage(package, dir.string(), {name + ".vox", "text"});
    const nlohmann::json manifest = nlohmann::json::parse(readFile(dir / "manifest.json"));

    std::vector<uint32_t> pushOffsets;
    for (const auto& field : manifest["push_constants"]["fields"])
        pushOffsets.push_back(field["offset"]);
    std::set<uint32_t> declaredSomewhere;
    EXPECT_EQ(manifest["kernels"].size(), package.kernels.size());
    for (const auto& kernel : manifest["kernels"]) {
        const std::string kernelName = kernel["name"];
        const Interface reflected = reflect(readFile(dir / std::string(kernel["spv"])));
        EXPECT_EQ(kernel["bindings"].get<std::set<uint32_t>>(), reflected.bindings) << kernelName;
        EXPECT_TRUE(std::is_sorted(kernel["bindings"].begin(), kernel["bindings"].end())) << kernelName;
        EXPECT_EQ(reflected.descriptorSets, std::set<uint32_t>{0}) << kernelName;
        EXPECT_EQ(reflected.pushConstantOffsets, std::vector<std::vector<uint32_t>>{pushOffsets}) << kernelName;
        declaredSomewhere.insert(reflected.bindings.begin(), reflected.bindings.end());
    }
    // The buffers table describes exactly the bindings some kernel declares.
    std::set<uint32_t> described;
    for (const auto& buffer : manifest["buffers"])
        described.insert(uint32_t(buffer["binding"]));
    EXPECT_EQ(described, declaredSomewhere);
    fs::remove_all(dir);
    return manifest;
}

TEST(codegen_ManifestContract, SampleProgramBindingsAndPushConstantsMatchTheSpirv) {
    const nlohmann::json manifest = expectManifestMatchesSpirv(compileProgram(test::sampleProgram()), "sample");
    EXPECT_EQ(manifest["push_constants"]["size"], 7 * 16);
    for (const auto& kernel : manifest["kernels"])
        EXPECT_FALSE(kernel["bindings"].get<std::set<uint32_t>>().contains(kBindingMaterials)) << kernel["name"];
}

// Binding 8 is in the manifest of every kernel of a material-using package, as in its SPIR-V,
// and the material table names every material.
TEST(codegen_ManifestContract, MaterialProgramDeclaresTheMaterialBufferAndTable) {
    const Program program = test::materialProgram();
    const nlohmann::json manifest = expectManifestMatchesSpirv(compileProgram(program), "materials");
    for (const auto& kernel : manifest["kernels"])
        EXPECT_TRUE(kernel["bindings"].get<std::set<uint32_t>>().contains(kBindingMaterials)) << kernel["name"];
    ASSERT_EQ(manifest["materials"].size(), program.materials.size());
    for (size_t i = 0; i < program.materials.size(); ++i) {
        EXPECT_EQ(manifest["materials"][i]["id"], program.materials[i].id);
        EXPECT_EQ(manifest["materials"][i]["name"], program.materials[i].name);
        EXPECT_EQ(manifest["materials"][i]["color"][1].get<float>(), program.materials[i].color.g);
    }
}

#ifdef VOXC_HAVE_CHECK
TEST(codegen_ManifestContract, EveryExampleMatchesItsSpirv) {
    for (const auto& entry : fs::directory_iterator(VOXC_EXAMPLES_DIR)) {
        if (entry.path().extension() != ".vox") continue;
        CheckResult checked = checkFile(entry.path().string());
        ASSERT_TRUE(checked.program) << checked.rendered();
        SCOPED_TRACE(entry.path().filename().string());
        expectManifestMatchesSpirv(compileProgram(*checked.program), entry.path().stem().string());
    }
}

// A package holds the buffers the compiler fills (point sets, solve tables), so an engine needs
// nothing but the directory: every buffer a kernel declares whose words come from the compiler
// names its file, which holds exactly `count` little-endian words, the words the executor uploads.
TEST(codegen_ManifestContract, BuffersTheCompilerFillsAreFilesOfThePackage) {
    for (const char* example : {"lsystem_cave", "curves_cliff", "valley"}) {
        SCOPED_TRACE(example);
        CheckResult checked = checkFile(fmt::format("{}/{}.vox", VOXC_EXAMPLES_DIR, example));
        ASSERT_TRUE(checked.program) << checked.rendered();
        const KernelPackage package = compileProgram(*checked.program);
        const std::map<std::string, std::string> files = packageFiles(package);
        const nlohmann::json manifest = nlohmann::json::parse(files.at("manifest.json"));
        size_t withFile = 0;
        for (const auto& buffer : manifest["buffers"]) {
            const uint32_t binding = buffer["binding"];
            if (binding != kBindingPointSets && binding != kBindingSolveTables) {
                EXPECT_FALSE(buffer.contains("file")) << binding;
                continue;
            }
            ASSERT_TRUE(buffer.contains("file")) << binding;
            const std::string& bytes = files.at(buffer["file"].get<std::string>());
            const std::vector<int32_t> words = binding == kBindingPointSets
                                                   ? pointSetWords(package.pointSets, package.world.origin,
                                                                   package.world.size)
                                                   : solveTableWords(package.solveTables);
            ASSERT_EQ(buffer["count"].get<size_t>(), words.size());
            ASSERT_EQ(bytes.size(), 4 * words.size());
            for (size_t i = 0; i < words.size(); i += 997) {
                const uint32_t word = uint32_t(uint8_t(bytes[4 * i])) | uint32_t(uint8_t(bytes[4 * i + 1])) << 8 |
                                      uint32_t(uint8_t(bytes[4 * i + 2])) << 16 | uint32_t(uint8_t(bytes[4 * i + 3])) << 24;
                ASSERT_EQ(word, uint32_t(words[i])) << "word " << i;
            }
            ++withFile;
        }
        EXPECT_EQ(withFile, 1u);
    }
}
#endif

} // namespace manifest_contract_test
} // namespace voxc::codegen
