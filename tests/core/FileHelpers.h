#pragma once
// Small file helpers shared by the core tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace voxc::test {

// An empty directory of its own for each test (names are unique across the core tests).
inline std::string freshDir(const std::string& name) {
    const std::string dir = testing::TempDir() + "core_" + name + "/";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

inline void putFile(const std::string& path, const std::string& contents) {
    std::ofstream(path, std::ios::binary) << contents;
}

} // namespace voxc::test
