// Writes the .glb files the validator test checks (spec G1): an empty mesh, one material, several
// materials, more than 65,535 vertices (32-bit indices), random-density noise, and, in bad/, a
// file with a wrong POSITION bound that the checker must reject (so it is known to look).
#include "TestGrids.h"
#include "voxc/mesh/Export.h"
#include "voxc/mesh/MarchingCubes.h"

#include <filesystem>
#include <iostream>
#include <random>

using namespace voxc;

namespace {

ChunkedGrid ballAndSlab() {
    ChunkedGrid grid = test::makeGrid({-4, 2, 5}, {30, 22, 26}, 16, [](glm::vec3 p) {
        return std::max(test::coneBall({10.4f, 12.2f, 17.7f}, 9.0f)(p), test::box({-2, 4, 8}, {24, 8, 28})(p));
    });
    test::paintMaterials(grid, [](glm::ivec3 p) { return uint8_t(p.x < 4 ? 1 : p.x < 10 ? 2 : p.x < 16 ? 7 : 9); });
    return grid;
}

ChunkedGrid noise(glm::ivec3 size) {
    ChunkedGrid grid(ChunkLayout::make({0, 0, 0}, size, 32));
    std::mt19937 random(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (float& d : grid.data()) d = unit(random);
    return grid;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: voxc_glb_fixtures OUTDIR\n";
        return 1;
    }
    const std::filesystem::path dir(argv[1]);
    std::filesystem::create_directories(dir / "bad");
    const std::vector<Material> materials = {{"rock", {}, 1, {0.5f, 0.25f, 1.0f}}, {"sand", {}, 2, {0.86f, 0.78f, 0.55f}},
                                             {"grass", {}, 7, {0.2f, 0.6f, 0.1f}}};
    const Mesh several = meshMarchingCubes(ballAndSlab(), MeshOptions{});
    writeGlb((dir / "empty.glb").string(), Mesh{});
    writeGlb((dir / "one_material.glb").string(), meshMarchingCubes(test::makeGrid({0, 0, 0}, {20, 20, 20}, 8, test::coneBall({9.5f, 10.2f, 8.7f}, 8.0f)), MeshOptions{}));
    writeGlb((dir / "several_materials.glb").string(), several, materials);
    const Mesh large = meshMarchingCubes(noise({40, 40, 40}), MeshOptions{});
    if (large.positions.size() <= 65535) {
        std::cerr << "the large fixture has only " << large.positions.size() << " vertices\n";
        return 1;
    }
    writeGlb((dir / "large.glb").string(), large);
    writeGlb((dir / "noise.glb").string(), meshMarchingCubes(noise({16, 16, 16}), MeshOptions{}));

    std::string bad = encodeGlb(several, materials);
    const size_t max = bad.find("\"max\":[");
    if (max == std::string::npos) return 1;
    char& digit = bad[bad.find_first_of("0123456789", max)];
    digit = digit == '9' ? '8' : char(digit + 1); // same length, so the container stays valid
    writeFileAtomically((dir / "bad" / "wrong_bounds.glb").string(), bad);
    return 0;
}
