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

SourceLoc locate(const std::string& text, size_t offset, uint32_t length = 1) {
    offset = std::min(offset, text.size());
    uint32_t line = 1, column = 1;
    for (size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return {line, column, length};
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

std::vector<Brush> parseEdits(const SourceFile& source, Diagnostics& diagnostics, const std::vector<Material>& materials) {
    const std::string& text = source.text();
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& error) {
        // error.byte counts from 1 and names the character that could not be read.
        std::string message = error.what();
        if (const size_t colon = message.rfind(": "); colon != std::string::npos) message = message.substr(colon + 2);
        diagnostics.error("E0001", locate(text, error.byte == 0 ? 0 : error.byte - 1),
                          "the edits file is not valid JSON: " + message);
        return {};
    }
    if (!document.is_array()) {
        diagnostics.error("E0010", locate(text, text.find_first_not_of(" \t\r\n")),
                          "an edits file is a JSON array of edits, e.g. [{\"op\": \"carve\", \"center\": [1, 2, 3], \"radius\": 4}]");
        return {};
    }
    std::vector<ElementPlaces> places = scanPlaces(text);
    places.resize(std::max(places.size(), document.size())); // the scan sees every element; never index past it
    if (document.size() > kMaxEdits) {
        diagnostics.error("E0012", locate(text, places[kMaxEdits].start),
                          fmt::format("{} edits: at most {} per file", document.size(), kMaxEdits));
        return {};
    }
    std::vector<Brush> edits;
    for (size_t i = 0; i < document.size(); ++i) {
        const nlohmann::json& edit = document[i];
        const ElementPlaces& place = places[i];
        const SourceLoc at = locate(text, place.start);
        const auto keyAt = [&](const std::string& key) {
            const auto found = place.keys.find(key);
            return found == place.keys.end() ? at : locate(text, found->second, uint32_t(key.size() + 2));
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
        if (ok) edits.push_back(brush);
    }
    return edits;
}

std::vector<Brush> loadEdits(const std::string& path, const std::vector<Material>& materials) {
    Diagnostics diagnostics;
    std::optional<SourceFile> source = loadSourceFile(path, diagnostics);
    std::vector<Brush> edits;
    if (source && !reportIfNotText(*source, diagnostics)) edits = parseEdits(*source, diagnostics, materials);
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
