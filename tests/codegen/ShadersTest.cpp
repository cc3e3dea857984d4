#include "voxc/builtins/Shapes.h"
#include "voxc/core/Errors.h"
#include "voxc/shaders/ShaderSources.h"

#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

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

// noise_permutation.glsl spells Perlin's permutation out as pairs (perm(i) | perm(i + 1) << 8) so the
// kernels need not copy it from the noise-table buffer; the pairs must be those of the table the
// interpreter reads, or device and interpreter noise differ.
TEST(codegen_Shaders, PerlinPermutationPairsAreThoseOfTheInterpreterTable) {
    const std::string_view source = shaderSource("noise_permutation.glsl");
    const std::string_view opening = "int noisePermutationPairs[256] = int[256](";
    const size_t begin = source.find(opening);
    ASSERT_NE(begin, std::string_view::npos);
    const size_t end = source.find(");", begin);
    ASSERT_NE(end, std::string_view::npos);
    std::string list(source.substr(begin + opening.size(), end - begin - opening.size()));
    for (char& c : list)
        if (c == ',') c = ' ';
    std::istringstream in(list);
    std::vector<int> pairs;
    for (int value; in >> value;) pairs.push_back(value);
    ASSERT_TRUE(in.eof()) << "not a list of integers";
    const std::span<const int, 256> permutation = perlinPermutation();
    ASSERT_EQ(pairs.size(), 256u);
    for (int i = 0; i < 256; ++i)
        EXPECT_EQ(pairs[size_t(i)], permutation[size_t(i)] | (permutation[size_t((i + 1) & 255)] << 8)) << "entry " << i;
}

TEST(codegen_Shaders, UnknownTemplateIsAnInternalError) { EXPECT_THROW(shaderSource("nope.glsl"), InternalError); }

} // namespace shaders_test
} // namespace voxc
