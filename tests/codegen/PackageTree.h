#pragma once
// A package directory's files as bytes by relative path, for comparing whole packages in tests.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace voxc::test {

using PackageTree = std::map<std::string, std::string>;

inline PackageTree readTree(const std::filesystem::path& dir) {
    PackageTree files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        std::ifstream in(entry.path(), std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        files[std::filesystem::relative(entry.path(), dir).string()] = bytes.str();
    }
    return files;
}

} // namespace voxc::test
