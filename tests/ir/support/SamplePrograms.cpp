#include "SamplePrograms.h"

#include "ProgramText.h"

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
    return program;
}

} // namespace voxc::test
