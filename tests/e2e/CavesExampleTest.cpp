// examples/caves.vox as a game would take it (issue 8, "Done when"): on lavapipe its air is one
// connected network reaching every drawn segment of the skeleton (noise may leave a few
// isolated bubbles of a handful of voxels, never a cut passage), its rooms and tunnels are
// carved and its speleothems grow. (The interpreter's agreement with Vulkan for the carve and the
// speleothem stages is tested at every chunk size in tests/vulkan and tests/caves.)
#include "Lavapipe.h"
#include "GridCompare.h"
#include "voxc/check/Check.h"
#include "voxc/generators/lsystem/Connect.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/generators/lsystem/Turtle.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace voxc {
namespace caves_example_test {

// Component id per air voxel (density < 0.5), 6-connected, and each component's size.
struct AirComponents {
    std::vector<int32_t> id; // -1 for rock
    std::vector<size_t> sizes;
};

AirComponents airComponents(const DenseGrid& grid) {
    const glm::ivec3 size = grid.size();
    AirComponents out;
    out.id.assign(grid.data().size(), -1);
    std::vector<glm::ivec3> stack;
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const glm::ivec3 seed(x, y, z);
                if (grid.at(seed) >= 0.5f || out.id[grid.index(seed)] >= 0) continue;
                const int32_t component = int32_t(out.sizes.size());
                out.sizes.push_back(0);
                out.id[grid.index(seed)] = component;
                stack.push_back(seed);
                while (!stack.empty()) {
                    const glm::ivec3 p = stack.back();
                    stack.pop_back();
                    ++out.sizes.back();
                    for (glm::ivec3 step : {glm::ivec3(1, 0, 0), glm::ivec3(-1, 0, 0), glm::ivec3(0, 1, 0),
                                            glm::ivec3(0, -1, 0), glm::ivec3(0, 0, 1), glm::ivec3(0, 0, -1)}) {
                        const glm::ivec3 q = p + step;
                        if (glm::any(glm::lessThan(q, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(q, size)))
                            continue;
                        const size_t i = grid.index(q);
                        if (grid.at(q) >= 0.5f || out.id[i] >= 0) continue;
                        out.id[i] = component;
                        stack.push_back(q);
                    }
                }
            }
    return out;
}

TEST(e2e_CavesExample, OneConnectedNetworkWithRoomsTunnelsAndSpeleothems) {
    CheckResult checked = checkFile(std::string(VOXC_SOURCE_DIR) + "/examples/caves.vox");
    ASSERT_TRUE(checked.program && !checked.hasErrors()) << checked.rendered();
    const Program& program = *checked.program;
    const DenseGrid grid = test::runOnLavapipe(program);

    const AirComponents air = airComponents(grid);
    ASSERT_FALSE(air.sizes.empty());
    const size_t total = std::accumulate(air.sizes.begin(), air.sizes.end(), size_t(0));
    const auto largest = std::max_element(air.sizes.begin(), air.sizes.end());
    EXPECT_GT(total, size_t(100000));
    // Stray bubbles are a few voxels each and a tiny share of the air.
    for (size_t i = 0; i < air.sizes.size(); ++i)
        if (int64_t(i) != largest - air.sizes.begin()) { EXPECT_LE(air.sizes[i], 64u) << "component " << i; }
    EXPECT_GE(double(*largest), 0.999 * double(total));

    // Every drawn segment's ends (inside the grid, as the constrain box keeps them) are air of
    // the one large component: the network is connected as the skeleton is.
    ASSERT_EQ(checked.lsystems.size(), 1u);
    const lsystem::Definition& definition = checked.lsystems[0].definition;
    const lsystem::Expansion expansion = lsystem::expand(definition);
    const lsystem::Skeleton skeleton = lsystem::interpret(definition, expansion.symbols, expansion.types);
    size_t rooms = 0, tunnels = 0;
    for (const lsystem::Segment& segment : skeleton.segments) {
        (segment.type == lsystem::SymbolType::Room ? rooms : tunnels) += 1;
        for (glm::dvec3 end : {segment.from, segment.to}) {
            const glm::ivec3 voxel = glm::ivec3(glm::round(end)) - program.world.origin;
            ASSERT_TRUE(glm::all(glm::greaterThanEqual(voxel, glm::ivec3(0))) &&
                        glm::all(glm::lessThan(voxel, program.world.size)));
            EXPECT_EQ(air.id[grid.index(voxel)], int32_t(largest - air.sizes.begin()));
        }
    }
    EXPECT_GT(rooms, 20u);
    EXPECT_GT(tunnels, 50u);

    // Speleothems: flowstone (id 3) is written and solid somewhere.
    size_t flowstone = 0;
    for (size_t i = 0; i < grid.data().size(); ++i) flowstone += grid.materials()[i] == 3 && grid.data()[i] >= 0.5f;
    EXPECT_GT(flowstone, 500u);
}

} // namespace caves_example_test
} // namespace voxc
