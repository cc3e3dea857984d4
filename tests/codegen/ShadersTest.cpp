#include "voxc/core/Errors.h"
#include "voxc/shaders/ShaderSources.h"

#include <gtest/gtest.h>

namespace voxc {
namespace shaders_test {

TEST(codegen_Shaders, EveryTemplateIsEmbedded) {
    const std::vector<std::string_view> names = shaderFileNames();
    for (std::string_view name :
         {"common.glsl", "noop_sweep.glsl", "perlin.glsl", "random.glsl", "start.glsl", "sweep.glsl"})
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
    // Embedded verbatim, including the markers codegen fills in.
    EXPECT_EQ(shaderSource("sweep.glsl").rfind("#version 450\n// <<HEADER>>\n", 0), 0u);
    EXPECT_NE(shaderSource("common.glsl").find("int voxelAddress(ivec3 local)"), std::string_view::npos);
}

TEST(codegen_Shaders, UnknownTemplateIsAnInternalError) { EXPECT_THROW(shaderSource("nope.glsl"), InternalError); }

} // namespace shaders_test
} // namespace voxc
