#include "SamplePrograms.h"

#include "ProgramText.h"
#include "voxc/builtins/Functions.h"
#include "voxc/stages/StageKind.h"

#include <stdexcept>

namespace voxc::test {

namespace {

SourceLoc at(uint32_t line, uint32_t column) { return SourceLoc{line, column, 1}; }

Grammar overhang(glm::ivec3 worldSize) {
    Rule erode = makeRule("erode", {"GEQ 0.5, LT 0.5, IGN", "GEQ 0.5, LT 0.5, IGN", "GEQ 0.5, LT 0.5 & GT 0.1, IGN"},
                          {"NOP, NOP, NOP", "NOP, NOP, NOP", "ADD -0.5, NOP, SET 1"});
    erode.loc = at(12, 3);
    erode.priority = 1;
    Rule grow = makeRule("grow", {"GEQ 0.5, IGN, IGN", "GEQ 0.5, LT 0.5, IGN", "GEQ 0.5, LT 0.5, ABS"},
                         {"NOP, NOP, NOP", "NOP, SET 0.25, NOP", "NOP, NOP, ADD 0.1"});
    grow.loc = at(20, 3);
    grow.priority = 1;
    setWeight(grow, 0.5f);
    setProbability(grow, 0.75f);
    Rule never = makeRule("never", {"IGN, IGN, IGN", "IGN, GT 1 & LT 0, IGN", "IGN, IGN, IGN"},
                          {"SET 1, SET 1, SET 1", "NOP, NOP, NOP", "NOP, NOP, NOP"});
    never.loc = at(28, 3);
    Rule settle = makeRule("settle", {"ABS", "PRES"}, {"SET 1", "ADD -1"});
    settle.loc = at(33, 3);
    Grammar g = makeGrammar("overhang", worldSize, {erode, grow, never, settle});
    g.loc = at(8, 1);
    g.iterations = 4;
    g.clampMin = 0.0f;
    g.clampMax = 1.0f;
    return g;
}

Grammar smooth(glm::ivec3 worldSize) {
    Rule blend = makeRule("blend", {"IGN, IGN", "---", "IGN, IGN"}, {"NOP, ADD 0.125", "---", "SET 0.5, NOP"});
    blend.loc = at(43, 3);
    Rule impossible = makeRule("impossible", {"EQ 2 & NEQ 2"}, {"SET 0"});
    impossible.loc = at(48, 3);
    Grammar g = makeGrammar("smooth", worldSize, {impossible, blend});
    g.loc = at(40, 1);
    g.stride = {2, 1, 2};
    g.boundsMin = {1, 2, 0};
    g.boundsMax = {worldSize.x, worldSize.y - 1, worldSize.z};
    return g;
}

} // namespace

Program sampleProgram() {
    const glm::ivec3 size{20, 12, 10};
    Program program = makeProgram(size, {overhang(size), smooth(size)}, 7);
    program.sourcePath = "tests/sample.vox";
    program.world.origin = {-5, 3, -12};
    program.world.chunkSize = 8;

    StartShape fill;
    fill.kind = ShapeKind::Fill;
    fill.loc = at(3, 3);
    fill.value = 0.0f;
    StartShape box;
    box.kind = ShapeKind::Box;
    box.loc = at(4, 3);
    box.min = {0.0f, 0.0f, 0.0f};
    box.max = {10.0f, 4.0f, 10.0f};
    StartShape heightfield;
    heightfield.kind = ShapeKind::Heightfield;
    heightfield.loc = at(5, 3);
    heightfield.heightfield.base = 6.0f;
    heightfield.heightfield.amplitude = 3.0f;
    program.start = {fill, box, heightfield};
    stages::describePipeline(program);
    return program;
}

namespace {

// Builds a field's DAG node by node (operands first), as the checker would.
class FieldBuilder {
public:
    explicit FieldBuilder(std::string name, SourceLoc loc) { field_.name = std::move(name), field_.loc = loc; }
    uint32_t constant(float v) {
        FieldNode node;
        node.constant = glm::vec3(v, 0.0f, 0.0f);
        return add(std::move(node));
    }
    uint32_t input(FieldInput input) {
        FieldNode node;
        node.kind = FieldNode::Kind::Input;
        node.input = input;
        return add(std::move(node));
    }
    uint32_t call(std::string_view function, std::vector<uint32_t> operands, Type type = Type::Float) {
        const FunctionInfo* info = findFunction(function);
        if (!info) throw std::invalid_argument("no function " + std::string(function));
        FieldNode node;
        node.kind = FieldNode::Kind::Call;
        node.type = type;
        node.function = uint32_t(info - functions().data());
        node.operands = std::move(operands);
        return add(std::move(node));
    }
    Field finish(uint32_t root) {
        field_.root = root;
        return std::move(field_);
    }

private:
    uint32_t add(FieldNode node) {
        node.loc = field_.loc;
        field_.nodes.push_back(std::move(node));
        return uint32_t(field_.nodes.size() - 1);
    }
    Field field_;
};

// name = axis < threshold ? inside : outside
Field stepField(std::string name, SourceLoc loc, FieldInput axis, float threshold, float inside, float outside) {
    FieldBuilder b(std::move(name), loc);
    const uint32_t below = b.call("lt", {b.input(axis), b.constant(threshold)}, Type::Bool);
    return b.finish(b.call("select", {below, b.constant(inside), b.constant(outside)}));
}

// name = axis * scale + offset
Field rampField(std::string name, SourceLoc loc, FieldInput axis, float scale, float offset) {
    FieldBuilder b(std::move(name), loc);
    uint32_t value = b.call("mul", {b.input(axis), b.constant(scale)});
    if (offset != 0.0f) value = b.call("add", {value, b.constant(offset)});
    return b.finish(value);
}

Grammar weather(glm::ivec3 worldSize) {
    // Moss creeps along +x through solid voxels, one cell per iteration and phase.
    Rule spread = makeRule("spread_moss", {"MAT 3, GEQ 0.5 & NMAT 3"}, {"NOP, MAT 3"});
    spread.loc = at(62, 3);
    spread.priority = 1;
    Rule sand = makeRule("sand_on_top", {"LT 0.5", "GEQ 0.5 & MAT 1"}, {"NOP", "MAT 2"});
    sand.loc = at(67, 3);
    Rule erode = makeRule("erode_sand", {"ABS & NMAT 3", "GEQ 0.5 & MAT 2"}, {"SET 0.5 & MAT 1", "ADD -0.25"});
    erode.loc = at(72, 3);
    setProbability(erode, 0.5f);
    Grammar g = makeGrammar("weather", worldSize, {spread, sand, erode});
    g.loc = at(60, 1);
    g.iterations = 12;
    g.clampMin = 0.0f;
    g.clampMax = 1.0f;
    return g;
}

Stage fieldStage(uint32_t field, FieldMode mode, std::optional<uint8_t> material, SourceLoc loc) {
    Stage stage;
    stage.kind = Stage::Kind::Field;
    stage.index = field;
    stage.mode = mode;
    stage.material = material;
    stage.loc = loc;
    return stage;
}

} // namespace

Program materialProgram(bool withSet) {
    const glm::ivec3 size{40, 36, 28};
    Program program = makeProgram(size, {weather(size)}, 5);
    program.sourcePath = withSet ? "tests/materials_set.vox" : "tests/materials.vox";
    program.world.origin = {-3, 2, -9};
    program.world.chunkSize = 8;
    program.materials = {Material{"rock", at(1, 1), 1, {0.4f, 0.4f, 0.4f}},
                         Material{"sand", at(2, 1), 2, {0.9f, 0.8f, 0.5f}},
                         Material{"moss", at(3, 1), 3, {0.2f, 0.6f, 0.2f}}};

    StartShape fill;
    fill.kind = ShapeKind::Fill;
    fill.loc = at(6, 3);
    fill.value = 0.0f;
    StartShape ground;
    ground.kind = ShapeKind::Box;
    ground.loc = at(7, 3);
    ground.min = {0.0f, 0.0f, 0.0f};
    ground.max = {40.0f, 14.0f, 28.0f};
    ground.material = 1;
    StartShape boulder;
    boulder.kind = ShapeKind::Sphere;
    boulder.loc = at(8, 3);
    boulder.center = {20.0f, 16.0f, 14.0f};
    boulder.radius = 7.0f;
    boulder.material = 2;
    StartShape seed;
    seed.kind = ShapeKind::Box;
    seed.loc = at(9, 3);
    seed.min = {0.0f, 4.0f, 0.0f};
    seed.max = {1.0f, 10.0f, 28.0f};
    seed.material = 3;
    program.start = {fill, ground, boulder, seed};

    program.fields = {stepField("half", at(20, 1), FieldInput::LocalX, 20.0f, 0.8f, 0.2f),
                      rampField("ramp", at(21, 1), FieldInput::LocalX, 0.04f, 0.0f),
                      rampField("slope", at(22, 1), FieldInput::LocalZ, 0.05f, 0.3f),
                      stepField("low", at(23, 1), FieldInput::LocalY, 16.0f, 0.9f, 0.1f)};
    const Stage start = program.pipeline.at(0), grammar = program.pipeline.at(1);
    if (withSet) {
        program.pipeline = {start, fieldStage(2, FieldMode::Intersect, std::nullopt, at(90, 17)),
                            fieldStage(3, FieldMode::Set, 3, at(90, 35)), grammar,
                            fieldStage(0, FieldMode::Paint, 1, at(90, 60))};
    } else {
        program.pipeline = {start,
                            fieldStage(0, FieldMode::Union, 3, at(90, 10)),
                            grammar,
                            fieldStage(1, FieldMode::Subtract, 2, at(90, 40)),
                            fieldStage(2, FieldMode::Intersect, kMaterialNone, at(90, 70)),
                            fieldStage(0, FieldMode::Paint, 1, at(90, 100))};
    }
    stages::describePipeline(program);
    return program;
}

} // namespace voxc::test
