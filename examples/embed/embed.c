/* An engine's use of libvoxc (docs/embedding.md): load a .vox file or a package directory that
 * `voxc compile` wrote, generate its grid (or a box of it), mesh it and read the arrays.
 * Usage: embed FILE.vox|PACKAGE_DIR [vulkan|interpreter] [MINX,MINY,MINZ:MAXX,MAXY,MAXZ]
 * Prints the grid size, the solid voxel count and the mesh's vertex and triangle counts. */
#include <voxc/voxc.h>

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

static int fail(const char* what) {
    fprintf(stderr, "embed: %s failed:\n%s\n", what, voxc_last_error());
    return 1;
}

int main(int argc, char** argv) {
    int32_t min[3], max[3];
    const int region = argc == 4 && sscanf(argv[3], "%d,%d,%d:%d,%d,%d", &min[0], &min[1], &min[2], &max[0], &max[1],
                                           &max[2]) == 6;
    if (argc < 2 || argc > 4 || (argc == 4 && !region)) {
        fprintf(stderr, "usage: embed FILE.vox|PACKAGE_DIR [vulkan|interpreter] [MINX,MINY,MINZ:MAXX,MAXY,MAXZ]\n");
        return 2;
    }
    voxc_backend backend = VOXC_BACKEND_VULKAN;
    if (argc >= 3 && strcmp(argv[2], "interpreter") == 0) backend = VOXC_BACKEND_INTERPRETER;

    voxc_program* program = NULL;
    struct stat input;
    const int package = stat(argv[1], &input) == 0 && S_ISDIR(input.st_mode);
    if ((package ? voxc_package_load(argv[1], &program) : voxc_program_load(argv[1], NULL, &program)) != VOXC_OK)
        return fail("loading");
    voxc_grid* grid = NULL;
    const voxc_status generated =
        region ? voxc_generate_region(program, min, max, backend, &grid) : voxc_generate(program, backend, &grid);
    if (generated != VOXC_OK) {
        voxc_program_free(program);
        return fail("generating");
    }
    int32_t size[3], origin[3];
    voxc_grid_size(grid, size);
    voxc_grid_origin(grid, origin);
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

    printf("%s, grid %dx%dx%d at %d,%d,%d: %zu of %zu voxels solid\n", voxc_version(), size[0], size[1], size[2],
           origin[0], origin[1], origin[2], solid, voxels);
    printf("mesh: %zu vertices, %zu triangles\n", voxc_mesh_vertex_count(mesh), triangles);
    for (int id = 1; id < 256; ++id)
        if (perMaterial[id] > 0) printf("  %s: %zu triangles\n", voxc_program_material_name(program, (uint8_t)id), perMaterial[id]);

    voxc_mesh_free(mesh);
    voxc_grid_free(grid);
    voxc_program_free(program);
    return 0;
}
