#pragma once
// Every argument-type list a function record's type rule accepts (lists of up to five
// arguments over all types), so tests cover every overload without a hand-kept list.
#include "voxc/builtins/Functions.h"

#include <string>
#include <vector>

namespace voxc::test {

struct Overload {
    std::vector<Type> args;
    Type result;
};

inline std::vector<Overload> acceptedOverloads(const FunctionInfo& info) {
    constexpr Type kTypes[] = {Type::Float, Type::Int, Type::Bool, Type::Vec2, Type::Vec3};
    std::vector<Overload> out;
    std::vector<std::vector<Type>> level{{}};
    for (int arity = 0; arity <= 5; ++arity) {
        for (const std::vector<Type>& args : level)
            if (std::optional<Type> r = info.typeRule(args)) out.push_back({args, *r});
        std::vector<std::vector<Type>> next;
        for (const std::vector<Type>& args : level)
            for (Type t : kTypes) {
                next.push_back(args);
                next.back().push_back(t);
            }
        level = std::move(next);
    }
    return out;
}

inline std::string describe(const FunctionInfo& info, const std::vector<Type>& args) {
    std::string text = std::string(info.name) + "(";
    for (size_t i = 0; i < args.size(); ++i) text += (i ? ", " : "") + std::string(typeName(args[i]));
    return text + ")";
}

} // namespace voxc::test
