#include "voxc/builtins/Functions.h"
#include "voxc/builtins/Ops.h"
#include "voxc/builtins/Shapes.h"
#include "voxc/ir/Ir.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace voxc::ir {

namespace {

std::string loc(const SourceLoc& l) { return fmt::format("{}:{}", l.line, l.column); }

const char* aggregateName(AggregateKind kind) {
    switch (kind) {
    case AggregateKind::Mean: return "mean";
    case AggregateKind::Min: return "min";
    case AggregateKind::Max: return "max";
    case AggregateKind::SolidFraction: return "solid_fraction";
    case AggregateKind::MaterialFraction: return "material_fraction";
    }
    return "?";
}

const char* accessName(CellAccess access) {
    switch (access) {
    case CellAccess::None: return "none";
    case CellAccess::Address: return "address";
    case CellAccess::Load: return "load";
    }
    return "?";
}

void printRule(std::string& out, const IrSweep& sweep, const IrRule& rule) {
    out += fmt::format("    rule {} {} ({}) priority {} weight {} probability {}\n", rule.ruleIndex, rule.name,
                       loc(rule.loc), rule.priority, rule.weightUnits, rule.probabilityUnits);
    std::string symbol, transform, needs;
    for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
        const std::string at = printCell(sweep.cells[c].offset);
        std::string predicates;
        for (const Predicate& p : rule.symbol[c].predicates) {
            if (p.op == SymbolOp::IGN) continue;
            predicates += (predicates.empty() ? "" : " & ") + printPredicate(p);
        }
        for (const MaterialPredicate& p : rule.symbol[c].materialPredicates)
            predicates += (predicates.empty() ? "" : " & ") + printMaterialPredicate(p);
        if (!predicates.empty()) symbol += fmt::format("{}{} {}", symbol.empty() ? "" : " | ", at, predicates);
        if (transformOpInfo(rule.transform[c].op).writes || rule.transform[c].material)
            transform += fmt::format("{}{} {}", transform.empty() ? "" : " | ", at, printTransform(rule.transform[c]));
        if (!rule.needs.empty() && !rule.needs[c].empty())
            needs += fmt::format("{}cell {} {{{}}}", needs.empty() ? "" : ", ", c, fmt::join(rule.needs[c], ", "));
    }
    out += fmt::format("      symbol {}\n", symbol.empty() ? "(matches everywhere)" : symbol);
    out += fmt::format("      transform {}\n", transform.empty() ? "(writes nothing)" : transform);
    for (const AggregateTest& test : rule.aggregates) out += fmt::format("      where {}\n", printAggregate(test));
    for (const Stamp& stamp : rule.stamps)
        out += fmt::format("      stamp {} {} reach {}\n", fieldModeName(stamp.mode), stamp.fieldName, printVec(stamp.reach));
    if (!rule.needs.empty()) out += fmt::format("      needs {}\n", needs.empty() ? "(nothing)" : needs);
}

void printSweep(std::string& out, const IrSweep& sweep) {
    out += fmt::format("  sweep {} window {} anchors {} phases {}\n", sweep.index, printVec(sweep.window),
                       printVec(sweep.anchorCount), printVec(sweep.phaseCount));
    for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
        const IrCell& cell = sweep.cells[c];
        out += fmt::format("    cell {} {} {}", c, printCell(cell.offset), accessName(cell.access));
        if (cell.loadsMaterial) out += " material";
        if (testCount(cell) != 0) {
            out += " tests";
            for (uint32_t b = 0; b < cell.tests.size(); ++b)
                out += fmt::format(" {}:{}", b, printPredicate(cell.tests[b]));
            for (uint32_t m = 0; m < cell.materialTests.size(); ++m)
                out += fmt::format(" {}:{}", cell.tests.size() + m, printMaterialPredicate(cell.materialTests[m]));
        }
        out += "\n";
    }
    for (const IrRule& rule : sweep.rules)
        printRule(out, sweep, rule);
    for (const IrRemovedRule& removed : sweep.removed)
        out += fmt::format("    removed rule {} {} ({}): cell {} passes no density\n", removed.ruleIndex, removed.name,
                           loc(removed.loc), removed.cell);
}

const char* inputName(FieldInput input) {
    static const char* const names[] = {"x", "y", "z", "wx", "wy", "wz"};
    return names[int(input)];
}

std::string printConstant(const FieldNode& node) {
    switch (node.type) {
    case Type::Float: return glslFloat(node.constant.x);
    case Type::Int: return std::to_string(node.constantInt);
    case Type::Bool: return node.constantBool ? "true" : "false";
    case Type::Vec2: return fmt::format("vec2({}, {})", glslFloat(node.constant.x), glslFloat(node.constant.y));
    case Type::Vec3:
        return fmt::format("vec3({}, {}, {})", glslFloat(node.constant.x), glslFloat(node.constant.y),
                           glslFloat(node.constant.z));
    }
    return "?";
}

// One line per node: "%4 = call add(%2, %3) : float column".
void printField(std::string& out, const IrField& field) {
    out += fmt::format("field {} ({}) root %{}\n", field.name, loc(field.loc), field.root);
    for (uint32_t i = 0; i < field.nodes.size(); ++i) {
        const FieldNode& node = field.nodes[i];
        std::string value;
        switch (node.kind) {
        case FieldNode::Kind::Constant: value = "const " + printConstant(node); break;
        case FieldNode::Kind::Input: value = fmt::format("input {}", inputName(node.input)); break;
        case FieldNode::Kind::Component: value = fmt::format("%{}.{}", node.operands[0], "xyz"[node.component]); break;
        case FieldNode::Kind::PointSet:
            value = fmt::format("point_set_distances(%{}) {} centres, {} segments", node.operands[0],
                                node.pointSet->centres.size(), node.pointSet->segments.size());
            break;
        case FieldNode::Kind::Map:
            value = node.map->dimensions == 2
                        ? fmt::format("map {}(%{}, %{}) {}x{} cells", node.map->name, node.operands[0],
                                      node.operands[1], node.map->size.x, node.map->size.z)
                        : fmt::format("volume {}(%{}, %{}, %{}) {}x{}x{} cells", node.map->name, node.operands[0],
                                      node.operands[1], node.operands[2], node.map->size.x, node.map->size.y,
                                      node.map->size.z);
            break;
        case FieldNode::Kind::Call: {
            std::vector<std::string> operands;
            for (uint32_t o : node.operands) operands.push_back(fmt::format("%{}", o));
            value = fmt::format("call {}({})", functions()[node.function].name, fmt::join(operands, ", "));
            break;
        }
        }
        const bool column = !field.perColumn.empty() && field.perColumn[i];
        out += fmt::format("  %{} = {} : {}{}\n", i, value, typeName(node.type), column ? " column" : "");
    }
}

} // namespace

std::string_view fieldModeName(FieldMode mode) {
    switch (mode) {
    case FieldMode::Set: return "set";
    case FieldMode::Union: return "union";
    case FieldMode::Subtract: return "subtract";
    case FieldMode::Intersect: return "intersect";
    case FieldMode::Paint: return "paint";
    }
    return "?";
}

std::string printStage(const Stage& stage) {
    return stage.material ? fmt::format("{} material {}", stage.label, *stage.material) : stage.label;
}

std::string printPredicate(const Predicate& p) {
    const SymbolOpInfo& info = symbolOpInfo(p.op);
    return info.takesValue ? fmt::format("{} {}", info.name, glslFloat(p.value)) : std::string(info.name);
}

std::string printAggregate(const AggregateTest& test) {
    const std::string box = fmt::format("{}..{}", printVec(test.boxMin), printVec(test.boxMax));
    switch (test.kind) {
    case AggregateKind::Mean:
        return fmt::format("mean over {}: sum in [{}, {}]", box, test.low, test.high);
    case AggregateKind::Min:
    case AggregateKind::Max:
        return fmt::format("{} over {} in [{}, {}]", aggregateName(test.kind), box, test.low, test.high);
    case AggregateKind::SolidFraction:
        return fmt::format("solid cells over {}: {} to {}", box, test.minCount, test.maxCount);
    case AggregateKind::MaterialFraction:
        return fmt::format("cells of material {} over {}: {} to {}", test.material, box, test.minCount, test.maxCount);
    }
    return "?";
}

std::string printMaterialPredicate(const MaterialPredicate& p) {
    return fmt::format("{} {}", materialOpInfo(p.op).name, p.material);
}

// `MAT m` alone when the density is left as it is, else the density operator first.
std::string printTransform(const TransformCell& t) {
    const TransformOpInfo& info = transformOpInfo(t.op);
    std::string density = info.takesValue ? fmt::format("{} {}", info.name, glslFloat(t.value)) : std::string(info.name);
    if (!t.material) return density;
    const std::string material = fmt::format("MAT {}", *t.material);
    return info.writes ? density + " & " + material : material;
}

std::string printCell(glm::ivec3 p) { return fmt::format("({}, {}, {})", p.x, p.y, p.z); }
std::string printVec(glm::ivec3 v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

glm::ivec3 cellOffset(glm::ivec3 window, uint32_t cell) {
    const int i = int(cell);
    return {i % window.x, (i / window.x) % window.y, i / (window.x * window.y)};
}

std::string printIr(const IrModule& module) {
    const World& w = module.world;
    std::string out = fmt::format("module \"{}\"\n", module.sourcePath);
    out += fmt::format("world size {} origin {} chunk {} seed {}\n", printVec(w.size), printVec(w.origin), w.chunkSize,
                       w.seed);
    out += "start\n";
    for (const StartShape& shape : module.start)
        out += fmt::format("  {} value {}{} ({})\n", shapeInfo(shape.kind).name, glslFloat(shape.value),
                           shape.material ? fmt::format(" material {}", *shape.material) : "", loc(shape.loc));
    out += "pipeline";
    for (const Stage& stage : module.pipeline)
        out += " " + printStage(stage);
    out += "\n";
    if (!module.deadStages.empty()) {
        out += "dead stages";
        for (const Stage& stage : module.deadStages)
            out += " " + printStage(stage);
        out += "\n";
    }
    for (const IrGrammar& g : module.grammars) {
        out += fmt::format("grammar {} ({}) stride {} bounds {}..{} iterations {}", g.name, loc(g.loc),
                           printVec(g.stride), printVec(g.boundsMin), printVec(g.boundsMax), g.iterations);
        if (g.clampMin || g.clampMax)
            out += fmt::format(" clamp [{}, {}]", g.clampMin ? glslFloat(*g.clampMin) : "-",
                               g.clampMax ? glslFloat(*g.clampMax) : "-");
        out += "\n";
        for (const IrSweep& sweep : g.sweeps)
            printSweep(out, sweep);
    }
    for (const IrField& field : module.fields)
        printField(out, field);
    return out;
}

} // namespace voxc::ir
