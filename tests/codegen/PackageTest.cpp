#include "SamplePrograms.h"
#include "PackageTree.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/codegen/PackageReader.h"
#include "voxc/codegen/PackageWriter.h"
#include "voxc/codegen/CompileCache.h"
#include "voxc/core/Errors.h"
#include "voxc/core/Sha256.h"
#ifdef VOXC_HAVE_CHECK
#include "voxc/check/Check.h"
#include "voxc/check/LoadPackage.h"
#endif

#include <chrono>
#include <cstdlib>
#include <fmt/format.h>
#include <filesystem>
#include <functional>
#include <fstream>
#include <algorithm>
#include <gtest/gtest.h>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace voxc::codegen {
namespace package_test {

namespace fs = std::filesystem;

class codegen_Package : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() /
                ("voxc_codegen_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(root_);
    }
    void TearDown() override { fs::remove_all(root_); }
    fs::path root_;
};

using test::readTree;

TEST_F(codegen_Package, CompilingAndWritingTwiceGivesIdenticalBytes) {
    const Program program = test::sampleProgram();
    const PackageSource source{"sample.vox", "grammar text"};
    writePackage(compileProgram(program), (root_ / "a").string(), source);
    writePackage(compileProgram(program), (root_ / "b").string(), source);
    const auto a = readTree(root_ / "a");
    const auto b = readTree(root_ / "b");
    EXPECT_EQ(a.size(), 20u); // manifest + 9 kernels x (.comp, .spv) + sources/0.vox
    EXPECT_EQ(a, b);
    EXPECT_TRUE(a.contains("kernels/overhang_sweep0.spv"));
    EXPECT_TRUE(a.contains("kernels/start.comp"));
}

TEST_F(codegen_Package, WrittenFilesMatchThePackage) {
    const KernelPackage package = compileProgram(test::sampleProgram());
    const PackageSource source{"sample.vox", "grammar text"};
    writePackage(package, root_.string(), source);
    const auto files = readTree(root_);
    for (const Kernel& k : package.kernels) {
        EXPECT_EQ(files.at("kernels/" + k.name + ".comp"), k.glsl);
        const std::string& spv = files.at("kernels/" + k.name + ".spv");
        ASSERT_EQ(spv.size(), k.spirv.size() * 4);
        EXPECT_EQ(std::string(spv.data(), 4), std::string("\x03\x02\x23\x07", 4)); // little-endian magic
    }
    EXPECT_EQ(files.at("manifest.json"), packageManifest(package, source));
    EXPECT_EQ(files, packageFiles(package, source));
}

TEST_F(codegen_Package, ManifestDescribesKernelsAndDispatch) {
    const Program program = test::sampleProgram();
    const KernelPackage package = compileProgram(program);
    const nlohmann::ordered_json m = nlohmann::ordered_json::parse(packageManifest(package, {"sample.vox", "abc"}));
    std::vector<std::string> keys;
    for (const auto& [key, value] : m.items())
        keys.push_back(key);
    EXPECT_EQ(keys, (std::vector<std::string>{"format", "schema_version", "voxc_version", "source", "sources", "world",
                                              "uses_materials", "materials", "push_constants", "buffers", "kernels",
                                              "dispatch", "files"}));
    EXPECT_EQ(m["format"], "voxc-package");
    EXPECT_EQ(m["schema_version"], 1);
    EXPECT_EQ(m["uses_materials"], false);
    EXPECT_EQ(m["materials"], nlohmann::json::array());
    EXPECT_EQ(m["source"]["file"], "sample.vox");
    // FIPS 180-4's example "abc".
    EXPECT_EQ(m["source"]["sha256"], "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    // The package's copy of the source, hashed as `source` is.
    EXPECT_EQ(m["sources"], nlohmann::ordered_json::parse(R"([{"path": "sample.vox", "file": "sources/0.vox",
        "sha256": "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"}])"));
    EXPECT_EQ(m["world"]["origin"], nlohmann::json::array({-5, 3, -12}));
    EXPECT_EQ(m["world"]["chunk"], 8);
    EXPECT_EQ(m["world"]["seed"], 7);
    // Origin -5 with chunks of 8: the table starts at chunk -1.
    EXPECT_EQ(m["world"]["chunk_table"]["base"][0], -1);

    const auto& kernels = m["kernels"];
    ASSERT_EQ(kernels.size(), package.kernels.size());
    const auto& sweep = kernels[1];
    EXPECT_EQ(sweep["name"], "overhang_sweep0");
    EXPECT_EQ(sweep["origin"], package.kernels[1].origin);
    EXPECT_EQ(sweep["glsl"], "kernels/overhang_sweep0.comp");
    EXPECT_EQ(sweep["spv"], "kernels/overhang_sweep0.spv");
    EXPECT_EQ(sweep["local_size"], nlohmann::json::array({8, 8, 1}));
    EXPECT_EQ(sweep["bindings"], nlohmann::json(package.kernels[1].bindings));
    EXPECT_EQ(sweep["spv_sha256"], sha256Hex(packageFiles(package).at("kernels/overhang_sweep0.spv")));
    // The start kernel declares only the shared buffers, not the tile buffers.
    EXPECT_EQ(kernels[0]["bindings"], nlohmann::json::array({kBindingVoxels, kBindingChunkTable, kBindingNoiseTables}));
    EXPECT_EQ(sweep["anchors_per_invocation"], nlohmann::json::array({1, 1, 1}));
    // The start kernel walks whole columns along y.
    EXPECT_EQ(kernels[0]["anchors_per_invocation"], nlohmann::json::array({1, package.world.size.y, 1}));
    const auto& push = m["push_constants"];
    EXPECT_EQ(push["size"], sizeof(PushBlock));
    ASSERT_EQ(push["fields"].size(), 7u);
    EXPECT_EQ(push["fields"][0]["name"], "gridOrigin");
    EXPECT_EQ(push["fields"][6]["name"], "anchorCount");
    EXPECT_EQ(push["fields"][6]["offset"], 96);
    EXPECT_EQ(push["fields"][6]["type"], "ivec4");

    // The voxel buffer holds every chunk of the chunk table.
    const auto& voxels = m["buffers"][0];
    EXPECT_EQ(voxels["binding"], kBindingVoxels);
    EXPECT_EQ(voxels["name"], "voxels");
    EXPECT_EQ(voxels["element_type"], "float");
    EXPECT_EQ(voxels["element_bytes"], 4);
    EXPECT_EQ(voxels["count"], uint64_t(m["world"]["chunk_table"]["count"][0]) *
                                   uint64_t(m["world"]["chunk_table"]["count"][1]) *
                                   uint64_t(m["world"]["chunk_table"]["count"][2]) * 8 * 8 * 8);

    EXPECT_EQ(m["dispatch"]["tile_ranges_kernel"], "tile_ranges");
    const auto& stages = m["dispatch"]["stages"];
    ASSERT_EQ(stages.size(), 3u);
    EXPECT_EQ(stages[0]["kind"], "start");
    EXPECT_EQ(stages[0]["kernel"], "start");
    EXPECT_EQ(stages[1]["grammar"], "overhang");
    EXPECT_EQ(stages[1]["iterations"], 4);
    const auto& smooth = stages[2]["sweeps"][0];
    EXPECT_EQ(smooth["kernel"], "smooth_sweep0");
    EXPECT_EQ(smooth["active_tiles_kernel"], "smooth_sweep0_active_tiles");
    EXPECT_TRUE(stages[2]["sweeps"][1]["active_tiles_kernel"].is_null()); // no live rule
    EXPECT_EQ(smooth["window"], nlohmann::json::array({2, 1, 2}));
    ASSERT_EQ(smooth["phases"].size(), 1u); // stride [2,1,2] covers a [2,1,2] window in one phase
    EXPECT_EQ(smooth["phases"][0]["start"], nlohmann::json::array({1, 2, 0}));
    EXPECT_EQ(smooth["phases"][0]["step"], nlohmann::json::array({2, 1, 2}));
    EXPECT_EQ(smooth["phases"][0]["count"], nlohmann::json::array({9, 9, 5}));
}

// The source hash is SHA-256: FIPS 180-4's examples, including the two-block padding case and a
// long message.
TEST_F(codegen_Package, ManifestHashesTheSourceWithSha256) {
    const KernelPackage package = compileProgram(test::sampleProgram());
    const auto hashOf = [&](std::string text) {
        return nlohmann::json::parse(packageManifest(package, {"x.vox", std::move(text)}))["source"]["sha256"];
    };
    EXPECT_EQ(hashOf(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    EXPECT_EQ(hashOf("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
              "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    EXPECT_EQ(hashOf(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

#ifdef VOXC_HAVE_CHECK
// voxc_package_load: a package of a file importing a rule file, compiled with another seed and
// chunk size, loads without its sources and without glslang, to the plan and files it holds.
TEST_F(codegen_Package, LoadsAPackageAwayFromItsSources) {
    const std::string file = std::string(VOXC_EXAMPLES_DIR) + "/../tests/pipeline/project/world.vox";
    CheckOptions options;
    options.seed = 9;
    const CheckResult checked = checkFile(file, options);
    ASSERT_TRUE(checked.program) << checked.rendered();
    Program program = *checked.program;
    program.world.chunkSize = 8;
    const KernelPackage package = compileProgram(program);
    const PackageSource source = packageSource(file, checked.source.text(), checked.lsystems);
    writePackage(package, (root_ / "pkg").string(), source);
    EXPECT_EQ(readTree(root_ / "pkg").at("sources/1.rules"), source.imports.at(0).text);
    EXPECT_EQ(source.imports.at(0).path, "tunnels.rules");

    const uint64_t compiledBefore = compileCacheCounts().compiled;
    const LoadedPackage loaded = loadPackage((root_ / "pkg").string());
    EXPECT_EQ(compileCacheCounts().compiled, compiledBefore);
    EXPECT_EQ(loaded.program.world.seed, 9u);
    EXPECT_EQ(loaded.program.world.chunkSize, 8);
    EXPECT_EQ(packageFiles(loaded.package, source), packageFiles(package, source));

    // A rule file the copy lacks: the check's error, located.
    std::string manifest = readTree(root_ / "pkg").at("manifest.json");
    manifest.replace(manifest.find("\"tunnels.rules\""), 15, "\"tunnelz.rules\"");
    std::ofstream(root_ / "pkg" / "manifest.json", std::ios::binary) << manifest;
    try {
        loadPackage((root_ / "pkg").string());
        ADD_FAILURE() << "loaded";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("its copy of world.vox does not check"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("E0100"), std::string::npos) << e.what();
    }
}

TEST_F(codegen_Package, ManifestListsFieldStages) {
    CheckResult checked = checkFile(std::string(VOXC_EXAMPLES_DIR) + "/fields.vox");
    ASSERT_TRUE(checked.program) << checked.rendered();
    const nlohmann::json m = nlohmann::json::parse(packageManifest(compileProgram(*checked.program)));
    const auto& stages = m["dispatch"]["stages"];
    // `start` is a dead stage: `set ground` overwrites every voxel.
    ASSERT_EQ(stages.size(), 4u);
    nlohmann::json ground = stages[0];
    // The ground is evaluated in every chunk of fields.vox's grid: the chunks merge into one box.
    EXPECT_EQ(ground["boxes"], nlohmann::json::parse("[[[0, 0, 0], [64, 64, 64]]]"));
    ground.erase("boxes");
    // A field is a function of position: its voxels depend on no other voxel.
    EXPECT_EQ(ground, (nlohmann::json{{"kind", "field"},
                                      {"field", "ground"},
                                      {"mode", "set"},
                                      {"kernel", "ground_set"},
                                      {"dependency_radius", {0, 0, 0}}}));
    EXPECT_EQ(stages[1]["kernel"], "tunnel_subtract");
    EXPECT_EQ(stages[2]["mode"], "union");
    EXPECT_EQ(stages[3]["kind"], "grammar");
}

TEST_F(codegen_Package, ArchUnionSkipsChunksItCannotChange) {
    CheckResult checked = checkFile(std::string(VOXC_EXAMPLES_DIR) + "/arch.vox");
    ASSERT_TRUE(checked.program) << checked.rendered();
    checked.program->world.chunkSize = 8;
    const KernelPackage package = compileProgram(*checked.program);
    ASSERT_EQ(package.stages.size(), 2u);
    // The start box writes 1 over 0, so union with the arch's exact 0 far from it changes nothing.
    size_t evaluated = 0, unchanged = 0;
    for (const FieldBox& box : package.stages[1].gridBoxes) {
        evaluated += !box.constant;
        unchanged += box.unchanged;
        if (box.unchanged) { EXPECT_EQ(box.value, 0.0f); }
    }
    EXPECT_GT(evaluated, 0u);
    EXPECT_GT(unchanged, evaluated);
}

// Density bounds follow the pipeline through field stages: after `set ground` (a clamp to [0, 1])
// the arch's union and the cave's subtract leave the chunks far from them undispatched.
TEST_F(codegen_Package, FieldStagesAfterASetSkipChunksTheyCannotChange) {
    CheckResult checked = checkFile(std::string(VOXC_EXAMPLES_DIR) + "/scene.vox");
    ASSERT_TRUE(checked.program) << checked.rendered();
    checked.program->world.chunkSize = 16;
    const KernelPackage package = compileProgram(*checked.program);
    for (const char* name : {"bridge", "grotto"}) {
        const auto stage = std::find_if(package.stages.begin(), package.stages.end(),
                                        [&](const StagePlan& s) {
                                            const std::pair<std::string, std::string> field{"field", name};
                                            return std::find(s.attributes.begin(), s.attributes.end(), field) !=
                                                   s.attributes.end();
                                        });
        ASSERT_NE(stage, package.stages.end()) << name;
        const size_t unchanged = size_t(std::count_if(stage->gridBoxes.begin(), stage->gridBoxes.end(),
                                                      [](const FieldBox& box) { return box.unchanged; }));
        EXPECT_GT(unchanged, 0u) << name;
    }
}
#endif

// What voxc_package_load does with a package: its files read back and checked, its kernels
// compiled again from the GLSL with the package's SPIR-V (glslang never runs), every file equal.
TEST_F(codegen_Package, ReadingBackTakesTheSpirvAndRefusesAnAlteredPackage) {
    const Program program = test::sampleProgram();
    const KernelPackage package = compileProgram(program);
    const PackageSource source{"sample.vox", "grammar text", {{"../rules/a.rules", "A;F;N;1"}}};
    writePackage(package, root_.string(), source);
    const PackageContents contents = readPackage(root_.string());
    EXPECT_EQ(contents.source.imports.at(0).path, "../rules/a.rules");
    EXPECT_EQ(contents.source.imports.at(0).text, "A;F;N;1");
    EXPECT_EQ(contents.seed, program.world.seed);
    EXPECT_EQ(contents.chunkSize, program.world.chunkSize);
    EXPECT_EQ(contents.files.at("sources/1.rules"), "A;F;N;1");

    const uint64_t compiledBefore = compileCacheCounts().compiled;
    KernelPackage rebuilt;
    {
        const PackagedSpirvScope scope(contents);
        rebuilt = compileProgram(program);
    }
    EXPECT_EQ(compileCacheCounts().compiled, compiledBefore);
    verifyRebuiltPackage(rebuilt, contents);

    const auto refusal = [&](const std::string& path, const std::function<void(std::string&)>& alter) {
        const fs::path copy = root_.string() + "_altered";
        fs::remove_all(copy);
        fs::copy(root_, copy, fs::copy_options::recursive);
        std::string bytes = readTree(copy).at(path);
        alter(bytes);
        std::ofstream(copy / path, std::ios::binary) << bytes;
        try {
            const PackageContents altered = readPackage(copy.string());
            const PackagedSpirvScope scope(altered);
            verifyRebuiltPackage(compileProgram(program), altered);
        } catch (const UserError& e) {
            fs::remove_all(copy);
            return std::string(e.what());
        }
        fs::remove_all(copy);
        return std::string("accepted");
    };
    EXPECT_NE(refusal("kernels/start.spv", [](std::string& b) { b[40] ^= 1; }).find("kernels/start.spv does not match its SHA-256"),
              std::string::npos);
    EXPECT_NE(refusal("sources/1.rules", [](std::string& b) { b[0] = 'B'; }).find("sources/1.rules does not match"),
              std::string::npos);
    EXPECT_NE(refusal("kernels/start.comp", [](std::string& b) { b.back() = ' '; }).find("kernel start whose GLSL differs"),
              std::string::npos);
    // A file of another size than the manifest gives is refused from its size, unread.
    EXPECT_NE(refusal("sources/1.rules", [](std::string& b) { b += "\n"; })
                  .find("sources/1.rules is 8 bytes and manifest.json says 7; the package is corrupt"),
              std::string::npos);
    EXPECT_NE(refusal("manifest.json", [](std::string& b) { b.replace(b.find("\"seed\": 7"), 9, "\"seed\": 8"); })
                  .find("manifest.json differs from what its sources compile to"),
              std::string::npos);
    EXPECT_NE(refusal("manifest.json", [](std::string& b) { b.replace(b.find("\"voxc_version\": \"") + 17, 5, "0.0.1"); })
                  .find("written by voxc 0.0.1"),
              std::string::npos);
    EXPECT_NE(refusal("manifest.json", [](std::string& b) { b.resize(b.size() / 2); }).find("it has no voxc manifest.json"),
              std::string::npos);
    EXPECT_THROW(readPackage((root_ / "none").string()), UserError);
}

// manifest.json's "files" gives every other file's size; a loader checks it before reading the
// file, so a tampered kernel of 4 GiB (sparse: no disk used) is refused at once, never read whole,
// and writing the package again replaces it.
TEST_F(codegen_Package, AFileOfAnotherSizeThanTheManifestSaysIsRefusedUnread) {
    const KernelPackage package = compileProgram(test::sampleProgram());
    const PackageSource source{"sample.vox", "grammar text", {}};
    writePackage(package, root_.string(), source);
    const std::map<std::string, std::string> files = packageFiles(package, source);
    const nlohmann::json listed = nlohmann::json::parse(files.at("manifest.json"))["files"];
    ASSERT_EQ(listed.size() + 1, files.size()); // every file but the manifest
    for (const auto& [path, bytes] : files)
        if (path != "manifest.json") {
            EXPECT_EQ(listed.at(path).get<uint64_t>(), bytes.size()) << path;
        }

    const fs::path spv = root_ / "kernels" / "start.spv";
    const uint64_t written = fs::file_size(spv);
    fs::resize_file(spv, uint64_t(4) << 30);
    const auto started = std::chrono::steady_clock::now();
    try {
        readPackage(root_.string());
        ADD_FAILURE() << "loaded";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find(fmt::format("kernels/start.spv is 4294967296 bytes and manifest.json says "
                                                         "{}; the package is corrupt; compile it again",
                                                         written)),
                  std::string::npos)
            << e.what();
    }
    // Reading 4 GiB of zeros takes seconds; a refusal from the size, milliseconds.
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(2));
    // One byte short is refused as well.
    fs::resize_file(spv, written - 1);
    EXPECT_THROW(readPackage(root_.string()), UserError);
    // `compile` into it again replaces the tampered package.
    EXPECT_EQ(writePackage(package, root_.string(), source), PackageWrite::Replaced);
    EXPECT_EQ(fs::file_size(spv), written);
    EXPECT_NO_THROW(readPackage(root_.string()));
}

TEST_F(codegen_Package, SpirvValAcceptsEveryWrittenModule) {
    const std::string spirvVal = VOXC_SPIRV_VAL;
    if (spirvVal.empty() || spirvVal.ends_with("NOTFOUND")) GTEST_SKIP() << "spirv-val not installed";
    writePackage(compileProgram(test::sampleProgram()), root_.string());
    int modules = 0;
    for (const auto& entry : fs::directory_iterator(root_ / "kernels")) {
        if (entry.path().extension() != ".spv") continue;
        ++modules;
        const std::string command = spirvVal + " --target-env vulkan1.1 '" + entry.path().string() + "' 2>&1";
        EXPECT_EQ(std::system(command.c_str()), 0) << command;
    }
    EXPECT_EQ(modules, 9);
}

} // namespace package_test
} // namespace voxc::codegen
