#include "LanguageHelp.h"

#include "voxc/builtins/Functions.h"
#include "voxc/builtins/Ops.h"
#include "voxc/builtins/Shapes.h"
#include "voxc/generators/dey/Generators.h"

#include <fmt/format.h>

namespace voxc::lsp {

namespace {

std::string number(double v) { return fmt::format("{}", v); }

std::string range(double min, double max) { return fmt::format("[{}, {}]", number(min), number(max)); }

const char* shapeKeyType(KeyType type) {
    switch (type) {
    case KeyType::Number: return "number";
    case KeyType::Integer: return "integer";
    case KeyType::Vec3: return "[x, y, z]";
    case KeyType::Axis: return "axis (x, y or z)";
    }
    return "value";
}

const char* generatorKeyType(dey::GeneratorKeyType type) {
    switch (type) {
    case dey::GeneratorKeyType::Number: return "number";
    case dey::GeneratorKeyType::Integer: return "integer";
    case dey::GeneratorKeyType::Vec3: return "[x, y, z]";
    }
    return "value";
}

WordHelp shapeKeyHelp(const ShapeInfo& shape, const KeySpec& key) {
    std::string detail = fmt::format("{} key of the `{}` shape", shapeKeyType(key.type), shape.name);
    std::string doc = fmt::format("`{} = ...;` {}", key.name, shapeKeyType(key.type));
    if (key.type != KeyType::Axis) doc += fmt::format(" in {}", range(key.min, key.max));
    doc += key.required ? ", required" : ", optional";
    return {std::string(key.name), WordKind::Property, std::move(detail), std::move(doc)};
}

WordHelp generatorKeyHelp(const dey::GeneratorInfo& generator, const dey::GeneratorKey& key) {
    std::string detail = fmt::format("{} key of the `{}` generator", generatorKeyType(key.type), generator.name);
    std::string doc = fmt::format("`{} = ...;` {} in {}", key.name, generatorKeyType(key.type), range(key.min, key.max));
    if (key.step > 0) doc += fmt::format(", sampled every {} from {} (W0205 otherwise)", number(key.step), number(key.min));
    if (key.required)
        doc += ", required";
    else if (key.override)
        doc += ", no default: replaces a shared key for one end";
    else if (key.type == dey::GeneratorKeyType::Vec3)
        doc += fmt::format(", default [{}, {}, {}]", number(key.value[0]), number(key.value[1]), number(key.value[2]));
    else
        doc += fmt::format(", default {}", number(key.value[0]));
    return {std::string(key.name), WordKind::Property, std::move(detail), std::move(doc)};
}

std::vector<WordHelp> collectBuiltins() {
    std::vector<WordHelp> words;
    for (const FunctionInfo& function : functions())
        words.push_back({std::string(function.name), WordKind::Function, std::string(function.signature),
                         fmt::format("```\n{}\n```\n{}", function.signature, function.doc)});
    for (const SymbolOpInfo& op : symbolOps())
        words.push_back({std::string(op.name), WordKind::Operator,
                         op.takesValue ? "symbol operator, takes a value" : "symbol operator", std::string(op.doc)});
    for (const TransformOpInfo& op : transformOps())
        words.push_back({std::string(op.name), WordKind::Operator,
                         op.takesValue ? "transform operator, takes a value" : "transform operator", std::string(op.doc)});
    for (const MaterialOpInfo& op : materialOps())
        words.push_back({std::string(op.name), WordKind::Operator, "material operator, takes a material name",
                         std::string(op.doc)});
    for (const ShapeInfo& shape : shapes()) {
        std::string doc = fmt::format("start shape `{} {{ ... }}`; keys:", shape.name);
        for (const KeySpec& key : shape.keys) doc += "\n- " + shapeKeyHelp(shape, key).documentation;
        words.push_back({std::string(shape.name), WordKind::Class, "start shape", std::move(doc)});
    }
    for (const dey::GeneratorInfo& generator : dey::generators()) {
        std::string doc = fmt::format("generator `feature NAME = {} {{ ... }}`; keys:", generator.name);
        for (const dey::GeneratorKey& key : generator.keys) doc += "\n- " + generatorKeyHelp(generator, key).documentation;
        words.push_back({std::string(generator.name), WordKind::Class, "feature generator", std::move(doc)});
    }
    return words;
}

} // namespace

const std::vector<WordHelp>& builtinWords() {
    static const std::vector<WordHelp> words = collectBuiltins();
    return words;
}

std::optional<WordHelp> findBuiltin(std::string_view word) {
    std::optional<WordHelp> found;
    for (const WordHelp& help : builtinWords()) {
        if (help.name != word) continue;
        if (!found) {
            found = help;
        } else if (found->documentation != help.documentation) {
            found->detail += "; " + help.detail;
            found->documentation += "\n\n" + help.documentation;
        }
    }
    return found;
}

std::vector<WordHelp> registryKeys(std::string_view blockKind) {
    std::vector<WordHelp> keys;
    if (const std::optional<ShapeKind> kind = findShape(blockKind)) {
        const ShapeInfo& shape = shapeInfo(*kind);
        for (const KeySpec& key : shape.keys) keys.push_back(shapeKeyHelp(shape, key));
    } else if (const dey::GeneratorInfo* generator = dey::findGenerator(blockKind)) {
        for (const dey::GeneratorKey& key : generator->keys) keys.push_back(generatorKeyHelp(*generator, key));
    }
    return keys;
}

} // namespace voxc::lsp
