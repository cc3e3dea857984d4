#include "voxc/viewer/Script.h"

#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <sstream>

namespace voxc::viewer {

namespace {

struct Word {
    std::string text;
    SourceLoc loc;
};

std::vector<Word> splitWords(std::string_view line, uint32_t lineNumber) {
    std::vector<Word> words;
    size_t i = 0;
    while (i < line.size()) {
        if (line[i] == '#') break;
        if (line[i] == ' ' || line[i] == '\t' || line[i] == '\r') {
            ++i;
            continue;
        }
        const size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' && line[i] != '#') ++i;
        words.push_back({std::string(line.substr(start, i - start)), {lineNumber, uint32_t(start + 1), uint32_t(i - start)}});
    }
    return words;
}

std::optional<double> number(std::string_view text) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::optional<glm::vec3> point(std::string_view text) {
    glm::vec3 p;
    size_t start = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const size_t comma = axis < 2 ? text.find(',', start) : text.size();
        if (comma == std::string_view::npos) return std::nullopt;
        const std::optional<double> value = number(text.substr(start, comma - start));
        if (!value) return std::nullopt;
        p[axis] = float(*value);
        start = comma + 1;
    }
    return p;
}

struct Spec {
    const char* name;
    Action::Kind kind;
    int operands;
};

constexpr Spec kSpecs[] = {
    {"camera", Action::Kind::Camera, 1},        {"carve", Action::Kind::Carve, 2},
    {"add", Action::Kind::Add, 2},              {"carve-ray", Action::Kind::Carve, 2},
    {"add-ray", Action::Kind::Add, 2},          {"set", Action::Kind::Set, 2},
    {"undo", Action::Kind::Undo, 0},            {"redo", Action::Kind::Redo, 0},
    {"reload", Action::Kind::Reload, 0},        {"save-edits", Action::Kind::SaveEdits, 1},
    {"wait", Action::Kind::Wait, 1},            {"wait-change", Action::Kind::WaitChange, 1},
    {"wait-refined", Action::Kind::WaitRefined, 1},
    {"screenshot", Action::Kind::Screenshot, 1}, {"screenshot-window", Action::Kind::ScreenshotWindow, 1},
};

} // namespace

std::vector<Action> parseScript(const SourceFile& source, Diagnostics& diagnostics) {
    std::vector<Action> actions;
    for (uint32_t lineNumber = 1; lineNumber <= source.lineCount(); ++lineNumber) {
        const std::vector<Word> words = splitWords(source.line(lineNumber), lineNumber);
        if (words.empty()) continue;
        const Word& verb = words[0];
        const Spec* spec = nullptr;
        for (const Spec& candidate : kSpecs)
            if (verb.text == candidate.name) spec = &candidate;
        if (spec == nullptr) {
            std::string names;
            for (const Spec& candidate : kSpecs) names += fmt::format("{}{}", names.empty() ? "" : ", ", candidate.name);
            diagnostics.error("E0008", verb.loc, fmt::format("unknown action '{}' (actions: {})", verb.text, names));
            continue;
        }
        if (int(words.size()) - 1 != spec->operands) {
            diagnostics.error("E0006", verb.loc,
                              fmt::format("'{}' takes {} operand{}, not {}", verb.text, spec->operands,
                                          spec->operands == 1 ? "" : "s", words.size() - 1));
            continue;
        }
        Action action{spec->kind, verb.loc};
        const auto needNumber = [&](const Word& word, double& out) {
            const std::optional<double> value = number(word.text);
            if (!value) diagnostics.error("E0010", word.loc, fmt::format("'{}' is not a number", word.text));
            else out = *value;
            return value.has_value();
        };
        bool ok = true;
        switch (spec->kind) {
        case Action::Kind::Camera:
        case Action::Kind::SaveEdits:
        case Action::Kind::Screenshot:
        case Action::Kind::ScreenshotWindow: action.text = words[1].text; break;
        case Action::Kind::Set:
            action.text = words[1].text;
            ok = needNumber(words[2], action.value);
            break;
        case Action::Kind::Wait:
        case Action::Kind::WaitChange:
        case Action::Kind::WaitRefined:
            ok = needNumber(words[1], action.value);
            if (ok && !(action.value >= 0 && action.value <= kMaxScriptWaitSeconds)) {
                diagnostics.error("E0007", words[1].loc,
                                  fmt::format("{} seconds: expected 0 to {}", words[1].text, kMaxScriptWaitSeconds));
                ok = false;
            }
            break;
        case Action::Kind::Carve:
        case Action::Kind::Add:
            action.alongRay = verb.text.ends_with("-ray");
            if (action.alongRay) {
                const std::optional<glm::vec3> origin = point(words[1].text), direction = point(words[2].text);
                if (!origin) diagnostics.error("E0010", words[1].loc, fmt::format("'{}' is not a point X,Y,Z", words[1].text));
                if (!direction) diagnostics.error("E0010", words[2].loc, fmt::format("'{}' is not a direction DX,DY,DZ", words[2].text));
                ok = origin && direction;
                if (ok) action.origin = *origin, action.direction = *direction;
            } else {
                double x = 0, y = 0;
                ok = needNumber(words[1], x) && needNumber(words[2], y);
                action.pixel = {float(x), float(y)};
            }
            break;
        default: break;
        }
        if (ok) actions.push_back(std::move(action));
    }
    return actions;
}

} // namespace voxc::viewer
