// The Python module voxc._native over libvoxc's C API (voxc/voxc.h; docs/python.md): programs,
// grids and meshes as Python objects whose NumPy arrays view the C handles' memory, checks as
// Diagnostic objects. Every long call runs with the GIL released; libvoxc's progress callback
// takes it back between steps to report progress and to let Ctrl+C (KeyboardInterrupt) stop the
// call, which then hands out nothing.
#include "voxc/voxc.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace {

// voxc.Error and its kinds, made in PYBIND11_MODULE.
PyObject* errorType = nullptr;
PyObject* userErrorType = nullptr;
PyObject* internalErrorType = nullptr;
PyObject* cancelledType = nullptr;

struct Diagnostic {
    std::string code, severity, file;
    uint32_t line = 0, column = 0, length = 0;
    std::string message, rendered;
};

// What one long call's progress callback saw: the Python exception to raise instead of
// VOXC_CANCELLED (KeyboardInterrupt, or what the user's callback raised), if any.
struct CallState {
    py::object progress; // None or a callable(phase: str, fraction: float) -> bool | None
    std::optional<py::error_already_set> raised;
    bool declined = false; // the callback returned False
};

// libvoxc's progress callback: runs on the calling thread, which has released the GIL.
int progressTrampoline(void* user, const char* phase, double fraction) {
    auto& state = *static_cast<CallState*>(user);
    py::gil_scoped_acquire gil;
    try {
        // Runs Python's signal handlers (on the main thread): Ctrl+C raises KeyboardInterrupt here.
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (!state.progress.is_none()) {
            const py::object answer = state.progress(phase, fraction);
            if (!answer.is_none() && !answer.cast<bool>()) {
                state.declined = true;
                return 1;
            }
        }
    } catch (py::error_already_set& error) {
        state.raised = std::move(error);
        return 1;
    }
    return 0;
}

// Raises what a failed C call means in Python; `state` is the call's, if it had progress.
[[noreturn]] void raiseStatus(voxc_status status, CallState* state = nullptr) {
    if (status == VOXC_CANCELLED && state) {
        if (state->raised) throw std::move(*state->raised);
        if (state->declined) {
            PyErr_SetString(cancelledType, "the progress callback returned False");
            throw py::error_already_set();
        }
    }
    const std::string message = voxc_last_error();
    PyObject* type = status == VOXC_ERROR_USER       ? userErrorType
                     : status == VOXC_ERROR_ARGUMENT ? PyExc_ValueError
                     : status == VOXC_CANCELLED      ? cancelledType
                                                     : internalErrorType;
    PyErr_SetString(type, message.c_str());
    throw py::error_already_set();
}

// Runs `call` (a libvoxc call returning voxc_status) with the GIL released and the progress
// callback set for its duration; raises on failure.
template <typename Call>
void longCall(const py::object& progress, Call&& call) {
    CallState state{progress};
    voxc_status status;
    {
        py::gil_scoped_release released;
        voxc_set_progress(progressTrampoline, &state);
        status = call();
        voxc_set_progress(nullptr, nullptr);
    }
    if (status != VOXC_OK) raiseStatus(status, &state);
}

struct LoadOptions {
    voxc_load_options options{};
    std::vector<std::string> names; // what options.overrides point into
    std::vector<voxc_override> overrides;
};

void fillOptions(LoadOptions& out, std::optional<uint32_t> seed, std::optional<int32_t> chunk,
                 const std::optional<std::map<std::string, double>>& overrides) {
    out.options.has_seed = seed.has_value();
    out.options.seed = seed.value_or(0);
    out.options.chunk_size = chunk.value_or(0);
    if (overrides) {
        out.names.reserve(overrides->size());
        for (const auto& [name, value] : *overrides) {
            out.names.push_back(name);
            out.overrides.push_back({nullptr, value});
        }
        for (size_t i = 0; i < out.names.size(); ++i) out.overrides[i].name = out.names[i].c_str();
        out.options.overrides = out.overrides.data();
        out.options.override_count = out.overrides.size();
    }
}

// A C handle shared by the Python objects and the NumPy arrays viewing its memory.
template <typename T, void (*Free)(T*)>
std::shared_ptr<T> own(T* handle) {
    return std::shared_ptr<T>(handle, Free);
}

// A NumPy array over `data` (owned by `owner`) with the given shape and element strides.
template <typename E, typename Owner>
py::array viewOf(const E* data, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides, const Owner& owner) {
    for (py::ssize_t& s : strides) s *= py::ssize_t(sizeof(E));
    // The capsule keeps the handle alive as long as the array (or a view of it) exists.
    auto* keep = new Owner(owner);
    py::capsule base(keep, [](void* p) { delete static_cast<Owner*>(p); });
    return py::array(py::dtype::of<E>(), std::move(shape), std::move(strides), data, base);
}

struct Mesh {
    std::shared_ptr<voxc_mesh> handle;
    int lod = 0;

    size_t vertexCount() const { return voxc_mesh_vertex_count(handle.get()); }
    size_t triangleCount() const { return voxc_mesh_triangle_count(handle.get()); }
    py::array vertices() const {
        return viewOf(voxc_mesh_positions(handle.get()), {py::ssize_t(vertexCount()), 3}, {3, 1}, handle);
    }
    py::array normals() const {
        return viewOf(voxc_mesh_normals(handle.get()), {py::ssize_t(vertexCount()), 3}, {3, 1}, handle);
    }
    py::array triangles() const {
        return viewOf(voxc_mesh_indices(handle.get()), {py::ssize_t(triangleCount()), 3}, {3, 1}, handle);
    }
    py::array materials() const {
        return viewOf(voxc_mesh_triangle_materials(handle.get()), {py::ssize_t(triangleCount())}, {1}, handle);
    }
};

struct Grid {
    std::shared_ptr<voxc_grid> handle;
    std::array<int32_t, 3> size{}, origin{};

    explicit Grid(voxc_grid* grid) : handle(own<voxc_grid, voxc_grid_free>(grid)) {
        voxc_grid_size(grid, size.data());
        voxc_grid_origin(grid, origin.data());
    }
    // libvoxc's grids are x fastest: shape (x, y, z) with Fortran strides indexes them as [x, y, z],
    // the same as `voxc run --voxels`' C-order (size_x, size_y, size_z) file, without a copy.
    std::vector<py::ssize_t> shape() const { return {size[0], size[1], size[2]}; }
    std::vector<py::ssize_t> strides() const { return {1, size[0], py::ssize_t(size[0]) * size[1]}; }
    py::array density() const { return viewOf(voxc_grid_densities(handle.get()), shape(), strides(), handle); }
    py::array material() const { return viewOf(voxc_grid_materials(handle.get()), shape(), strides(), handle); }

    std::vector<Mesh> meshLevels(float iso, const std::vector<int>& levels, const py::object& progress) const {
        std::vector<Mesh> meshes;
        for (int level : levels) {
            voxc_mesh* mesh = nullptr;
            longCall(progress, [&] {
                return level == 0 ? voxc_mesh_grid(handle.get(), iso, &mesh) : voxc_mesh_grid_lod(handle.get(), iso, level, &mesh);
            });
            meshes.push_back(Mesh{own<voxc_mesh, voxc_mesh_free>(mesh), level});
        }
        return meshes;
    }
};

std::vector<Diagnostic> diagnosticsOf(const voxc_diagnostics* diagnostics) {
    std::vector<Diagnostic> out;
    static const char* const severities[] = {"error", "warning", "note"};
    for (size_t i = 0; i < voxc_diagnostics_count(diagnostics); ++i) {
        voxc_diagnostic d;
        voxc_diagnostics_get(diagnostics, i, &d);
        out.push_back({d.code, severities[d.severity], d.file, d.line, d.column, d.length, d.message, d.rendered});
    }
    return out;
}

// A .vox path, or text: a str is text when it has a line break or does not end in ".vox".
struct SourceArg {
    std::string path;
    std::optional<std::string> text;
};

SourceArg sourceOf(const py::object& source, const std::optional<std::string>& text, const std::string& name) {
    if (text) {
        if (!source.is_none()) throw py::value_error("give a path or text=, not both");
        return {name, text};
    }
    if (source.is_none()) throw py::value_error("give a .vox path, .vox text, or text=");
    if (!py::isinstance<py::str>(source)) // os.PathLike
        return {py::str(py::module_::import("os").attr("fspath")(source)).cast<std::string>(), std::nullopt};
    const std::string s = source.cast<std::string>();
    const bool isPath = s.find('\n') == std::string::npos && s.size() >= 4 &&
                        std::equal(s.end() - 4, s.end(), ".vox", [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
    if (isPath) return {s, std::nullopt};
    return {name, s};
}

// Checks the source and returns its diagnostics; raises nothing for the file's own errors.
std::vector<Diagnostic> check(const py::object& source, const std::optional<std::string>& text, const std::string& name,
                              std::optional<uint32_t> seed, const std::optional<std::map<std::string, double>>& overrides) {
    const SourceArg arg = sourceOf(source, text, name);
    LoadOptions options;
    fillOptions(options, seed, std::nullopt, overrides);
    voxc_diagnostics* diagnostics = nullptr;
    longCall(py::none(), [&] {
        return voxc_check(arg.path.c_str(), arg.text ? arg.text->data() : nullptr, arg.text ? arg.text->size() : 0,
                          &options.options, &diagnostics);
    });
    const std::shared_ptr<voxc_diagnostics> owned(diagnostics, voxc_diagnostics_free);
    return diagnosticsOf(diagnostics);
}

struct Program {
    std::shared_ptr<voxc_program> handle;
    // libvoxc's programs are for one thread at a time; Python threads take turns here.
    std::shared_ptr<std::mutex> busy = std::make_shared<std::mutex>();
    std::array<int32_t, 3> size{}, origin{};

    Program(const py::object& source, const std::optional<std::string>& text, const std::optional<std::string>& package,
            const std::string& name, std::optional<uint32_t> seed, std::optional<int32_t> chunk,
            const std::optional<std::map<std::string, double>>& overrides, const py::object& progress) {
        voxc_program* program = nullptr;
        if (package) {
            if (!source.is_none() || text) throw py::value_error("give one of a path, text= or package=");
            if (seed || chunk || overrides)
                throw py::value_error("a package keeps the seed, chunk size and values it was compiled with");
            longCall(progress, [&] { return voxc_package_load(package->c_str(), &program); });
        } else {
            const SourceArg arg = sourceOf(source, text, name);
            LoadOptions options;
            fillOptions(options, seed, chunk, overrides);
            longCall(progress, [&] {
                return arg.text ? voxc_program_load_source(arg.path.c_str(), arg.text->data(), arg.text->size(),
                                                           &options.options, &program)
                                : voxc_program_load(arg.path.c_str(), &options.options, &program);
            });
        }
        handle = own<voxc_program, voxc_program_free>(program);
        voxc_program_grid(program, size.data(), origin.data());
    }

    py::dict materials() const {
        py::dict out;
        for (int id = 1; id < 256; ++id)
            if (const char* name = voxc_program_material_name(handle.get(), uint8_t(id))) out[py::int_(id)] = name;
        return out;
    }

    py::dict materialColors() const {
        py::dict out;
        for (int id = 1; id < 256; ++id) {
            float rgb[3];
            if (voxc_program_material_color(handle.get(), uint8_t(id), rgb)) out[py::int_(id)] = py::make_tuple(rgb[0], rgb[1], rgb[2]);
        }
        return out;
    }

    Grid run(const std::optional<std::pair<std::array<int32_t, 3>, std::array<int32_t, 3>>>& region,
             const std::string& device, const py::object& progress) const {
        voxc_backend backend = VOXC_BACKEND_VULKAN;
        std::string vulkanDevice = device;
        if (device == "interp" || device == "interpreter") backend = VOXC_BACKEND_INTERPRETER;
        else if (device == "vulkan") vulkanDevice = "auto";
        else if (device != "auto" && device != "gpu" && device != "lavapipe")
            throw py::value_error("device must be \"auto\", \"gpu\", \"lavapipe\", \"vulkan\" or \"interp\", not \"" + device + "\"");
        voxc_grid* grid = nullptr;
        std::unique_lock<std::mutex> lock(*busy, std::defer_lock);
        {
            py::gil_scoped_release released; // wait for another thread's call without holding the GIL
            lock.lock();
        }
        if (backend == VOXC_BACKEND_VULKAN) {
            const voxc_status status = voxc_program_set_device(handle.get(), vulkanDevice.c_str());
            if (status != VOXC_OK) raiseStatus(status);
        }
        longCall(progress, [&] {
            return region ? voxc_generate_region(handle.get(), region->first.data(), region->second.data(), backend, &grid)
                          : voxc_generate(handle.get(), backend, &grid);
        });
        return Grid(grid);
    }

    std::pair<uint64_t, uint64_t> pipelineCounts() const {
        uint64_t created = 0, shared = 0;
        voxc_program_pipeline_counts(handle.get(), &created, &shared);
        return {created, shared};
    }
};

py::tuple tupleOf(const std::array<int32_t, 3>& v) { return py::make_tuple(v[0], v[1], v[2]); }

std::vector<int> levelsOf(const py::object& lod) {
    if (py::isinstance<py::int_>(lod)) return {lod.cast<int>()};
    return lod.cast<std::vector<int>>();
}

py::object meshResult(std::vector<Mesh> meshes, const py::object& lod) {
    if (py::isinstance<py::int_>(lod)) return py::cast(std::move(meshes.front()));
    return py::cast(std::move(meshes));
}

} // namespace

PYBIND11_MODULE(_native, m) {
    m.doc() = "voxc's C API (libvoxc) as Python objects; import voxc, not this module.";
    errorType = PyErr_NewExceptionWithDoc("voxc.Error", "Base of the errors voxc raises.", PyExc_Exception, nullptr);
    userErrorType = PyErr_NewExceptionWithDoc(
        "voxc.UserError", "The file has errors (the message holds every diagnostic as `voxc check` prints it), no Vulkan "
        "device, a grid too large, a corrupt package.", errorType, nullptr);
    internalErrorType = PyErr_NewExceptionWithDoc("voxc.InternalError", "A bug in voxc.", errorType, nullptr);
    cancelledType = PyErr_NewExceptionWithDoc("voxc.Cancelled", "The progress callback returned False.", errorType, nullptr);
    m.attr("Error") = py::handle(errorType);
    m.attr("UserError") = py::handle(userErrorType);
    m.attr("InternalError") = py::handle(internalErrorType);
    m.attr("Cancelled") = py::handle(cancelledType);
    m.attr("__version__") = std::string(voxc_version()).substr(5); // "voxc 0.1.0" -> "0.1.0"

    py::class_<Diagnostic>(m, "Diagnostic", "One diagnostic of a check, as `voxc check` reports it.")
        .def_readonly("code", &Diagnostic::code, "Stable code such as 'E0004' or 'W0201' (empty for 'too many errors').")
        .def_readonly("severity", &Diagnostic::severity, "'error', 'warning' or 'note'.")
        .def_readonly("file", &Diagnostic::file, "The file it is located in (an imported rule file, or the checked one).")
        .def_readonly("line", &Diagnostic::line, "1-based line; 0 when it is about the whole file.")
        .def_readonly("column", &Diagnostic::column, "1-based column.")
        .def_readonly("length", &Diagnostic::length, "Characters the location spans.")
        .def_readonly("message", &Diagnostic::message, "The message alone.")
        .def_readonly("rendered", &Diagnostic::rendered, "As `voxc check` prints it: file:line:col, caret, notes.")
        .def("__str__", [](const Diagnostic& d) { return d.rendered; })
        .def("__repr__", [](const Diagnostic& d) {
            return "<Diagnostic " + d.severity + " " + d.code + " " + d.file + ":" + std::to_string(d.line) + ":" +
                   std::to_string(d.column) + ": " + d.message + ">";
        });

    py::class_<Mesh>(m, "Mesh", "A marching-cubes mesh: closed, manifold, world coordinates; arrays view its memory.")
        .def_property_readonly("vertices", &Mesh::vertices, "float32 (n, 3): vertex positions, world coordinates.")
        .def_property_readonly("normals", &Mesh::normals, "float32 (n, 3): unit normals from solid to air.")
        .def_property_readonly("triangles", &Mesh::triangles, "uint32 (m, 3): vertex indices, counter-clockwise seen from air.")
        .def_property_readonly("materials", &Mesh::materials, "uint8 (m,): the material id of each triangle.")
        .def_readonly("lod", &Mesh::lod, "The LOD level: cells 2**lod voxels wide.")
        .def("__repr__", [](const Mesh& mesh) {
            return "<voxc.Mesh lod " + std::to_string(mesh.lod) + ": " + std::to_string(mesh.vertexCount()) + " vertices, " +
                   std::to_string(mesh.triangleCount()) + " triangles>";
        });

    py::class_<Grid>(m, "Grid", "Generated densities and material ids; arrays view its memory (no copy).")
        .def_property_readonly("density", &Grid::density,
                               "float32, shape (size_x, size_y, size_z), indexed [x, y, z] (grid-local), as `voxc run "
                               "--voxels` writes it; solid where > 0.5. A view of the grid (Fortran-ordered), not a copy.")
        .def_property_readonly("material", &Grid::material,
                               "uint8, same shape and indexing as density: each voxel's material id (0 is none).")
        .def_property_readonly("size", [](const Grid& grid) { return tupleOf(grid.size); }, "Voxels per axis (x, y, z).")
        .def_property_readonly("origin", [](const Grid& grid) { return tupleOf(grid.origin); },
                               "World coordinate of voxel [0, 0, 0]: the program's origin or the region's corner.")
        .def(
            "mesh",
            [](const Grid& grid, float iso, const py::object& lod, const py::object& progress) {
                return meshResult(grid.meshLevels(iso, levelsOf(lod), progress), lod);
            },
            py::arg("iso") = 0.5f, py::arg("lod") = 0, py::arg("progress") = py::none(),
            "Marching cubes at `iso`: a Mesh for an int `lod`, a list for a sequence of levels (0 to 6).")
        .def("__repr__", [](const Grid& grid) {
            return "<voxc.Grid " + std::to_string(grid.size[0]) + "x" + std::to_string(grid.size[1]) + "x" +
                   std::to_string(grid.size[2]) + " at " + std::to_string(grid.origin[0]) + "," +
                   std::to_string(grid.origin[1]) + "," + std::to_string(grid.origin[2]) + ">";
        });

    py::class_<Program>(m, "Program", "A checked and compiled .vox file, or a compiled package.")
        .def(py::init<const py::object&, const std::optional<std::string>&, const std::optional<std::string>&,
                      const std::string&, std::optional<uint32_t>, std::optional<int32_t>,
                      const std::optional<std::map<std::string, double>>&, const py::object&>(),
             py::arg("source") = py::none(), py::kw_only(), py::arg("text") = py::none(), py::arg("package") = py::none(),
             py::arg("name") = "<text>.vox", py::arg("seed") = py::none(), py::arg("chunk") = py::none(),
             py::arg("overrides") = py::none(), py::arg("progress") = py::none())
        .def_property_readonly("size", [](const Program& p) { return tupleOf(p.size); }, "The world's grid: voxels per axis (x, y, z).")
        .def_property_readonly("origin", [](const Program& p) { return tupleOf(p.origin); },
                               "World coordinate of the grid's voxel (0, 0, 0).")
        .def_property_readonly("materials", &Program::materials, "{id: name} of the file's materials.")
        .def_property_readonly("material_colors", &Program::materialColors,
                               "{id: (r, g, b)}: each material's colour as the file declares it, linear RGB in [0, 1].")
        .def_property_readonly("pipeline_counts", &Program::pipelineCounts,
                               "(created, shared): the Vulkan kernel pipelines its generations compiled and reused.")
        .def("run", &Program::run, py::arg("region") = py::none(), py::arg("device") = "auto",
             py::arg("progress") = py::none(),
             "Generates the grid (or the box region = ((x0, y0, z0), (x1, y1, z1)), world coordinates, max excluded).")
        .def(
            "mesh",
            [](const Program& program, const std::optional<std::pair<std::array<int32_t, 3>, std::array<int32_t, 3>>>& region,
               const std::string& device, float iso, const py::object& lod, const py::object& progress) {
                const Grid grid = program.run(region, device, progress);
                return meshResult(grid.meshLevels(iso, levelsOf(lod), progress), lod);
            },
            py::arg("region") = py::none(), py::arg("device") = "auto", py::arg("iso") = 0.5f, py::arg("lod") = 0,
            py::arg("progress") = py::none(), "run(region, device) then Grid.mesh(iso, lod).");

    m.def("check", &check, py::arg("source") = py::none(), py::kw_only(), py::arg("text") = py::none(),
          py::arg("name") = "<text>.vox", py::arg("seed") = py::none(), py::arg("overrides") = py::none(),
          "Checks a .vox file or text and returns its diagnostics; raises nothing for the file's own errors.");
}
