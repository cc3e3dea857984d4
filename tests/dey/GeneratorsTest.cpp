// The contract of Dey's generator records (voxc_generators) as the checker relies on it, without
// the checker: defaults that need no warning, and a build that returns a well-formed Field.
#include "voxc/generators/dey/Generators.h"
#include "voxc/program/FieldDag.h"

#include <cmath>
#include <gtest/gtest.h>

namespace voxc::dey {
namespace {

// Every defaulted key at its default; the required keys (the overhang's box) set to a valid box.
GeneratorParams defaults(const GeneratorInfo& info) {
    GeneratorParams params;
    for (const GeneratorKey& key : info.keys) {
        if (key.required) params.set(key.name, key.name == "min" ? std::array<double, 3>{8, 0, 8}
                                                                 : std::array<double, 3>{40, 48, 56});
        else if (!key.override) params.set(key.name, key.value);
    }
    return params;
}

TEST(dey_Generators, DefaultsLieInTheirRangesAndOnTheSamplingGrid) {
    ASSERT_EQ(generators().size(), 3u);
    for (const GeneratorInfo& info : generators()) {
        EXPECT_EQ(findGenerator(info.name), &info);
        for (const GeneratorKey& key : info.keys) {
            if (key.required || key.override) continue;
            SCOPED_TRACE(std::string(info.name) + "." + std::string(key.name));
            const int components = key.type == GeneratorKeyType::Vec3 ? 3 : 1;
            for (int i = 0; i < components; ++i) {
                EXPECT_GE(key.value[i], key.min);
                EXPECT_LE(key.value[i], key.max);
            }
            if (key.step > 0) {
                const double steps = (key.value[0] - key.min) / key.step;
                EXPECT_NEAR(steps, std::round(steps), 1e-9);
            }
        }
    }
    EXPECT_EQ(findGenerator("bridge"), nullptr);
}

TEST(dey_Generators, EveryRecordBuildsATopologicalHashConsedFloatField) {
    for (const GeneratorInfo& info : generators()) {
        SCOPED_TRACE(std::string(info.name));
        const GeneratorParams params = defaults(info);
        ASSERT_FALSE(info.validate(params).has_value());
        const Field field = info.build(params, 3);
        ASSERT_FALSE(field.nodes.empty());
        EXPECT_EQ(field.root, field.nodes.size() - 1);
        EXPECT_EQ(field.nodes[field.root].type, Type::Float);
        // Re-adding the nodes in order to a FieldDag finds no duplicate: the build shared them.
        FieldDag dag;
        for (uint32_t i = 0; i < field.nodes.size(); ++i) {
            for (uint32_t operand : field.nodes[i].operands) EXPECT_LT(operand, i);
            EXPECT_EQ(dag.add(field.nodes[i]), i);
        }
        // Naming the field and locating its nodes is the caller's.
        EXPECT_TRUE(field.name.empty());
    }
}

TEST(dey_Generators, ValidateNamesTheKeyOfAnUnusableCombination) {
    const GeneratorInfo& arch = *findGenerator("arch");
    GeneratorParams params = defaults(arch);
    params.set("start", {16, 16, 16});
    params.set("end", {16, 16, 16});
    const auto problem = arch.validate(params);
    ASSERT_TRUE(problem.has_value());
    EXPECT_EQ(problem->key, "end");
}

} // namespace
} // namespace voxc::dey
