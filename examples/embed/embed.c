/* An engine's use of libvoxc (docs/embedding.md): load a .vox file, generate its grid, mesh it
 * and read the arrays. Usage: embed FILE.vox [vulkan|interpreter]
 * Prints the grid size, the solid voxel count and the mesh's vertex and triangle counts. */
#include <voxc/voxc.h>

#include <stdio.h>
#include <string.h>

static int fail(const char* what) {
    fprintf(stderr, "embed: %s failed:\n%s\n", what, voxc_last_error());
    return 1;
}

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        fprintf(stderr, "usage: embed FILE.vox [vulkan|interpreter]\n");
        return 2;
    }
    voxc_backend backend = VOXC_BACKEND_VULKAN;
    if (argc == 3 && strcmp(argv[2], "interpreter") == 0) backend = VOXC_BACKEND_INTERPRETER;

    voxc_program* program = NULL;
    if (voxc_program_load(argv[1], NULL, &program) != VOXC_OK) return fail("loading");
    voxc_grid* grid = NULL;
    if (voxc_generate(program, backend, &grid) != VOXC_OK) {
        voxc_program_free(program);
        return fail("generating");
    }
    int32_t size[3];
    voxc_grid_size(grid, size);
    const size_t voxels = (size_t)size[0] * (size_t)size[1] * (size_t)size[2];
    const float* densities = voxc_grid_densities(grid);
    size_t solid = 0;
    for (size_t i = 0; i < voxels; ++i) solid += densities[i] > 0.5f;

    voxc_mesh* mesh = NULL;
    if (voxc_mesh_grid(grid, 0.5f, &mesh) != VOXC_OK) {
        voxc_grid_free(grid);
        voxc_program_free(program);
        return fail("meshing");
    }
    const size_t triangles = voxc_mesh_triangle_count(mesh);
    const uint8_t* materials = voxc_mesh_triangle_materials(mesh);
    size_t perMaterial[256] = {0};
    for (size_t t = 0; t < triangles; ++t) perMaterial[materials[t]]++;

    printf("%s, grid %dx%dx%d: %zu of %zu voxels solid\n", voxc_version(), size[0], size[1], size[2], solid, voxels);
    printf("mesh: %zu vertices, %zu triangles\n", voxc_mesh_vertex_count(mesh), triangles);
    for (int id = 1; id < 256; ++id)
        if (perMaterial[id] > 0) printf("  %s: %zu triangles\n", voxc_program_material_name(program, (uint8_t)id), perMaterial[id]);

    voxc_mesh_free(mesh);
    voxc_grid_free(grid);
    voxc_program_free(program);
    return 0;
}
