#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/grid/Grid.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>

namespace voxc {
namespace {

DenseGrid numberedGrid(glm::ivec3 size) {
    DenseGrid grid(size);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) grid.at({x, y, z}) = float(100 * x + 10 * y + z) + 0.5f;
    return grid;
}

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(grid_Npy, roundTripPreservesEveryVoxel) {
    const std::string path = testing::TempDir() + "grid_roundtrip.npy";
    const DenseGrid grid = numberedGrid({3, 4, 5});
    writeNpy(path, grid);
    const DenseGrid back = readNpy(path);
    EXPECT_EQ(back.size(), grid.size());
    EXPECT_EQ(back.data(), grid.data());
}

TEST(grid_Npy, headerIsVersion1AlignedTo64AndDataIsCOrder) {
    const std::string path = testing::TempDir() + "grid_header.npy";
    writeNpy(path, numberedGrid({2, 3, 4}));
    const std::string bytes = readBytes(path);
    ASSERT_GE(bytes.size(), 10u);
    EXPECT_EQ(bytes.substr(0, 6), "\x93NUMPY");
    EXPECT_EQ(bytes[6], 1);
    EXPECT_EQ(bytes[7], 0);
    const size_t headerLength = size_t(uint8_t(bytes[8])) | size_t(uint8_t(bytes[9])) << 8;
    EXPECT_EQ((10 + headerLength) % 64, 0u);
    const std::string dict = bytes.substr(10, headerLength);
    EXPECT_EQ(dict.rfind("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3, 4), }", 0), 0u);
    EXPECT_EQ(dict.back(), '\n');
    ASSERT_EQ(bytes.size(), 10 + headerLength + 24 * sizeof(float));
    // C order: the second float is arr[0,0,1], the fifth is arr[0,1,0].
    float values[5];
    std::memcpy(values, bytes.data() + 10 + headerLength, sizeof(values));
    EXPECT_EQ(values[0], 0.5f);
    EXPECT_EQ(values[1], 1.5f);
    EXPECT_EQ(values[4], 10.5f);
}

TEST(grid_Npy, malformedFilesAreUserErrors) {
    const std::string dir = testing::TempDir();
    writeFileAtomically(dir + "grid_bad_magic.npy", std::string("not a numpy file at all"));
    EXPECT_THROW(readNpy(dir + "grid_bad_magic.npy"), UserError);

    const std::string good = dir + "grid_truncated.npy";
    writeNpy(good, numberedGrid({2, 2, 2}));
    const std::string bytes = readBytes(good);
    writeFileAtomically(good, bytes.substr(0, bytes.size() - 3));
    EXPECT_THROW(readNpy(good), UserError);

    std::string wrongType = bytes;
    wrongType.replace(wrongType.find("<f4"), 3, "<f8");
    writeFileAtomically(dir + "grid_f8.npy", wrongType);
    EXPECT_THROW(readNpy(dir + "grid_f8.npy"), UserError);

    EXPECT_THROW(readNpy(dir + "grid_does_not_exist.npy"), UserError);
}

DenseGrid numberedMaterials(glm::ivec3 size) {
    DenseGrid grid = numberedGrid(size);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) grid.materialAt({x, y, z}) = uint8_t(100 * x + 10 * y + z);
    return grid;
}

TEST(grid_MaterialNpy, roundTripPreservesEveryMaterialAndLeavesDensities) {
    const std::string path = testing::TempDir() + "grid_materials.npy";
    const DenseGrid grid = numberedMaterials({3, 4, 5});
    writeMaterialNpy(path, grid);
    DenseGrid back({3, 4, 5}, 0.25f);
    readMaterialNpy(path, back);
    EXPECT_EQ(back.materials(), grid.materials());
    EXPECT_EQ(back.data(), std::vector<float>(60, 0.25f));
}

TEST(grid_MaterialNpy, headerIsUint8AlignedTo64AndDataIsCOrder) {
    const std::string path = testing::TempDir() + "grid_materials_header.npy";
    writeMaterialNpy(path, numberedMaterials({2, 3, 4}));
    const std::string bytes = readBytes(path);
    ASSERT_GE(bytes.size(), 10u);
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
    const size_t headerLength = size_t(uint8_t(bytes[8])) | size_t(uint8_t(bytes[9])) << 8;
    EXPECT_EQ((10 + headerLength) % 64, 0u);
    EXPECT_EQ(bytes.substr(10, headerLength).rfind("{'descr': '|u1', 'fortran_order': False, 'shape': (2, 3, 4), }", 0), 0u);
    ASSERT_EQ(bytes.size(), 10 + headerLength + 24);
    const std::string data = bytes.substr(10 + headerLength);
    EXPECT_EQ(uint8_t(data[1]), 1);   // arr[0,0,1]
    EXPECT_EQ(uint8_t(data[4]), 10);  // arr[0,1,0]
    EXPECT_EQ(uint8_t(data[23]), 123); // arr[1,2,3]
}

TEST(grid_MaterialNpy, wrongShapeOrTypeIsAUserError) {
    const std::string dir = testing::TempDir();
    writeMaterialNpy(dir + "grid_materials_shape.npy", numberedMaterials({2, 3, 4}));
    DenseGrid other({2, 4, 3});
    EXPECT_THROW(readMaterialNpy(dir + "grid_materials_shape.npy", other), UserError);
    writeNpy(dir + "grid_floats.npy", numberedGrid({2, 3, 4}));
    DenseGrid same({2, 3, 4});
    EXPECT_THROW(readMaterialNpy(dir + "grid_floats.npy", same), UserError);
    EXPECT_THROW(readNpy(dir + "grid_materials_shape.npy"), UserError);
    EXPECT_THROW(readMaterialNpy(dir + "grid_materials_missing.npy", same), UserError);
}

// Cross-checks the file against NumPy itself. NumPy is a test dependency (scripts/install-deps.sh), so a
// machine without it fails these tests rather than skipping them.
const std::string kPython = VOXC_NUMPY_PYTHON;

bool numpyAvailable() { return std::system((kPython + " -c 'import numpy' >/dev/null 2>&1").c_str()) == 0; }

TEST(grid_Npy, numpyLoadsTheFileWithMatchingValues) {
    ASSERT_TRUE(numpyAvailable()) << kPython << " cannot import numpy: run scripts/install-deps.sh";
    const std::string path = testing::TempDir() + "grid_numpy.npy";
    writeNpy(path, numberedGrid({3, 4, 5}));
    const std::string check = kPython + " -c \"import numpy as np; a = np.load('" + path +
                              "'); assert a.dtype == np.float32 and a.shape == (3, 4, 5); "
                              "assert a[2, 3, 4] == 234.5 and a[1, 0, 3] == 103.5\"";
    EXPECT_EQ(std::system(check.c_str()), 0);
}

TEST(grid_MaterialNpy, numpyLoadsTheFileAsUint8) {
    ASSERT_TRUE(numpyAvailable()) << kPython << " cannot import numpy: run scripts/install-deps.sh";
    const std::string path = testing::TempDir() + "grid_materials_numpy.npy";
    writeMaterialNpy(path, numberedMaterials({2, 3, 5}));
    const std::string check = kPython + " -c \"import numpy as np; a = np.load('" + path +
                              "'); assert a.dtype == np.uint8 and a.shape == (2, 3, 5); "
                              "assert a[1, 2, 4] == 124 and a[0, 1, 3] == 13\"";
    EXPECT_EQ(std::system(check.c_str()), 0);
}

} // namespace
} // namespace voxc
