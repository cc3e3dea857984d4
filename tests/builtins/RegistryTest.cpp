#include "voxc/builtins/Ops.h"
#include "voxc/builtins/Shapes.h"

#include <cstdlib>
#include <gtest/gtest.h>
#include <set>

namespace voxc {
namespace {

TEST(builtins_registry, EveryOperatorHasOneRecordWithEveryBackend) {
    std::set<std::string_view> names;
    for (const SymbolOpInfo& info : symbolOps()) {
        EXPECT_TRUE(names.insert(info.name).second) << info.name;
        EXPECT_EQ(&symbolOpInfo(info.op), &info);
        EXPECT_EQ(findSymbolOp(info.name), info.op);
        EXPECT_FALSE(info.glsl("d", "0.5").empty());
        EXPECT_NE(info.accepts, nullptr);
    }
    EXPECT_EQ(symbolOps().size(), 9u);
    for (const TransformOpInfo& info : transformOps()) {
        EXPECT_TRUE(names.insert(info.name).second) << info.name;
        EXPECT_EQ(findTransformOp(info.name), info.op);
        EXPECT_FALSE(info.glsl("d", "0.5").empty());
    }
    EXPECT_EQ(transformOps().size(), 3u);
    EXPECT_FALSE(findSymbolOp("NOP").has_value());
    EXPECT_FALSE(findTransformOp("GEQ").has_value());
}

TEST(builtins_registry, AcceptedSetsAgreeWithEvaluation) {
    const float probes[] = {-1.0f, -0.0f, 0.0f, 0.25f, 0.5f, 0.75f, 1.0f, 2.0f};
    for (const SymbolOpInfo& info : symbolOps()) {
        const ValueSet set = info.accepts(0.5f);
        for (float d : probes) {
            bool inSet = false;
            for (const Interval& i : set.intervals())
                inSet |= (d > i.lo || (i.loClosed && d == i.lo)) && (d < i.hi || (i.hiClosed && d == i.hi));
            EXPECT_EQ(inSet, info.eval(d, 0.5f)) << info.name << " at " << d;
        }
    }
}

TEST(builtins_registry, GlslFloatRoundTrips) {
    for (float v : {0.0f, 1.0f, -0.5f, 0.1f, 0.3f, 1e-7f, 123456.789f, -3.4e38f}) {
        const std::string text = glslFloat(v);
        EXPECT_NE(text.find_first_of(".e"), std::string::npos) << text;
        EXPECT_EQ(std::strtof(text.c_str(), nullptr), v) << text;
    }
}

TEST(builtins_registry, ShapesHaveUniqueNamesAndKeys) {
    std::set<std::string_view> names;
    for (const ShapeInfo& info : shapes()) {
        EXPECT_TRUE(names.insert(info.name).second);
        EXPECT_EQ(findShape(info.name), info.kind);
        std::set<std::string_view> keys;
        for (const KeySpec& key : info.keys) {
            EXPECT_TRUE(keys.insert(key.name).second) << info.name << "." << key.name;
            EXPECT_LE(key.min, key.max);
        }
        EXPECT_FALSE(info.glsl(StartShape{}).empty());
    }
}

} // namespace
} // namespace voxc
