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
    VOXC_ERROR_ARGUMENT = 3, /* a null pointer or an out-of-range value was passed */
    VOXC_CANCELLED = 4       /* the progress callback asked to stop (voxc_set_progress) */
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

/* Called by the long calls of the thread that set it (loading, generating, meshing) with the
 * phase ("check", "compile", "generate", "mesh") and the fraction of it done, from 0 to 1. A
 * nonzero return stops the call, which then returns VOXC_CANCELLED and hands out nothing. */
typedef int (*voxc_progress_fn)(void* user, const char* phase, double fraction);
/* Sets the calling thread's progress callback; a null `fn` removes it. */
VOXC_API void voxc_set_progress(voxc_progress_fn fn, void* user);

/* A value replacing one the file wrote, as a slider of `voxc view` does: `name` is a `const`'s
 * name (as if its declaration said `const NAME = value;`) or "FEATURE.KEY", a feature's key (as if
 * the block wrote `KEY = value;`). Either is checked as if the file said so. */
typedef struct voxc_override {
    const char* name;
    double value;
} voxc_override;

typedef struct voxc_load_options {
    int has_seed;        /* nonzero: use `seed` instead of the file's world seed */
    uint32_t seed;
    int32_t chunk_size;  /* 0: the file's; else a power of two from 8 to 64 */
    const voxc_override* overrides; /* override_count entries, or null */
    size_t override_count;
} voxc_load_options;

/* Checks and compiles the .vox file at `path` (its rule files are read relative to it).
 * `options` may be null. On success *out holds a program to free with voxc_program_free. */
VOXC_API voxc_status voxc_program_load(const char* path, const voxc_load_options* options, voxc_program** out);
/* As voxc_program_load, for `length` bytes of .vox text; `path` names it in diagnostics and its
 * directory is where rule files are read from. */
VOXC_API voxc_status voxc_program_load_source(const char* path, const char* text, size_t length,
                                              const voxc_load_options* options, voxc_program** out);

/* Diagnostics of a check, as values: what `voxc check` prints, one by one. */
typedef struct voxc_diagnostics voxc_diagnostics;

typedef enum voxc_severity { VOXC_SEVERITY_ERROR = 0, VOXC_SEVERITY_WARNING = 1, VOXC_SEVERITY_NOTE = 2 } voxc_severity;

typedef struct voxc_diagnostic {
    const char* code;     /* "E0004", "W0201"; empty for the final "too many errors" line */
    voxc_severity severity;
    const char* file;     /* the file it is located in (an imported rule file, or the checked one) */
    uint32_t line;        /* 1-based; 0: about the whole file */
    uint32_t column;      /* 1-based */
    uint32_t length;      /* characters the location spans */
    const char* message;
    const char* rendered; /* as `voxc check` prints it, caret and notes included */
} voxc_diagnostic;

/* Checks a .vox file (`text` null: the file at `path`; else `length` bytes of text named `path`)
 * and hands out its diagnostics, errors and warnings in report order; the file's own errors are
 * not a failure (VOXC_OK, with error diagnostics). `options` may be null. */
VOXC_API voxc_status voxc_check(const char* path, const char* text, size_t length, const voxc_load_options* options,
                                voxc_diagnostics** out);
VOXC_API size_t voxc_diagnostics_count(const voxc_diagnostics* diagnostics);
/* Fills *out with diagnostic `index`; its strings live as long as `diagnostics`. Returns 0 for
 * an index out of range (then *out is untouched), else 1. */
VOXC_API int voxc_diagnostics_get(const voxc_diagnostics* diagnostics, size_t index, voxc_diagnostic* out);
VOXC_API void voxc_diagnostics_free(voxc_diagnostics* diagnostics);
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
/* The material's colour as the file declares it (linear RGB in [0, 1], what mesh exports use):
 * returns 1 and fills rgb, or 0 for an id the file does not declare. */
VOXC_API int voxc_program_material_color(const voxc_program* program, uint8_t id, float rgb[3]);

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
/* The Vulkan device the program's Vulkan generations run on, as `voxc run --device`: "auto" (a GPU
 * if there is one, else lavapipe; the default), "gpu", "lavapipe" or a device index. A choice
 * other than the current one drops the program's Vulkan context (and its pipelines); the next
 * Vulkan generation makes one on the new device, or fails with VOXC_ERROR_USER when there is none. */
VOXC_API voxc_status voxc_program_set_device(voxc_program* program, const char* device);
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
/* Marching cubes at LOD `level` (0 to 6, cells 2^level voxels wide, at most the chunk size): the
 * mesh `voxc run --lod` writes for that level, closed and manifold; level 0 is voxc_mesh_grid's. */
VOXC_API voxc_status voxc_mesh_grid_lod(const voxc_grid* grid, float iso, int32_t level, voxc_mesh** out);
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
