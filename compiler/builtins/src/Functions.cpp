#include "voxc/builtins/Functions.h"

#include "functions/Records.h"

#include <vector>

namespace voxc {

std::string_view typeName(Type type) {
    switch (type) {
    case Type::Float: return "float";
    case Type::Int: return "int";
    case Type::Bool: return "bool";
    case Type::Vec2: return "vec2";
    case Type::Vec3: return "vec3";
    }
    return "?";
}

std::span<const FunctionInfo> functions() {
    static const std::vector<FunctionInfo> all = [] {
        std::vector<FunctionInfo> records;
        for (auto group : {function_records::mathFunctions(), function_records::noiseFunctions(),
                           function_records::operatorFunctions(), function_records::sdfFunctions()})
            records.insert(records.end(), group.begin(), group.end());
        return records;
    }();
    return all;
}

const FunctionInfo* findFunction(std::string_view name) {
    for (const FunctionInfo& f : functions())
        if (f.name == name) return &f;
    return nullptr;
}

namespace function_records {

std::string call(std::string_view function, std::span<const std::string> args) {
    std::string text(function);
    text += '(';
    for (size_t i = 0; i < args.size(); ++i) {
        if (i > 0) text += ", ";
        text += args[i];
    }
    return text + ')';
}

} // namespace function_records

} // namespace voxc
