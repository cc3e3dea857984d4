/* libvoxc: voxc for engines, as a C API (docs/embedding.md).
 *
 * Load a .vox file (checked and compiled in the process, as `voxc compile` does) or a compiled
 * package, generate its
 * grid on a Vulkan device or with the CPU interpreter (the two agree bit for bit), mesh it with
 * marching cubes, and read the arrays. Every handle is freed by its own voxc_*_free; arrays a
 * handle returns live as long as the handle. No C++ exception crosses this boundary: a function
 * that can fail returns a voxc_status and leaves a message for voxc_last_error().
 *
 * Threads: call libvoxc from one thread at a time. In particular a program is not safe to use
 * from two threads at once, even through the functions that take it as const: its first Vulkan
 * generation makes the Vulkan context that it keeps for the later ones.
 */
#ifndef VOXC_VOXC_H
#define VOXC_VOXC_H

#include <stddef.h>
#include <stdint.h>

#if defined(VOXC_BUILDING_LIBRARY)
#define VOXC_API __attribute__((visibility("default")))
#else
#define VOXC_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* The exit codes of the voxc command line, with one more for a bad argument. */
typedef enum voxc_status {
    VOXC_OK = 0,
    VOXC_ERROR_USER = 1,     /* the file has errors, no Vulkan device, a grid too large, ... */
    VOXC_ERROR_INTERNAL = 2, /* a bug in voxc */
    VOXC_ERROR_ARGUMENT = 3  /* a null pointer or an out-of-range value was passed */
} voxc_status;

typedef enum voxc_backend {
    VOXC_BACKEND_VULKAN = 0,     /* the compiled kernels on a Vulkan device (lavapipe if no GPU) */
    VOXC_BACKEND_INTERPRETER = 1 /* the CPU interpreter, the reference */
} voxc_backend;

typedef struct voxc_program voxc_program; /* a checked and compiled .vox file or a loaded package */
typedef struct voxc_grid voxc_grid;       /* generated densities and material ids */
typedef struct voxc_mesh voxc_mesh;       /* a marching-cubes mesh of a grid */

/* "voxc 0.1.0". */
VOXC_API const char* voxc_version(void);

/* The message of the last failure on the calling thread: for a file with errors, every
 * diagnostic as `voxc check` prints it. Valid until the thread's next libvoxc call. */
VOXC_API const char* voxc_last_error(void);

typedef struct voxc_load_options {
    int has_seed;        /* nonzero: use `seed` instead of the file's world seed */
    uint32_t seed;
    int32_t chunk_size;  /* 0: the file's; else a power of two from 8 to 64 */
} voxc_load_options;

/* Checks and compiles the .vox file at `path` (its rule files are read relative to it).
 * `options` may be null. On success *out holds a program to free with voxc_program_free. */
VOXC_API voxc_status voxc_program_load(const char* path, const voxc_load_options* options, voxc_program** out);
/* Loads a package directory that `voxc compile` wrote (manifest.json, kernels/, data/, sources/),
 * with the seed and chunk size it was compiled with. The kernels' SPIR-V comes from the package (no
 * GLSL compiler runs); the package's copy of the .vox and its rule files is checked again to rebuild
 * the plan, and every file of the package must be what they compile to. VOXC_ERROR_USER, saying
 * why, for a missing, corrupt or foreign package or one another voxc version wrote. */
VOXC_API voxc_status voxc_package_load(const char* directory, voxc_program** out);
VOXC_API void voxc_program_free(voxc_program* program);

/* The world's grid: size in voxels and the world coordinate of voxel (0,0,0). */
VOXC_API void voxc_program_grid(const voxc_program* program, int32_t size[3], int32_t origin[3]);
/* Material names by id (1..255; 0 is "none"); null for an id the file does not declare. */
VOXC_API const char* voxc_program_material_name(const voxc_program* program, uint8_t id);

/* Runs the program over its grid. On success *out holds a grid to free with voxc_grid_free.
 * The first Vulkan generation on a program (whole or region) makes a Vulkan context that the
 * program keeps, with every kernel's pipeline, until voxc_program_free; the program also keeps
 * its regions' SPIR-V. Later generations of the same size (regions of one size whose grown boxes
 * are not clipped by the grid's border) reuse both instead of compiling their kernels again. */
VOXC_API voxc_status voxc_generate(const voxc_program* program, voxc_backend backend, voxc_grid** out);
/* Computes only the box min <= p < max (world coordinates) of the program's grid, grown by the
 * pipeline's halo and cropped back, so its voxels equal the whole grid's there, bit for bit
 * (`voxc run --region`). VOXC_ERROR_ARGUMENT for an empty box or one not inside the grid. */
VOXC_API voxc_status voxc_generate_region(const voxc_program* program, const int32_t min[3], const int32_t max[3],
                                          voxc_backend backend, voxc_grid** out);
/* The kernel pipelines the program's Vulkan generations have used so far: `created` compiled by
 * the driver, `shared` reused from an earlier generation's kernel with the same SPIR-V. Both 0
 * before the first Vulkan generation; either pointer may be null. */
VOXC_API void voxc_program_pipeline_counts(const voxc_program* program, uint64_t* created, uint64_t* shared);
VOXC_API void voxc_grid_free(voxc_grid* grid);

VOXC_API void voxc_grid_size(const voxc_grid* grid, int32_t size[3]);
/* The world coordinate of voxel (0,0,0): the program's origin, or a region's minimum corner. */
VOXC_API void voxc_grid_origin(const voxc_grid* grid, int32_t origin[3]);
/* size[0]*size[1]*size[2] densities (solid where > the mesher's iso, 0.5 by default), x fastest:
 * voxel (x,y,z) at x + size[0]*(y + size[1]*z). */
VOXC_API const float* voxc_grid_densities(const voxc_grid* grid);
/* The material id of each voxel, same order. */
VOXC_API const uint8_t* voxc_grid_materials(const voxc_grid* grid);

/* Marching cubes at `iso` (0.5 as `voxc run`): closed, manifold, bit-identical to `voxc run`'s
 * host mesher. On success *out holds a mesh to free with voxc_mesh_free. */
VOXC_API voxc_status voxc_mesh_grid(const voxc_grid* grid, float iso, voxc_mesh** out);
VOXC_API void voxc_mesh_free(voxc_mesh* mesh);

VOXC_API size_t voxc_mesh_vertex_count(const voxc_mesh* mesh);
VOXC_API size_t voxc_mesh_triangle_count(const voxc_mesh* mesh);
/* 3 floats per vertex, world coordinates. */
VOXC_API const float* voxc_mesh_positions(const voxc_mesh* mesh);
/* 3 floats per vertex, unit length, from solid to air. */
VOXC_API const float* voxc_mesh_normals(const voxc_mesh* mesh);
/* 3 vertex indices per triangle, counter-clockwise seen from air. */
VOXC_API const uint32_t* voxc_mesh_indices(const voxc_mesh* mesh);
/* One material id per triangle. */
VOXC_API const uint8_t* voxc_mesh_triangle_materials(const voxc_mesh* mesh);

#ifdef __cplusplus
}
#endif

#endif /* VOXC_VOXC_H */
