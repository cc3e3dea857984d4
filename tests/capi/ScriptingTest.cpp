// What scripting languages need of libvoxc (the Python module, docs/python.md): diagnostics as
// values, programs from text with the viewer's overrides, a progress callback that can stop a
// call, LOD meshes and material colours.
#include <voxc/voxc.h>

#include <cstring>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace {

const char* kBroken = "world { size = [16, 16, 16]; }\nfield ground = clamp(8 - y, 0, 1) + nowhere;\n";
const char* kGround = "const H = 8;\nworld { size = [16, 16, 16]; chunk = 8; }\n"
                      "material rock { id = 3; color = [0.25, 0.5, 0.75]; }\n"
                      "field ground = clamp(H - y, 0, 1);\npipeline { start; set ground material rock; }\n";

voxc_program* loadText(const char* text, const voxc_load_options* options = nullptr) {
    voxc_program* program = nullptr;
    EXPECT_EQ(voxc_program_load_source("ground.vox", text, std::strlen(text), options, &program), VOXC_OK) << voxc_last_error();
    return program;
}

size_t solidVoxels(voxc_program* program) {
    voxc_grid* grid = nullptr;
    EXPECT_EQ(voxc_generate(program, VOXC_BACKEND_INTERPRETER, &grid), VOXC_OK) << voxc_last_error();
    int32_t size[3];
    voxc_grid_size(grid, size);
    size_t solid = 0;
    for (size_t i = 0; i < size_t(size[0]) * size[1] * size[2]; ++i) solid += voxc_grid_densities(grid)[i] > 0.5f;
    voxc_grid_free(grid);
    return solid;
}

TEST(Scripting, CheckGivesLocatedDiagnosticsWithoutFailing) {
    voxc_diagnostics* diagnostics = nullptr;
    ASSERT_EQ(voxc_check("broken.vox", kBroken, std::strlen(kBroken), nullptr, &diagnostics), VOXC_OK);
    ASSERT_GE(voxc_diagnostics_count(diagnostics), 1u);
    voxc_diagnostic d;
    ASSERT_EQ(voxc_diagnostics_get(diagnostics, 0, &d), 1);
    EXPECT_EQ(d.severity, VOXC_SEVERITY_ERROR);
    EXPECT_STREQ(d.code, "E0002");
    EXPECT_STREQ(d.file, "broken.vox");
    EXPECT_EQ(d.line, 2u);
    EXPECT_EQ(d.column, uint32_t(std::string(kBroken).find("nowhere") - std::string(kBroken).find('\n')));
    EXPECT_NE(std::string(d.rendered).find("broken.vox:2:"), std::string::npos);
    EXPECT_EQ(voxc_diagnostics_get(diagnostics, voxc_diagnostics_count(diagnostics), &d), 0);
    voxc_diagnostics_free(diagnostics);
}

TEST(Scripting, ConstOverridesAsTheViewersSliders) {
    voxc_program* plain = loadText(kGround);
    const voxc_override higher{"H", 12.0};
    const voxc_load_options options{0, 0, 0, &higher, 1};
    voxc_program* raised = loadText(kGround, &options);
    EXPECT_EQ(solidVoxels(plain), 16u * 16u * 8u);
    EXPECT_EQ(solidVoxels(raised), 16u * 16u * 12u);
    voxc_program_free(plain);
    voxc_program_free(raised);

    const voxc_override unknown{"NOPE", 1.0};
    const voxc_load_options bad{0, 0, 0, &unknown, 1};
    voxc_program* program = nullptr;
    EXPECT_EQ(voxc_program_load_source("ground.vox", kGround, std::strlen(kGround), &bad, &program), VOXC_ERROR_USER);
    EXPECT_EQ(program, nullptr);
    EXPECT_NE(std::string(voxc_last_error()).find("NOPE"), std::string::npos);
}

TEST(Scripting, ProgressReportsAndCancels) {
    voxc_program* program = loadText(kGround);
    struct Seen {
        std::vector<std::string> phases;
        bool stop = false;
    } seen;
    voxc_set_progress(
        [](void* user, const char* phase, double) {
            auto& s = *static_cast<Seen*>(user);
            s.phases.push_back(phase);
            return s.stop ? 1 : 0;
        },
        &seen);
    voxc_grid* grid = nullptr;
    ASSERT_EQ(voxc_generate(program, VOXC_BACKEND_INTERPRETER, &grid), VOXC_OK) << voxc_last_error();
    EXPECT_EQ(seen.phases.front(), "generate");
    voxc_grid_free(grid);
    seen.stop = true;
    EXPECT_EQ(voxc_generate(program, VOXC_BACKEND_INTERPRETER, &grid), VOXC_CANCELLED);
    EXPECT_EQ(grid, nullptr);
    voxc_set_progress(nullptr, nullptr);
    ASSERT_EQ(voxc_generate(program, VOXC_BACKEND_INTERPRETER, &grid), VOXC_OK); // removed: nothing stops it
    voxc_grid_free(grid);
    voxc_program_free(program);
}

TEST(Scripting, LodMeshesAndMaterialColours) {
    voxc_program* program = loadText(kGround);
    float rgb[3];
    ASSERT_EQ(voxc_program_material_color(program, 3, rgb), 1);
    EXPECT_EQ(rgb[0], 0.25f);
    EXPECT_EQ(rgb[2], 0.75f);
    EXPECT_EQ(voxc_program_material_color(program, 4, rgb), 0);
    voxc_grid* grid = nullptr;
    ASSERT_EQ(voxc_generate(program, VOXC_BACKEND_INTERPRETER, &grid), VOXC_OK);
    voxc_mesh *fine = nullptr, *coarse = nullptr, *none = nullptr;
    ASSERT_EQ(voxc_mesh_grid_lod(grid, 0.5f, 0, &fine), VOXC_OK) << voxc_last_error();
    ASSERT_EQ(voxc_mesh_grid_lod(grid, 0.5f, 1, &coarse), VOXC_OK) << voxc_last_error();
    EXPECT_LT(voxc_mesh_triangle_count(coarse), voxc_mesh_triangle_count(fine));
    EXPECT_GT(voxc_mesh_triangle_count(coarse), 0u);
    EXPECT_EQ(voxc_mesh_grid_lod(grid, 0.5f, 4, &none), VOXC_ERROR_ARGUMENT); // 16-voxel cells, 8-voxel chunks
    EXPECT_EQ(none, nullptr);
    voxc_mesh_free(fine);
    voxc_mesh_free(coarse);
    voxc_grid_free(grid);
    voxc_program_free(program);
}

} // namespace
