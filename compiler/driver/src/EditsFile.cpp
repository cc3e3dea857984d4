#include "EditsFile.h"
#include "Console.h"

#include "voxc/core/Errors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

namespace voxc::driver {

namespace {

// Line and column (1-based, counting bytes) of byte offsets, from the line starts found once:
// an edits file of kMaxEdits edits locates each in a binary search, not a scan from its start.
class OffsetLocator {
public:
    explicit OffsetLocator(const std::string& text) : size_(text.size()) {
        lineStarts_.push_back(0);
        for (size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') lineStarts_.push_back(i + 1);
    }
    SourceLoc operator()(size_t offset, uint32_t length = 1) const {
        offset = std::min(offset, size_);
        const size_t line = size_t(std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset) - lineStarts_.begin());
        return {uint32_t(line), uint32_t(offset - lineStarts_[line - 1] + 1), length};
    }

private:
    size_t size_;
    std::vector<size_t> lineStarts_;
};

// The voxels a brush's support box covers inside the grid (what applyBrush visits).
uint64_t clippedSupportVoxels(const Brush& brush, glm::ivec3 origin, glm::ivec3 size) {
    const glm::dvec3 reach(double(brush.radius) + 0.5 * double(brush.softness));
    const glm::dvec3 low = glm::max(glm::floor(glm::dvec3(brush.center) - reach), glm::dvec3(origin));
    const glm::dvec3 high = glm::min(glm::ceil(glm::dvec3(brush.center) + reach), glm::dvec3(origin + size - 1));
    const glm::dvec3 extent = glm::max(high - low + 1.0, glm::dvec3(0.0));
    return uint64_t(extent.x) * uint64_t(extent.y) * uint64_t(extent.z);
}

// Where each element of the top-level array starts, and where each of its keys does (the JSON is
// valid: the parser accepted it first), for diagnostics nlohmann's values cannot place.
struct ElementPlaces {
    size_t start = 0;
    std::map<std::string, size_t> keys;
};

std::vector<ElementPlaces> scanPlaces(const std::string& text) {
    std::vector<ElementPlaces> elements;
    int depth = 0;
    bool expectKey = false; // inside an element object, after '{' or ','
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '"') {
            const size_t start = i;
            std::string value;
            for (++i; i < text.size() && text[i] != '"'; ++i) {
                if (text[i] == '\\') ++i;
                else value += text[i];
            }
            if (depth == 2 && expectKey && !elements.empty()) elements.back().keys.emplace(value, start);
            expectKey = false;
            if (depth == 1) elements.push_back({start, {}});
            continue;
        }
        if (c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == ':') continue;
        if (depth == 1 && c != ',' && c != ']') elements.push_back({i, {}});
        if (c == '[' || c == '{') {
            ++depth;
            expectKey = c == '{' && depth == 2;
        } else if (c == ']' || c == '}') {
            --depth;
        } else if (c == ',') {
            expectKey = depth == 2;
        }
        // Skip the rest of a number or literal so it is not taken for another element.
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '-')
            while (i + 1 < text.size() && std::string_view(",]} \n\r\t").find(text[i + 1]) == std::string_view::npos) ++i;
    }
    return elements;
}

bool isFiniteNumber(const nlohmann::json& value) { return value.is_number() && std::isfinite(value.get<double>()); }

} // namespace

std::vector<Brush> parseEdits(const SourceFile& source, Diagnostics& diagnostics, const Program& program) {
    const std::vector<Material>& materials = program.materials;
    const std::string& text = source.text();
    const OffsetLocator locate(text);
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& error) {
        // error.byte counts from 1 and names the character that could not be read.
        std::string message = error.what();
        if (const size_t colon = message.rfind(": "); colon != std::string::npos) message = message.substr(colon + 2);
        diagnostics.error("E0001", locate(error.byte == 0 ? 0 : error.byte - 1),
                          "the edits file is not valid JSON: " + message);
        return {};
    } catch (const nlohmann::json::out_of_range& error) {
        // A number past a double's range ("1e400"): the parser names its text, not its place.
        std::string number;
        if (const size_t open = std::string_view(error.what()).find('\''); open != std::string::npos)
            number = std::string(error.what()).substr(open + 1, std::string_view(error.what()).rfind('\'') - open - 1);
        const size_t at = number.empty() ? std::string::npos : text.find(number);
        diagnostics.error("E0007", locate(at == std::string::npos ? 0 : at, uint32_t(std::max<size_t>(number.size(), 1))),
                          fmt::format("the number {} is beyond the range of a double", number.empty() ? "in the file" : number));
        return {};
    }
    if (!document.is_array()) {
        diagnostics.error("E0010", locate(text.find_first_not_of(" \t\r\n")),
                          "an edits file is a JSON array of edits, e.g. [{\"op\": \"carve\", \"center\": [1, 2, 3], \"radius\": 4}]");
        return {};
    }
    std::vector<ElementPlaces> places = scanPlaces(text);
    places.resize(std::max(places.size(), document.size())); // the scan sees every element; never index past it
    if (document.size() > kMaxEdits) {
        diagnostics.error("E0012", locate(places[kMaxEdits].start),
                          fmt::format("{} edits: at most {} per file", document.size(), kMaxEdits));
        return {};
    }
    std::vector<Brush> edits;
    uint64_t work = 0; // voxels the brushes' support boxes cover in the world's grid, so far
    for (size_t i = 0; i < document.size(); ++i) {
        const nlohmann::json& edit = document[i];
        const ElementPlaces& place = places[i];
        const SourceLoc at = locate(place.start);
        const auto keyAt = [&](const std::string& key) {
            const auto found = place.keys.find(key);
            return found == place.keys.end() ? at : locate(found->second, uint32_t(key.size() + 2));
        };
        const std::string name = fmt::format("edit {}", i + 1);
        if (!edit.is_object()) {
            diagnostics.error("E0010", at, name + ": an edit is an object {\"op\", \"center\", \"radius\", \"softness\"}");
            continue;
        }
        bool ok = true;
        for (const auto& [key, value] : edit.items())
            if (key != "op" && key != "center" && key != "radius" && key != "softness" && key != "material") {
                diagnostics.error("E0008", keyAt(key),
                                  fmt::format("{}: unknown key '{}' (keys: op, center, radius, softness, material)", name, key));
                ok = false;
            }
        for (const char* key : {"op", "center", "radius"})
            if (!edit.contains(key)) {
                diagnostics.error("E0009", at, fmt::format("{}: missing key '{}'", name, key));
                ok = false;
            }
        if (!ok) continue;
        Brush brush;
        const nlohmann::json& op = edit["op"];
        if (!op.is_string()) {
            diagnostics.error("E0010", keyAt("op"), name + ": 'op' must be the string \"carve\" or \"add\"");
            ok = false;
        } else if (op == "carve" || op == "add") {
            brush.op = op == "carve" ? Brush::Op::Carve : Brush::Op::Add;
        } else {
            diagnostics.error("E0011", keyAt("op"), fmt::format("{}: unknown op '{}' (carve or add)", name, op.get<std::string>()));
            ok = false;
        }
        const nlohmann::json& center = edit["center"];
        if (!center.is_array() || center.size() != 3 || !std::all_of(center.begin(), center.end(), isFiniteNumber)) {
            diagnostics.error("E0010", keyAt("center"), name + ": 'center' must be three numbers [x, y, z] (world voxels)");
            ok = false;
        } else {
            for (int axis = 0; axis < 3; ++axis) brush.center[axis] = center[size_t(axis)].get<float>();
            if (glm::any(glm::greaterThan(glm::abs(brush.center), glm::vec3(kMaxBrushCoordinate)))) {
                diagnostics.error("E0007", keyAt("center"), fmt::format("{}: 'center' beyond +-{}", name, kMaxBrushCoordinate));
                ok = false;
            }
        }
        const auto number = [&](const char* key, float& out, float max) {
            if (!edit.contains(key)) return;
            if (!isFiniteNumber(edit[key])) {
                diagnostics.error("E0010", keyAt(key), fmt::format("{}: '{}' must be a number", name, key));
                ok = false;
                return;
            }
            out = edit[key].get<float>();
            if (!(out > 0.0f && out <= max)) {
                diagnostics.error("E0007", keyAt(key), fmt::format("{}: '{}' {} is outside (0, {}]", name, key, edit[key].dump(), max));
                ok = false;
            }
        };
        number("radius", brush.radius, kMaxBrushRadius);
        number("softness", brush.softness, kMaxBrushSoftness);
        if (edit.contains("material")) {
            const nlohmann::json& material = edit["material"];
            const auto declared = material.is_string()
                                      ? std::find_if(materials.begin(), materials.end(),
                                                     [&](const Material& m) { return m.name == material.get<std::string>(); })
                                      : materials.end();
            if (!material.is_string() || brush.op != Brush::Op::Add) {
                diagnostics.error("E0010", keyAt("material"), name + ": 'material' is the name of a material, on an add");
                ok = false;
            } else if (declared == materials.end()) {
                std::string names;
                for (const Material& m : materials) names += (names.empty() ? "" : ", ") + m.name;
                diagnostics.error("E0002", keyAt("material"),
                                  fmt::format("{}: unknown material '{}' ({})", name, material.get<std::string>(),
                                              names.empty() ? "the program declares none" : "declared: " + names));
                ok = false;
            } else {
                brush.material = declared->id;
            }
        }
        if (!ok) continue;
        work += clippedSupportVoxels(brush, program.world.origin, program.world.size);
        if (work > kMaxEditVoxels) {
            diagnostics.error("E0012", at,
                              fmt::format("{}: the edits so far visit {} voxels of the grid, more than the limit of {} "
                                          "(the sum over edits of their support boxes clipped to the grid)",
                                          name, work, kMaxEditVoxels));
            return {};
        }
        edits.push_back(brush);
    }
    return edits;
}

std::vector<Brush> loadEdits(const std::string& path, const Program& program) {
    Diagnostics diagnostics;
    std::optional<SourceFile> source = loadSourceFile(path, diagnostics, kMaxEditsFileBytes);
    std::vector<Brush> edits;
    if (source && !reportIfNotText(*source, diagnostics)) edits = parseEdits(*source, diagnostics, program);
    const SourceFile& shown = source ? *source : SourceFile(path, "");
    const std::vector<Diagnostic> all = diagnostics.take();
    printDiagnostics(all, shown);
    failOnErrors(path, all);
    return edits;
}

void addEditsFlag(CLI::App& command, std::string& path) {
    command.add_option("--edits", path,
                       "A JSON edits file (sphere brushes: carve or add, center, radius, softness, material) replayed in order on "
                       "the generated grid, on the host, before meshing and writing");
}

size_t applyEdits(ChunkedGrid& grid, const std::vector<Brush>& edits) {
    size_t changed = 0;
    for (const Brush& brush : edits) changed += applyBrush(grid, brush).has_value();
    return changed;
}

size_t applyEdits(DenseGrid& grid, glm::ivec3 origin, const std::vector<Brush>& edits) {
    size_t changed = 0;
    for (const Brush& brush : edits) changed += applyBrush(grid, origin, brush).has_value();
    return changed;
}

std::string describeEdits(size_t applied, size_t changed) {
    if (applied == 0) return "";
    return fmt::format("edits: {} applied on the host, {} of them changed voxels\n", applied, changed);
}

} // namespace voxc::driver
