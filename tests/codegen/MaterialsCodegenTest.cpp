// Codegen for programs that use materials: every kernel declares the material buffer, field
// kernels carry their stage's material, paint boxes are skipped where nothing can change, and
// the manifest records it all.
#include "SamplePrograms.h"
#include "voxc/codegen/PackageWriter.h"
#include "voxc/stages/Pipeline.h"

#include <gtest/gtest.h>

namespace voxc::codegen {
namespace materials_codegen_test {

bool declaresMaterials(const Kernel& kernel) {
    return kernel.glsl.find("#version 450\n#define VOXC_MATERIALS\n") == 0;
}

const Kernel& kernelNamed(const KernelPackage& package, const std::string& name) {
    for (const Kernel& kernel : package.kernels)
        if (kernel.name == name) return kernel;
    throw std::runtime_error("no kernel " + name);
}

TEST(codegen_Materials, EveryKernelOfAMaterialPackageDeclaresTheBuffer) {
    const KernelPackage package = compileProgram(test::materialProgram());
    EXPECT_TRUE(package.usesMaterials);
    for (const Kernel& kernel : package.kernels) EXPECT_TRUE(declaresMaterials(kernel)) << kernel.name;
    const KernelPackage plain = compileProgram(test::sampleProgram());
    EXPECT_FALSE(plain.usesMaterials);
    for (const Kernel& kernel : plain.kernels) EXPECT_FALSE(declaresMaterials(kernel)) << kernel.name;
}

TEST(codegen_Materials, FieldKernelsAndStagesCarryTheMaterial) {
    const KernelPackage package = compileProgram(test::materialProgram());
    const std::vector<std::pair<std::string, std::optional<uint8_t>>> expected{
        {"half_union_moss", 3}, {"ramp_subtract_sand", 2}, {"slope_intersect_none", 0}, {"half_paint_rock", 1}};
    std::vector<std::pair<std::string, std::optional<uint8_t>>> actual;
    for (const StagePlan& stage : package.stages)
        if (stage.kind == "field") actual.push_back({package.kernels.at(stage.gridKernel).name, stage.material});
    EXPECT_EQ(actual, expected);
    EXPECT_NE(kernelNamed(package, "half_paint_rock").glsl.find("materials.material[address] = 1u;"), std::string::npos);
    EXPECT_NE(kernelNamed(package, "slope_intersect_none").glsl.find("if (wins && result >= 0.5) materials.material[address] = 0u;"),
              std::string::npos);
}

TEST(codegen_Materials, SweepsLoadAndWriteMaterials) {
    const KernelPackage package = compileProgram(test::materialProgram());
    const std::string& spread = kernelNamed(package, "weather_sweep0").glsl;
    EXPECT_NE(spread.find("material0 = materials.material[address0];"), std::string::npos);
    // Cell 0 is tested on its material only: its density is never loaded.
    EXPECT_EQ(spread.find("cell0 = voxels.density[address0];"), std::string::npos);
    EXPECT_NE(spread.find("materials.material[address1] = 3u;"), std::string::npos);
    const std::string& tiles = kernelNamed(package, "weather_sweep0_active_tiles").glsl;
    EXPECT_NE(tiles.find("(material tests may pass)"), std::string::npos);
}

// Paint keeps every density; a constant box is left out where it writes no material.
TEST(codegen_Materials, PaintBoxesAreUnchangedWhereNothingIsPainted) {
    Program program = test::materialProgram();
    const KernelPackage package = compileProgram(program);
    const StagePlan& paint = package.stages.back();
    ASSERT_FALSE(paint.writesDensities); // a paint stage
    size_t kept = 0, skipped = 0;
    for (const FieldBox& box : paint.gridBoxes) {
        if (!box.constant) continue;
        // half is 0.8 (painted where solid; densities unknown after the grammar) or 0.2 (never painted).
        EXPECT_EQ(box.unchanged, box.value < 0.5f);
        (box.unchanged ? skipped : kept) += 1;
    }
    EXPECT_GT(kept, 0u);
    EXPECT_GT(skipped, 0u);
    // Straight after a start of air every density is 0: nothing is painted anywhere.
    program.start.resize(1);
    program.pipeline = {program.pipeline.front(), program.pipeline.back()};
    const KernelPackage airThenPaint = compileProgram(program); // (the loop must not outlive the package)
    for (const FieldBox& box : airThenPaint.stages.back().gridBoxes) EXPECT_EQ(box.unchanged, box.constant);
}

TEST(codegen_Materials, ManifestRecordsMaterials) {
    const std::string manifest = packageManifest(compileProgram(test::materialProgram()));
    EXPECT_NE(manifest.find("\"uses_materials\": true"), std::string::npos);
    EXPECT_NE(manifest.find("\"material\": 3"), std::string::npos);
    EXPECT_NE(manifest.find("\"mode\": \"paint\""), std::string::npos);
    EXPECT_NE(packageManifest(compileProgram(test::sampleProgram())).find("\"uses_materials\": false"),
              std::string::npos);
}

} // namespace materials_codegen_test
} // namespace voxc::codegen
