#include "voxc/codegen/Template.h"

#include "voxc/core/Errors.h"
#include "voxc/shaders/ShaderSources.h"

#include <set>

namespace voxc::codegen {

namespace {

struct Expansion {
    const TemplateSections& sections;
    std::set<std::string, std::less<>> included;
    std::set<std::string, std::less<>> used;
    std::string out;
};

std::string_view trimLeft(std::string_view s) {
    const size_t first = s.find_first_not_of(" \t");
    return first == std::string_view::npos ? std::string_view{} : s.substr(first);
}

void expandText(Expansion& e, std::string_view file, std::string_view source, int depth);

void includeOnce(Expansion& e, std::string_view name, int depth) {
    if (!e.included.insert(std::string(name)).second) return;
    e.out += "// ---- begin " + std::string(name) + " ----\n";
    expandText(e, name, shaderSource(name), depth);
    e.out += "// ---- end " + std::string(name) + " ----\n";
}

// A generated section: its `#include` lines paste templates like the template's own (each file
// once per kernel); nothing else in it is interpreted.
void expandSection(Expansion& e, std::string_view text, int depth) {
    size_t pos = 0;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        const std::string_view body = trimLeft(line);
        if (body.starts_with("#include \"") && body.ends_with("\"")) {
            includeOnce(e, body.substr(10, body.size() - 11), depth + 1);
        } else {
            e.out.append(line).append("\n");
        }
    }
}

void expandText(Expansion& e, std::string_view file, std::string_view source, int depth) {
    size_t pos = 0;
    while (pos < source.size()) {
        size_t end = source.find('\n', pos);
        if (end == std::string_view::npos) end = source.size();
        const std::string_view line = source.substr(pos, end - pos);
        pos = end + 1;
        const std::string_view body = trimLeft(line);
        const std::string_view indent = line.substr(0, line.size() - body.size());
        if (body.starts_with("#include \"") && body.ends_with("\"")) {
            includeOnce(e, body.substr(10, body.size() - 11), depth + 1);
        } else if (depth > 0 && body.starts_with("#version")) {
            throw InternalError(std::string(file) + ": an included template may not declare #version");
        } else if (body.starts_with("// <<") && body.ends_with(">>")) {
            const std::string_view name = body.substr(5, body.size() - 7);
            const auto it = e.sections.find(name);
            if (it == e.sections.end())
                throw InternalError(std::string(file) + ": no section for marker " + std::string(name));
            if (!e.used.insert(it->first).second)
                throw InternalError(std::string(file) + ": marker " + std::string(name) + " appears twice");
            expandSection(e, prefixLines(it->second, indent), depth);
        } else {
            e.out.append(line).append("\n");
        }
    }
}

} // namespace

std::string prefixLines(std::string_view text, std::string_view prefix) {
    std::string_view bare = prefix.substr(0, prefix.find_last_not_of(' ') + 1);
    std::string out;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = text.substr(pos, end - pos);
        out.append(line.empty() ? bare : prefix).append(line).append("\n");
        pos = end + 1;
    }
    return out;
}

std::string instantiateTemplate(std::string_view templateFile, const TemplateSections& sections) {
    Expansion e{sections, {std::string(templateFile)}, {}, {}};
    expandText(e, templateFile, shaderSource(templateFile), 0);
    for (const auto& [name, text] : sections)
        if (!e.used.contains(name))
            throw InternalError(std::string(templateFile) + ": section " + name + " has no marker");
    return e.out;
}

} // namespace voxc::codegen
