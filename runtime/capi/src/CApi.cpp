// The C API over the compiler and the runtime. Every entry point that can fail catches
// everything (no C++ exception may unwind into C) and turns it into a status and a message.
#include "voxc/voxc.h"

#include "voxc/check/Check.h"
#include "voxc/check/FeatureOverrides.h"
#include "voxc/check/LoadPackage.h"
#include "voxc/codegen/CompileCache.h"
#include "voxc/core/Errors.h"
#include "voxc/grid/Grid.h"
#include "voxc/mesh/Lod.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Region.h"
#include "voxc/stages/Solve.h"
#include "voxc/syntax/Parser.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <fmt/format.h>
#include <functional>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

struct voxc_program {
    voxc::Program program;
    voxc::KernelPackage package;
    // The Vulkan context of every Vulkan generation on this program, made by the first: it keeps
    // each kernel's pipeline, and regions of one size compile to the same SPIR-V (a region's place
    // is run-time input), so the driver compiles their kernels once instead of once per region,
    // and `regionKernels` keeps that SPIR-V, so glslang compiles them once too. Mutable: the
    // generate functions take a const program (one thread at a time, voxc.h).
    mutable std::unique_ptr<voxc::VulkanContext> context = nullptr;
    std::string device = "auto"; // voxc_program_set_device
    mutable voxc::codegen::SpirvMemo regionKernels = {};
};

struct voxc_grid {
    voxc::DenseGrid dense;     // what the accessors hand out, x fastest
    voxc::ChunkedGrid chunked; // what the mesher reads
};

struct voxc_mesh {
    voxc::Mesh mesh;
};

struct voxc_diagnostics {
    // The strings voxc_diagnostic points into, one entry per diagnostic.
    struct Entry {
        std::string code, file, message, rendered;
        voxc_severity severity;
        voxc::SourceLoc loc;
    };
    std::vector<Entry> entries;
};

namespace {

thread_local std::string lastError;

// The calling thread's progress callback (voxc_set_progress).
thread_local voxc_progress_fn progressFn = nullptr;
thread_local void* progressUser = nullptr;

// How often a Vulkan run calls the progress callback (ExecutorOptions::batchMilliseconds): a
// Ctrl+C in Python stops it within about two of these.
constexpr double kProgressBatchMs = 50;

// Thrown out of the compiler and the runtime when the progress callback asks to stop.
struct Cancelled {};

void reportProgress(const char* phase, double fraction) {
    if (progressFn && progressFn(progressUser, phase, fraction) != 0) throw Cancelled{};
}

// What the engines call between their steps: the thread's callback in the given phase, or nothing.
std::function<void(double)> progressOf(const char* phase) {
    if (!progressFn) return {};
    return [phase](double fraction) { reportProgress(phase, fraction); };
}

voxc_status fail(voxc_status status, std::string message) {
    lastError = std::move(message);
    return status;
}

// Runs `body`, mapping what it throws to the command line's exit codes.
template <typename Body>
voxc_status guarded(Body&& body) {
    try {
        lastError.clear();
        body();
        return VOXC_OK;
    } catch (const Cancelled&) {
        return fail(VOXC_CANCELLED, "cancelled by the progress callback");
    } catch (const voxc::UserError& error) {
        return fail(VOXC_ERROR_USER, error.what());
    } catch (const voxc::InternalError& error) {
        return fail(VOXC_ERROR_INTERNAL, error.what());
    } catch (const std::bad_alloc&) {
        return fail(VOXC_ERROR_USER, "out of memory");
    } catch (const std::exception& error) {
        return fail(VOXC_ERROR_INTERNAL, std::string("internal error: ") + error.what());
    } catch (...) {
        return fail(VOXC_ERROR_INTERNAL, "internal error: an unknown exception");
    }
}

// The .vox text to check: `text` (length bytes, named `path`) or, when null, the file at `path`.
struct Source {
    const char* path;
    const char* text;
    size_t length;
};

// Checks `source` with `options`' seed and overrides, as `voxc check` and `voxc view` would.
voxc::CheckResult checkWith(const Source& source, const voxc_load_options* options) {
    voxc::CheckOptions checkOptions;
    std::map<std::string, double> featureKeys;
    if (options && options->has_seed) checkOptions.seed = options->seed;
    if (options && options->override_count > 0) {
        if (!options->overrides) throw voxc::UserError("overrides: override_count is set but overrides is null");
        for (size_t i = 0; i < options->override_count; ++i) {
            const voxc_override& o = options->overrides[i];
            if (!o.name || !*o.name) throw voxc::UserError(fmt::format("override {}: the name is empty", i));
            if (!std::isfinite(o.value)) throw voxc::UserError(fmt::format("override '{}': the value is not a finite number", o.name));
            const std::string name = o.name;
            if (name.find('.') == std::string::npos) checkOptions.constOverrides[name] = o.value;
            else featureKeys[name] = o.value;
        }
    }
    voxc::Diagnostics readErrors;
    std::optional<voxc::SourceFile> file;
    if (!source.text) {
        file = voxc::loadSourceFile(source.path, readErrors, size_t(checkOptions.limits.maxSourceBytes));
    } else if (source.length > size_t(checkOptions.limits.maxSourceBytes)) {
        readErrors.error("E0012", {},
                         fmt::format("the text of '{}' is larger than the limit of {} bytes ({} MiB)", source.path,
                                     checkOptions.limits.maxSourceBytes, checkOptions.limits.maxSourceBytes >> 20));
    } else {
        file = voxc::SourceFile(source.path, std::string(source.text, source.length));
    }
    if (!file) {
        voxc::CheckResult result;
        result.source = voxc::SourceFile(source.path, "");
        result.diagnostics = readErrors.take();
        return result;
    }
    if (!featureKeys.empty()) {
        // As the viewer's sliders: the keys are written into the text the checker reads.
        voxc::Diagnostics parseErrors;
        const voxc::ast::File parsed = voxc::parse(*file, parseErrors);
        if (const std::string errors = voxc::featureOverrideErrors(parsed, featureKeys); !errors.empty())
            throw voxc::UserError(errors);
        file = voxc::SourceFile(source.path, voxc::overrideFeatureKeys(file->text(), parsed, featureKeys));
    }
    return voxc::checkSource(*file, checkOptions);
}

voxc::Program checkedProgram(const Source& source, const voxc_load_options* options) {
    reportProgress("check", 0.0);
    voxc::CheckResult result = checkWith(source, options);
    if (result.hasErrors() || !result.program)
        throw voxc::UserError(result.rendered());
    reportProgress("check", 1.0);
    voxc::Program program = std::move(*result.program);
    if (options && options->chunk_size != 0) {
        const int32_t c = options->chunk_size;
        if (c < 8 || c > 64 || (c & (c - 1)) != 0)
            throw voxc::UserError(fmt::format("chunk_size {}: the chunk size must be a power of two from 8 to 64", c));
        program.world.chunkSize = c;
    }
    return program;
}

voxc_status loadProgram(const Source& source, const voxc_load_options* options, voxc_program** out) {
    *out = nullptr;
    return guarded([&] {
        voxc::Program program = checkedProgram(source, options);
        voxc::stages::solveBlocks(program); // once: the package, the interpreter and every region read the tables
        reportProgress("compile", 0.0);
        voxc::KernelPackage package = voxc::compileProgram(program);
        reportProgress("compile", 1.0);
        *out = new voxc_program{std::move(program), std::move(package)};
    });
}

// The handle's Vulkan context, made on first use; throws UserError when there is no device.
voxc::VulkanContext& contextOf(const voxc_program& handle) {
    if (!handle.context)
        handle.context =
            std::make_unique<voxc::VulkanContext>(voxc::ContextOptions{.device = handle.device, .shareKernelPipelines = true});
    return *handle.context;
}

// `program`'s whole grid, run by `backend` on `handle`'s context; `package` is `program`'s
// compiled package (`program` is the handle's or a region of it).
voxc::ChunkedGrid runGrid(const voxc_program& handle, const voxc::Program& program, const voxc::KernelPackage& package,
                          voxc_backend backend) {
    reportProgress("generate", 0.0);
    if (backend == VOXC_BACKEND_VULKAN) {
        // With a callback, batches of about kProgressBatchMs: it is called, and can stop the run, that often.
        voxc::VulkanExecutor executor(contextOf(handle), package,
                                      voxc::ExecutorOptions{.batchMilliseconds = progressFn ? kProgressBatchMs : 0,
                                                            .progress = progressOf("generate")});
        voxc::ChunkedGrid grid = executor.run().grid;
        reportProgress("generate", 1.0);
        return grid;
    }
    const voxc::World& world = program.world;
    voxc::DenseGrid dense = voxc::interpret(program, voxc::InterpOptions{.progress = progressOf("generate")});
    reportProgress("generate", 1.0);
    return voxc::ChunkedGrid::fromDense(dense, voxc::ChunkLayout::make(world.origin, world.size, world.chunkSize));
}

voxc_grid* gridOf(voxc::ChunkedGrid chunked) {
    voxc::DenseGrid dense = chunked.toDense();
    return new voxc_grid{std::move(dense), std::move(chunked)};
}

bool validBackend(voxc_backend backend) {
    return backend == VOXC_BACKEND_VULKAN || backend == VOXC_BACKEND_INTERPRETER;
}

} // namespace

extern "C" {

const char* voxc_version(void) { return "voxc 0.1.0"; }

const char* voxc_last_error(void) { return lastError.c_str(); }

void voxc_set_progress(voxc_progress_fn fn, void* user) {
    progressFn = fn;
    progressUser = fn ? user : nullptr;
}

voxc_status voxc_program_load(const char* path, const voxc_load_options* options, voxc_program** out) {
    if (!path || !out) return fail(VOXC_ERROR_ARGUMENT, "voxc_program_load: path and out must not be null");
    return loadProgram(Source{path, nullptr, 0}, options, out);
}

voxc_status voxc_program_load_source(const char* path, const char* text, size_t length, const voxc_load_options* options,
                                     voxc_program** out) {
    if (!path || !text || !out)
        return fail(VOXC_ERROR_ARGUMENT, "voxc_program_load_source: path, text and out must not be null");
    return loadProgram(Source{path, text, length}, options, out);
}

voxc_status voxc_check(const char* path, const char* text, size_t length, const voxc_load_options* options,
                       voxc_diagnostics** out) {
    if (!path || !out) return fail(VOXC_ERROR_ARGUMENT, "voxc_check: path and out must not be null");
    *out = nullptr;
    return guarded([&] {
        const voxc::CheckResult result = checkWith(Source{path, text, length}, options);
        auto diagnostics = std::make_unique<voxc_diagnostics>();
        for (const voxc::Diagnostic& d : result.diagnostics) {
            const voxc_severity severity = d.severity == voxc::Severity::Error     ? VOXC_SEVERITY_ERROR
                                           : d.severity == voxc::Severity::Warning ? VOXC_SEVERITY_WARNING
                                                                                   : VOXC_SEVERITY_NOTE;
            diagnostics->entries.push_back({d.code, d.file ? d.file->path() : result.source.path(), d.message,
                                            voxc::render(d, result.source), severity, d.loc});
        }
        *out = diagnostics.release();
    });
}

size_t voxc_diagnostics_count(const voxc_diagnostics* diagnostics) { return diagnostics ? diagnostics->entries.size() : 0; }

int voxc_diagnostics_get(const voxc_diagnostics* diagnostics, size_t index, voxc_diagnostic* out) {
    if (!diagnostics || !out || index >= diagnostics->entries.size()) return 0;
    const voxc_diagnostics::Entry& e = diagnostics->entries[index];
    *out = voxc_diagnostic{e.code.c_str(), e.severity,      e.file.c_str(),    e.loc.line,
                           e.loc.column,   e.loc.length,    e.message.c_str(), e.rendered.c_str()};
    return 1;
}

void voxc_diagnostics_free(voxc_diagnostics* diagnostics) { delete diagnostics; }

voxc_status voxc_package_load(const char* directory, voxc_program** out) {
    if (!directory || !out) return fail(VOXC_ERROR_ARGUMENT, "voxc_package_load: directory and out must not be null");
    *out = nullptr;
    return guarded([&] {
        voxc::LoadedPackage loaded = voxc::loadPackage(directory);
        *out = new voxc_program{std::move(loaded.program), std::move(loaded.package)};
    });
}

void voxc_program_free(voxc_program* program) { delete program; }

void voxc_program_grid(const voxc_program* program, int32_t size[3], int32_t origin[3]) {
    if (!program) return;
    for (int axis = 0; axis < 3; ++axis) {
        if (size) size[axis] = program->program.world.size[axis];
        if (origin) origin[axis] = program->program.world.origin[axis];
    }
}

const char* voxc_program_material_name(const voxc_program* program, uint8_t id) {
    if (!program) return nullptr;
    const voxc::Material* material = program->program.findMaterial(id);
    return material ? material->name.c_str() : nullptr;
}

int voxc_program_material_color(const voxc_program* program, uint8_t id, float rgb[3]) {
    const voxc::Material* material = program && rgb ? program->program.findMaterial(id) : nullptr;
    if (!material) return 0;
    for (int c = 0; c < 3; ++c) rgb[c] = material->color[c];
    return 1;
}

voxc_status voxc_generate(const voxc_program* program, voxc_backend backend, voxc_grid** out) {
    if (!program || !out) return fail(VOXC_ERROR_ARGUMENT, "voxc_generate: program and out must not be null");
    if (!validBackend(backend))
        return fail(VOXC_ERROR_ARGUMENT, fmt::format("voxc_generate: unknown backend {}", int(backend)));
    *out = nullptr;
    return guarded([&] {
        std::unique_ptr<voxc_grid> grid(gridOf(runGrid(*program, program->program, program->package, backend)));
        *out = grid.release();
    });
}

voxc_status voxc_generate_region(const voxc_program* program, const int32_t min[3], const int32_t max[3],
                                 voxc_backend backend, voxc_grid** out) {
    if (!program || !min || !max || !out)
        return fail(VOXC_ERROR_ARGUMENT, "voxc_generate_region: program, min, max and out must not be null");
    if (!validBackend(backend))
        return fail(VOXC_ERROR_ARGUMENT, fmt::format("voxc_generate_region: unknown backend {}", int(backend)));
    *out = nullptr;
    const voxc::World& world = program->program.world;
    const voxc::stages::GridBox region{glm::ivec3(min[0], min[1], min[2]) - world.origin,
                                       glm::ivec3(max[0], max[1], max[2]) - world.origin};
    for (int axis = 0; axis < 3; ++axis)
        if (region.min[axis] < 0 || region.max[axis] > world.size[axis] || region.min[axis] >= region.max[axis])
            return fail(VOXC_ERROR_ARGUMENT,
                        fmt::format("voxc_generate_region: the box {},{},{}:{},{},{} is empty or not inside the grid "
                                    "{},{},{}:{},{},{}",
                                    min[0], min[1], min[2], max[0], max[1], max[2], world.origin.x, world.origin.y,
                                    world.origin.z, world.origin.x + world.size.x, world.origin.y + world.size.y,
                                    world.origin.z + world.size.z));
    return guarded([&] {
        const voxc::stages::PipelineHalo halo = voxc::stages::pipelineHalo(program->program);
        const voxc::stages::GridBox computed = voxc::stages::haloBox(program->program, region, halo.radius);
        const voxc::Program regionProgram = voxc::stages::regionProgram(program->program, computed);
        voxc::KernelPackage package;
        if (backend == VOXC_BACKEND_VULKAN) {
            reportProgress("compile", 0.0);
            const voxc::codegen::SpirvMemoScope kernels(program->regionKernels);
            package = voxc::compileProgram(regionProgram);
            reportProgress("compile", 1.0);
        }
        const voxc::ChunkedGrid grid = runGrid(*program, regionProgram, package, backend);
        const glm::ivec3 offset = region.min - computed.min;
        const voxc::DenseGrid voxels = voxc::stages::cropGrid(grid.toDense(), {offset, offset + region.size()});
        const voxc::ChunkLayout& layout = grid.layout();
        *out = gridOf(voxc::ChunkedGrid::fromDense(
            voxels, voxc::ChunkLayout::make(layout.gridOrigin + offset, voxels.size(), layout.chunkSize)));
    });
}

voxc_status voxc_program_set_device(voxc_program* program, const char* device) {
    if (!program || !device) return fail(VOXC_ERROR_ARGUMENT, "voxc_program_set_device: program and device must not be null");
    return guarded([&] {
        if (program->device == device) return;
        program->context.reset();
        program->device = device;
    });
}

void voxc_program_pipeline_counts(const voxc_program* program, uint64_t* created, uint64_t* shared) {
    const voxc::KernelPipelineCounts counts =
        program && program->context ? program->context->kernelPipelineCounts() : voxc::KernelPipelineCounts{};
    if (created) *created = counts.created;
    if (shared) *shared = counts.shared;
}

void voxc_grid_free(voxc_grid* grid) { delete grid; }

void voxc_grid_size(const voxc_grid* grid, int32_t size[3]) {
    if (!grid || !size) return;
    for (int axis = 0; axis < 3; ++axis) size[axis] = grid->dense.size()[axis];
}

void voxc_grid_origin(const voxc_grid* grid, int32_t origin[3]) {
    if (!grid || !origin) return;
    for (int axis = 0; axis < 3; ++axis) origin[axis] = grid->chunked.layout().gridOrigin[axis];
}

const float* voxc_grid_densities(const voxc_grid* grid) { return grid ? grid->dense.data().data() : nullptr; }

const uint8_t* voxc_grid_materials(const voxc_grid* grid) { return grid ? grid->dense.materials().data() : nullptr; }

voxc_status voxc_mesh_grid(const voxc_grid* grid, float iso, voxc_mesh** out) {
    if (!grid || !out) return fail(VOXC_ERROR_ARGUMENT, "voxc_mesh_grid: grid and out must not be null");
    if (!std::isfinite(iso)) return fail(VOXC_ERROR_ARGUMENT, "voxc_mesh_grid: iso must be a finite number");
    *out = nullptr;
    return guarded([&] {
        reportProgress("mesh", 0.0);
        auto mesh = std::make_unique<voxc_mesh>(voxc_mesh{voxc::meshMarchingCubes(grid->chunked, voxc::MeshOptions{.iso = iso})});
        reportProgress("mesh", 1.0);
        *out = mesh.release();
    });
}

voxc_status voxc_mesh_grid_lod(const voxc_grid* grid, float iso, int32_t level, voxc_mesh** out) {
    if (!grid || !out) return fail(VOXC_ERROR_ARGUMENT, "voxc_mesh_grid_lod: grid and out must not be null");
    if (!std::isfinite(iso)) return fail(VOXC_ERROR_ARGUMENT, "voxc_mesh_grid_lod: iso must be a finite number");
    const int32_t chunkSize = grid->chunked.layout().chunkSize;
    if (level < 0 || level > voxc::kMaxLodLevel || (1 << level) > chunkSize)
        return fail(VOXC_ERROR_ARGUMENT,
                    fmt::format("voxc_mesh_grid_lod: level {} is not from 0 to {} with cells at most the {}-voxel chunk size",
                                level, voxc::kMaxLodLevel, chunkSize));
    *out = nullptr;
    return guarded([&] {
        reportProgress("mesh", 0.0);
        const voxc::LodPyramid pyramid(grid->chunked, level);
        auto mesh = std::make_unique<voxc_mesh>(voxc_mesh{voxc::meshLod(
            pyramid, voxc::LodLayout::uniform(grid->chunked.layout(), level), voxc::MeshOptions{.iso = iso})});
        reportProgress("mesh", 1.0);
        *out = mesh.release();
    });
}

void voxc_mesh_free(voxc_mesh* mesh) { delete mesh; }

size_t voxc_mesh_vertex_count(const voxc_mesh* mesh) { return mesh ? mesh->mesh.positions.size() : 0; }

size_t voxc_mesh_triangle_count(const voxc_mesh* mesh) { return mesh ? mesh->mesh.triangles.size() / 3 : 0; }

// glm::vec3 is three packed floats, so a vector of them is the flat array the header promises.
static_assert(sizeof(glm::vec3) == 3 * sizeof(float));

const float* voxc_mesh_positions(const voxc_mesh* mesh) {
    return mesh ? reinterpret_cast<const float*>(mesh->mesh.positions.data()) : nullptr;
}

const float* voxc_mesh_normals(const voxc_mesh* mesh) {
    return mesh ? reinterpret_cast<const float*>(mesh->mesh.normals.data()) : nullptr;
}

const uint32_t* voxc_mesh_indices(const voxc_mesh* mesh) { return mesh ? mesh->mesh.triangles.data() : nullptr; }

const uint8_t* voxc_mesh_triangle_materials(const voxc_mesh* mesh) {
    return mesh ? mesh->mesh.triangleMaterials.data() : nullptr;
}

} // extern "C"
