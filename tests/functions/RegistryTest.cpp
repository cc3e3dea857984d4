// Every record of voxc::functions(): unique names, complete backends, existing GLSL libraries,
// and a type rule that accepts its documented signature(s) and rejects wrong argument lists.
#include "Signatures.h"

#include "voxc/builtins/Functions.h"
#include "voxc/shaders/ShaderSources.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace voxc {
namespace registry_test {

Type parseType(std::string text) {
    // Generic signatures name a placeholder; its first instance is checked.
    if (text == "T") text = "float";
    if (text == "V") text = "vec2";
    for (Type t : {Type::Float, Type::Int, Type::Bool, Type::Vec2, Type::Vec3})
        if (typeName(t) == text) return t;
    throw std::runtime_error("unknown type in signature: " + text);
}

std::string trim(const std::string& s) {
    const size_t b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// The overloads a signature spells out: "f(a: T, b: float) -> T; f(...) -> float; T = ..." .
std::vector<test::Overload> documentedOverloads(const FunctionInfo& info) {
    std::vector<test::Overload> out;
    const std::string signature(info.signature);
    size_t start = 0;
    while (start < signature.size()) {
        size_t end = signature.find("; ", start);
        if (end == std::string::npos) end = signature.size();
        const std::string part = signature.substr(start, end - start);
        start = end + 2;
        if (part.rfind(std::string(info.name) + "(", 0) != 0) continue; // a note, not an overload
        test::Overload o;
        const size_t open = part.find('('), close = part.find(')'), arrow = part.find("->");
        std::string params = part.substr(open + 1, close - open - 1);
        size_t p = 0;
        while (!params.empty() && p != std::string::npos) {
            const size_t comma = params.find(',', p);
            const std::string param = params.substr(p, comma == std::string::npos ? std::string::npos : comma - p);
            o.args.push_back(parseType(trim(param.substr(param.find(':') + 1))));
            p = comma == std::string::npos ? comma : comma + 1;
        }
        o.result = parseType(trim(part.substr(arrow + 2)));
        out.push_back(o);
    }
    return out;
}

TEST(functions_Registry, EveryRecordIsCompleteAndUnique) {
    std::set<std::string_view> names;
    const std::vector<std::string_view> shaders = shaderFileNames();
    ASSERT_GE(functions().size(), 29u);
    for (const FunctionInfo& f : functions()) {
        EXPECT_TRUE(names.insert(f.name).second) << "duplicate " << f.name;
        EXPECT_EQ(findFunction(f.name), &f);
        EXPECT_FALSE(f.doc.empty()) << f.name;
        EXPECT_NE(f.typeRule, nullptr) << f.name;
        EXPECT_NE(f.eval, nullptr) << f.name;
        EXPECT_NE(f.glsl, nullptr) << f.name;
        EXPECT_GE(f.tolerance, 0.0f) << f.name;
        for (std::string_view library : f.glslLibraries)
            EXPECT_NE(std::find(shaders.begin(), shaders.end(), library), shaders.end()) << f.name << ": " << library;
    }
    EXPECT_EQ(findFunction("no_such_function"), nullptr);
}

TEST(functions_Registry, TypeRulesAcceptTheDocumentedSignaturesAndRejectOthers) {
    for (const FunctionInfo& f : functions()) {
        const std::vector<test::Overload> documented = documentedOverloads(f);
        ASSERT_FALSE(documented.empty()) << f.name << ": signature names no overload: " << f.signature;
        for (const test::Overload& o : documented) {
            EXPECT_EQ(f.typeRule(o.args), o.result) << test::describe(f, o.args);
            std::vector<Type> extra = o.args;
            extra.push_back(Type::Bool);
            EXPECT_EQ(f.typeRule(extra), std::nullopt) << test::describe(f, extra);
            if (!o.args.empty()) {
                std::vector<Type> wrong = o.args;
                wrong[0] = o.args[0] == Type::Bool ? Type::Vec3 : Type::Bool;
                EXPECT_EQ(f.typeRule(wrong), std::nullopt) << test::describe(f, wrong);
            }
        }
        // Every accepted overload emits GLSL and evaluates to its declared type.
        for (const test::Overload& o : test::acceptedOverloads(f)) {
            std::vector<std::string> names;
            std::vector<Value> values;
            for (size_t i = 0; i < o.args.size(); ++i) {
                names.push_back("a" + std::to_string(i));
                Value v;
                v.type = o.args[i];
                v.v = glm::vec3(0.5f, 1.5f, 2.5f);
                v.i = 3;
                values.push_back(v);
            }
            EXPECT_FALSE(f.glsl(names, o.args).empty()) << test::describe(f, o.args);
            EXPECT_EQ(f.eval(values).type, o.result) << test::describe(f, o.args);
        }
    }
}

TEST(functions_Registry, TypeNames) {
    EXPECT_EQ(typeName(Type::Float), "float");
    EXPECT_EQ(typeName(Type::Int), "int");
    EXPECT_EQ(typeName(Type::Bool), "bool");
    EXPECT_EQ(typeName(Type::Vec2), "vec2");
    EXPECT_EQ(typeName(Type::Vec3), "vec3");
}

} // namespace registry_test
} // namespace voxc
