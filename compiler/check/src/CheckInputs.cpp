#include "CheckInputs.h"

#include "Values.h"

#include "voxc/builtins/Functions.h"
#include "voxc/core/InputFile.h"
#include "voxc/generators/inputs/HeightImage.h"
#include "voxc/generators/inputs/MeshDistance.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace voxc::check {

namespace {

constexpr std::string_view kHeightmapKeys[] = {"file", "origin", "size", "height", "values"};
constexpr std::string_view kMeshKeys[] = {"file", "translate", "rotate", "scale", "band"};

inputs::Limits inputLimits(const Limits& limits) {
    inputs::Limits out;
    out.maxPixels = limits.maxImagePixels;
    out.maxTriangles = limits.maxMeshTriangles;
    out.maxPoints = limits.maxMeshPoints;
    out.maxDistanceCells = limits.maxDistanceCells;
    return out;
}

// `[a, b]` of two numbers within ±kMaxCoordinate.
std::optional<std::array<double, 2>> readTwo(Context& context, const ast::Assignment& a, double lo, double hi) {
    const ast::Value& value = a.value;
    if (!value.isList() || value.elements.size() != 2 || value.elements[0].isList() || value.elements[1].isList()) {
        context.diagnostics.error("E0010", value.loc, fmt::format("'{}' expects two numbers [a, b]", a.key));
        return std::nullopt;
    }
    std::array<double, 2> out{};
    for (size_t i = 0; i < 2; ++i) {
        const std::optional<double> v = context.constants.evaluate(*value.elements[i].scalar);
        if (!v) return std::nullopt;
        if (!(*v >= lo && *v <= hi)) {
            context.diagnostics.error("E0007", value.elements[i].loc,
                                      fmt::format("'{}' values must lie in [{}, {}]", a.key, lo, hi));
            return std::nullopt;
        }
        out[i] = *v;
    }
    return out;
}

class InputReader {
public:
    InputReader(Context& context, const std::string& sourcePath) : context_(context), sourcePath_(sourcePath) {}

    // `file = "..."`: the file's bytes, read relative to the .vox's folder, or a located error.
    std::optional<InputFile> read(const ast::Block& block, const ast::Assignment& a) {
        const ast::Expr* expr = a.value.isList() ? nullptr : a.value.scalar.get();
        if (!expr || expr->kind != ast::Expr::Kind::String) {
            context_.diagnostics.error("E0010", a.value.loc, "'file' expects a file name in double quotes");
            return std::nullopt;
        }
        InputFile input;
        input.block = *block.label;
        input.kind = block.kind;
        input.name = expr->name;
        input.loc = a.value.loc;
        const std::filesystem::path name(input.name);
        input.path = (std::filesystem::path(sourcePath_).parent_path() / name).string();
        const std::filesystem::path normal = name.lexically_normal();
        input.outside = name.is_absolute() || (!normal.empty() && *normal.begin() == "..");
        const size_t maxBytes = size_t(context_.limits.maxInputBytes);
        if (context_.readInputFile) {
            std::optional<std::string> bytes = context_.readInputFile(input.path);
            if (!bytes) {
                context_.diagnostics.error("E0100", a.value.loc, fmt::format("cannot read file '{}': no such file", input.path));
                return std::nullopt;
            }
            input.bytes = std::make_shared<const std::string>(std::move(*bytes));
        } else {
            // Only a regular file, at most the cap: the name is the document's, and a FIFO or
            // /dev/stdin would block the check (and, under `voxc lsp`, read the protocol stream).
            InputFileRead file = voxc::readInputFile(input.path, maxBytes);
            if (!file.bytes) {
                context_.diagnostics.error(std::string(file.code()), a.value.loc, file.message);
                return std::nullopt;
            }
            input.bytes = std::make_shared<const std::string>(std::move(*file.bytes));
        }
        if (input.bytes->size() > maxBytes) {
            context_.diagnostics.error("E0012", a.value.loc,
                                       fmt::format("cannot read file '{}': it is larger than the limit of {} bytes",
                                                   input.path, maxBytes));
            return std::nullopt;
        }
        return input;
    }

private:
    Context& context_;
    const std::string& sourcePath_;
};

// The map's cells count against what all input maps may upload together.
bool claimCells(Context& context, const ast::Block& block, const ast::Assignment& file, uint64_t cells,
                uint64_t& budget) {
    if (cells <= budget) {
        budget -= cells;
        return true;
    }
    context.diagnostics.error("E0012", file.value.loc,
                              fmt::format("{} '{}' needs {} map cells, past what is left of the {} all heightmap "
                                          "and mesh blocks may use",
                                          block.kind, *block.label, cells, context.limits.maxMapCells));
    return false;
}

std::shared_ptr<const SampledMap> checkHeightmap(Context& context, const ast::Block& block, const InputFile& input,
                                                 const ast::Assignment& fileKey, uint64_t& budget) {
    const BlockKeys keys(context, block, fmt::format("heightmap '{}'", *block.label), kHeightmapKeys);
    bool ok = true;
    std::array<double, 2> origin{0, 0};
    std::optional<std::array<double, 2>> size, height, values;
    if (const ast::Assignment* a = keys.find("origin")) {
        const auto v = readTwo(context, *a, -kMaxCoordinate, kMaxCoordinate);
        ok = ok && v;
        if (v) origin = *v;
    }
    if (const ast::Assignment* a = keys.find("size")) {
        size = readTwo(context, *a, 1e-3, kMaxCoordinate);
        ok = ok && size;
    }
    if (const ast::Assignment* a = keys.require("height")) {
        height = readTwo(context, *a, -kMaxCoordinate, kMaxCoordinate);
        ok = ok && height;
    } else {
        ok = false;
    }
    const ast::Assignment* valuesKey = keys.find("values");
    if (valuesKey) {
        values = readTwo(context, *valuesKey, -3.4e38, 3.4e38);
        if (values && (*values)[0] == (*values)[1]) {
            context.diagnostics.error("E0007", valuesKey->value.loc, "'values' needs two different numbers [a, b]");
            values.reset();
        }
        ok = ok && values;
    }
    if (!ok) return nullptr;
    inputs::HeightImage image;
    try {
        image = inputs::decodeHeightImage(*input.bytes, inputLimits(context.limits));
    } catch (const inputs::InputError& e) {
        context.diagnostics.error(e.code, fileKey.value.loc, fmt::format("heightmap '{}': {}: {}", *block.label, input.path, e.what()));
        return nullptr;
    }
    if (!claimCells(context, block, fileKey, uint64_t(image.width) * uint64_t(image.height), budget)) return nullptr;
    const std::array<double, 2> span = size.value_or(std::array<double, 2>{double(image.width), double(image.height)});
    const std::array<double, 2> raw = values.value_or(std::array<double, 2>{0.0, image.fullScale});
    auto map = std::make_shared<SampledMap>();
    map->name = *block.label;
    map->source = "heightmap";
    map->dimensions = 2;
    map->size = {image.width, 1, image.height};
    map->origin = {float(origin[0]), 0.0f, float(origin[1])};
    map->cellsPerVoxel = {float(double(image.width) / span[0]), 1.0f, float(double(image.height) / span[1])};
    // height = lo + (v - a) / (b - a) · (hi - lo), in double, once per pixel.
    const double scale = ((*height)[1] - (*height)[0]) / (raw[1] - raw[0]);
    map->values.reserve(image.values.size());
    for (float v : image.values) map->values.push_back(float((*height)[0] + (double(v) - raw[0]) * scale));
    for (size_t i = 0; i < map->values.size(); ++i)
        if (!std::isfinite(map->values[i])) {
            context.diagnostics.error("E0007", fileKey.value.loc,
                                      fmt::format("heightmap '{}': pixel ({}, {}) maps to a height beyond the float range",
                                                  *block.label, i % size_t(image.width), i / size_t(image.width)));
            return nullptr;
        }
    const auto [lowest, highest] = std::minmax_element(map->values.begin(), map->values.end());
    map->lowest = *lowest, map->highest = *highest;
    return map;
}

std::shared_ptr<const SampledMap> checkMesh(Context& context, const ast::Block& block, const InputFile& input,
                                            const ast::Assignment& fileKey, uint64_t& budget) {
    const BlockKeys keys(context, block, fmt::format("mesh '{}'", *block.label), kMeshKeys);
    bool ok = true;
    inputs::MeshTransform transform;
    double band = 4.0;
    if (const ast::Assignment* a = keys.find("translate")) {
        const auto v = readNumberVec3(context, *a, -kMaxCoordinate, kMaxCoordinate);
        ok = ok && v;
        if (v) transform.translate = {(*v)[0], (*v)[1], (*v)[2]};
    }
    if (const ast::Assignment* a = keys.find("rotate")) {
        const auto v = readNumberVec3(context, *a, -360.0, 360.0);
        ok = ok && v;
        if (v) transform.rotateDegrees = {(*v)[0], (*v)[1], (*v)[2]};
    }
    if (const ast::Assignment* a = keys.find("scale")) {
        const auto v = readNumber(context, *a, 1e-6, 1e6);
        ok = ok && v;
        if (v) transform.scale = *v;
    }
    if (const ast::Assignment* a = keys.find("band")) {
        const auto v = readNumber(context, *a, 1.0, 64.0);
        ok = ok && v;
        if (v) band = *v;
    }
    if (!ok) return nullptr;
    const std::optional<inputs::MeshFormat> format = inputs::meshFormatOf(input.name);
    if (!format) {
        context.diagnostics.error("E0010", fileKey.value.loc,
                                  fmt::format("mesh '{}': '{}' is not a mesh file voxc reads (.glb, .gltf, .obj, .ply)",
                                              *block.label, input.name));
        return nullptr;
    }
    inputs::DistanceGrid grid;
    try {
        inputs::TriangleMesh mesh = inputs::decodeMesh(*input.bytes, *format, inputLimits(context.limits));
        grid = inputs::meshDistances(mesh, transform, float(band), inputLimits(context.limits));
        mesh.points = inputs::placePoints(mesh, transform);
        context.placedMeshes[*block.label] = std::make_shared<const inputs::TriangleMesh>(std::move(mesh));
    } catch (const inputs::InputError& e) {
        context.diagnostics.error(e.code, fileKey.value.loc, fmt::format("mesh '{}': {}: {}", *block.label, input.path, e.what()));
        return nullptr;
    }
    if (grid.openEdges > 0 || grid.nonManifoldEdges > 0)
        context.diagnostics.warning(
            "W0212", fileKey.value.loc,
            fmt::format("mesh '{}' is not a closed surface ({} edges border one triangle, {} more than two): the sign "
                        "around a hole is whatever OpenVDB's fill carries through it; close the mesh to be sure of "
                        "its inside (docs/language.md, \"Meshes\")",
                        *block.label, grid.openEdges, grid.nonManifoldEdges));
    if (grid.crossingPairs > 0)
        context.diagnostics.warning(
            "W0214", fileKey.value.loc,
            fmt::format("mesh '{}' intersects itself: {} pair{} of triangles cross (the first: triangles {} and {}); "
                        "{}(p) is the union of the solids it encloses, as OpenVDB's sign rule reads it (docs/language.md, "
                        "\"Meshes\")",
                        *block.label, grid.crossingPairs, grid.crossingPairs == 1 ? "" : "s", grid.firstCrossing.first,
                        grid.firstCrossing.second, *block.label));
    if (grid.insideOutParts > 0)
        context.diagnostics.warning(
            "W0213", fileKey.value.loc,
            fmt::format("mesh '{}' is inside out: {} closed part{} wound clockwise seen from outside (signed volume "
                        "-{:.6g} cubic voxels); {}(p) does not depend on the winding, but a curves block taking it as "
                        "an input puts the air on the side its faces point to, inside it; reverse the faces' winding "
                        "(docs/language.md, \"Meshes\")",
                        *block.label, grid.insideOutParts, grid.insideOutParts == 1 ? " is" : "s are",
                        grid.insideOutVolume, *block.label));
    if (!claimCells(context, block, fileKey, uint64_t(grid.values.size()), budget)) return nullptr;
    auto map = std::make_shared<SampledMap>();
    map->name = *block.label;
    map->source = "mesh";
    map->dimensions = 3;
    map->size = grid.size;
    // Cell (i, j, k) is world voxel min + (i, j, k): its centre sits half a cell past the corner.
    map->origin = glm::vec3(grid.min) - 0.5f;
    map->cellsPerVoxel = glm::vec3(1.0f);
    map->values = std::move(grid.values);
    const auto [lowest, highest] = std::minmax_element(map->values.begin(), map->values.end());
    map->lowest = *lowest, map->highest = *highest;
    return map;
}

} // namespace

std::vector<InputFile> checkInputs(Context& context, const ast::File& file, const std::string& sourcePath) {
    std::vector<InputFile> files;
    InputReader reader(context, sourcePath);
    uint64_t budget = uint64_t(context.limits.maxMapCells);
    for (const ast::Block& block : file.blocks) {
        if (block.kind != "heightmap" && block.kind != "mesh") continue;
        if (!checkLabel(context, block, true) || !block.label) continue;
        if (context.maps.contains(*block.label) || findFunction(*block.label)) {
            context.diagnostics.error("E0003", block.labelLoc,
                                      fmt::format("'{}' is already the name of a {}", *block.label,
                                                  context.maps.contains(*block.label) ? "heightmap or mesh"
                                                                                      : "builtin function"));
            continue;
        }
        context.maps[*block.label] = nullptr; // until its map is made
        rejectUnexpectedMembers(context, block, fmt::format("{} '{}'", block.kind, *block.label), Allowed{});
        const ast::Assignment* fileKey = nullptr;
        for (const ast::Assignment& a : block.assignments)
            if (a.key == "file" && !fileKey) fileKey = &a;
        if (!fileKey) {
            context.diagnostics.error("E0009", block.loc,
                                      fmt::format("{} '{}' needs 'file = \"...\";', the file to read", block.kind, *block.label));
            continue;
        }
        std::optional<InputFile> input = reader.read(block, *fileKey);
        if (!input) continue;
        context.maps[*block.label] = block.kind == "heightmap" ? checkHeightmap(context, block, *input, *fileKey, budget)
                                                               : checkMesh(context, block, *input, *fileKey, budget);
        files.push_back(std::move(*input));
    }
    return files;
}

} // namespace voxc::check
