// `fn name(params) -> type = body;` and `field name = value;`
#include "FieldLowering.h"
#include "Sections.h"
#include "Suggest.h"

#include "voxc/builtins/Functions.h"

#include <algorithm>
#include <fmt/format.h>
#include <map>

namespace voxc::check {

namespace {

constexpr std::string_view kTypeNames[] = {"float", "int", "bool", "vec2", "vec3"};

bool checkType(Context& context, const std::string& name, SourceLoc loc) {
    if (parseTypeName(name)) return true;
    context.diagnostics.error("E0002", loc,
                              fmt::format("unknown type '{}'{}", name, suggestOrList(name, kTypeNames)));
    return false;
}

// Validates the declaration; true when its signature is usable.
bool checkSignature(Context& context, const ast::FunctionDecl& function) {
    // Parameters are looked up by scanning, and compared pairwise for duplicates below.
    if (function.parameters.size() > size_t(context.limits.maxParameters)) {
        context.diagnostics.error("E0012", function.loc,
                                  fmt::format("function '{}' has {} parameters, more than the limit of {}",
                                              function.name, function.parameters.size(),
                                              context.limits.maxParameters));
        return false;
    }
    bool ok = checkType(context, function.result, function.resultLoc);
    for (size_t i = 0; i < function.parameters.size(); ++i) {
        const ast::Parameter& parameter = function.parameters[i];
        ok = checkType(context, parameter.type, parameter.typeLoc) && ok;
        for (size_t j = 0; j < i; ++j)
            if (function.parameters[j].name == parameter.name)
                context.diagnostics.error("E0003", parameter.loc,
                                          fmt::format("a second parameter named '{}'", parameter.name),
                                          {{function.parameters[j].loc, "the first one is here"}});
    }
    return ok;
}

FunctionTable declareFunctions(Context& context, const ast::File& file) {
    FunctionTable table;
    for (const ast::FunctionDecl& function : file.functions) {
        if (findFunction(function.name)) {
            context.diagnostics.error("E0003", function.loc,
                                      fmt::format("'{}' is a builtin function; choose another name", function.name));
            continue;
        }
        auto [it, inserted] = table.emplace(function.name, &function);
        if (!inserted)
            context.diagnostics.error("E0003", function.loc,
                                      fmt::format("a function named '{}' already exists", function.name),
                                      {{it->second->loc, "first declared here"}});
    }
    return table;
}

void reportIfExhausted(Context& context, const FieldLowering& lowering, SourceLoc loc, const std::string& what) {
    if (!lowering.exhausted()) return;
    context.diagnostics.error("E0012", loc,
                              fmt::format("{} is too large to inline: lowering it visits more than {} expression "
                                          "nodes",
                                          what, context.limits.maxLoweringSteps));
}

// Type-checks a body once on its own, so errors surface even in functions no field calls;
// parameters are stand-in constants of their types in a scratch DAG.
void checkBody(Context& context, const FunctionTable& table, const ast::FunctionDecl& function) {
    FieldDag scratch;
    FieldLowering lowering(context, table, scratch);
    std::vector<Lowered> arguments;
    for (const ast::Parameter& parameter : function.parameters) {
        FieldNode standIn;
        standIn.type = *parseTypeName(parameter.type);
        arguments.push_back(Lowered::ofNode(scratch.add(standIn), standIn.type));
    }
    lowering.lowerFunctionBody(function, arguments);
    reportIfExhausted(context, lowering, function.loc, fmt::format("function '{}'", function.name));
}

// The longest chain of operands in `nodes` (operands precede their users).
uint32_t dagDepth(const std::vector<FieldNode>& nodes) {
    std::vector<uint32_t> depth(nodes.size(), 1);
    uint32_t deepest = 0;
    for (size_t i = 0; i < nodes.size(); ++i) {
        for (uint32_t operand : nodes[i].operands) depth[i] = std::max(depth[i], depth[operand] + 1);
        deepest = std::max(deepest, depth[i]);
    }
    return deepest;
}

// Every later pass walks a field's nodes; these bounds keep that work and any recursion small.
bool reportIfTooLarge(Context& context, const Field& field) {
    const Limits& limits = context.limits;
    if (field.nodes.size() > size_t(limits.maxFieldNodes)) {
        context.diagnostics.error("E0012", field.loc,
                                  fmt::format("field '{}' has {} nodes after inlining, more than the limit of {}",
                                              field.name, field.nodes.size(), limits.maxFieldNodes));
        return true;
    }
    if (uint32_t depth = dagDepth(field.nodes); depth > uint32_t(limits.maxFieldDepth)) {
        context.diagnostics.error("E0012", field.loc,
                                  fmt::format("field '{}' nests {} operations deep after inlining, more than the "
                                              "limit of {}",
                                              field.name, depth, limits.maxFieldDepth));
        return true;
    }
    return false;
}

} // namespace

std::vector<Field> checkFields(Context& context, const ast::File& file, const std::vector<std::string>& grammarNames) {
    const FunctionTable table = declareFunctions(context, file);
    for (const ast::FunctionDecl& function : file.functions) {
        auto declared = table.find(function.name);
        if (checkSignature(context, function) && declared != table.end() && declared->second == &function)
            checkBody(context, table, function);
    }

    std::vector<Field> fields;
    std::map<std::string, SourceLoc> names;
    for (const ast::FieldDecl& decl : file.fields) {
        auto [it, inserted] = names.emplace(decl.name, decl.loc);
        if (!inserted)
            context.diagnostics.error("E0003", decl.loc, fmt::format("a field named '{}' already exists", decl.name),
                                      {{it->second, "first declared here"}});
        else if (decl.name == "start" ||
                 std::find(grammarNames.begin(), grammarNames.end(), decl.name) != grammarNames.end())
            context.diagnostics.error("E0003", decl.loc,
                                      fmt::format("'{}' already names a pipeline stage (a grammar or 'start')",
                                                  decl.name));
        FieldDag dag;
        FieldLowering lowering(context, table, dag);
        Lowered value = lowering.lowerField(*decl.value);
        reportIfExhausted(context, lowering, decl.loc, fmt::format("field '{}'", decl.name));
        if (value.number) value = lowering.materialize(value, Type::Float, decl.value->loc);
        if (!value.ok) continue;
        if (value.type != Type::Float) {
            context.diagnostics.error("E0010", decl.value->loc,
                                      fmt::format("a field's value must be a float, but this is {}",
                                                  typeName(value.type)));
            continue;
        }
        Field field;
        field.name = decl.name;
        field.loc = decl.loc;
        field.nodes = dag.reachableFrom(value.node, field.root);
        if (reportIfTooLarge(context, field)) continue;
        fields.push_back(std::move(field));
    }
    return fields;
}

} // namespace voxc::check
