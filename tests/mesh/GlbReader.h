#pragma once
// A reader for the tests, written from the glTF 2.0 specification independently of the writer:
// it checks the container as it goes (gtest failures) and reads accessors generically.
#include <cstdint>
#include <cstring>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace voxc::test {

struct GlbFile {
    nlohmann::json json;
    std::string bin; // the BIN chunk with its padding; empty when there is none
    uint32_t headerLength = 0;
    uint32_t jsonChunkLength = 0;
    std::string jsonChunk; // with its padding
};

inline uint32_t readUint32(const std::string& bytes, size_t at) {
    uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

// Parses the container; every structural rule of the GLB format is an EXPECT.
inline GlbFile parseGlb(const std::string& bytes) {
    GlbFile f;
    EXPECT_GE(bytes.size(), 20u);
    if (bytes.size() < 20) return f;
    EXPECT_EQ(readUint32(bytes, 0), 0x46546C67u); // "glTF"
    EXPECT_EQ(readUint32(bytes, 4), 2u);
    f.headerLength = readUint32(bytes, 8);
    EXPECT_EQ(f.headerLength, bytes.size());
    f.jsonChunkLength = readUint32(bytes, 12);
    EXPECT_EQ(readUint32(bytes, 16), 0x4E4F534Au); // JSON first
    EXPECT_EQ(f.jsonChunkLength % 4, 0u);
    f.jsonChunk = bytes.substr(20, f.jsonChunkLength);
    const size_t jsonEnd = f.jsonChunk.find_last_not_of(' ') + 1;
    for (size_t i = jsonEnd; i < f.jsonChunk.size(); ++i) EXPECT_EQ(f.jsonChunk[i], ' ');
    f.json = nlohmann::json::parse(f.jsonChunk.substr(0, jsonEnd));
    const size_t binAt = 20 + size_t(f.jsonChunkLength);
    if (binAt < bytes.size()) {
        const uint32_t binLength = readUint32(bytes, binAt);
        EXPECT_EQ(readUint32(bytes, binAt + 4), 0x004E4942u); // BIN second
        EXPECT_EQ(binLength % 4, 0u);
        EXPECT_EQ(binAt + 8 + binLength, bytes.size());
        f.bin = bytes.substr(binAt + 8, binLength);
    }
    return f;
}

// The elements of an accessor as raw component bytes, one vector per element.
inline std::vector<std::string> accessorElements(const GlbFile& f, size_t accessor) {
    const nlohmann::json& a = f.json["accessors"][accessor];
    const nlohmann::json& view = f.json["bufferViews"][a["bufferView"].get<size_t>()];
    const int componentType = a["componentType"];
    const size_t componentSize = componentType == 5126 || componentType == 5125 ? 4 : componentType == 5123 ? 2 : 1;
    const std::string type = a["type"];
    const size_t components = type == "SCALAR" ? 1 : type == "VEC3" ? 3 : 4;
    const size_t elementSize = componentSize * components;
    const size_t stride = view.value("byteStride", elementSize);
    const size_t start = view.value("byteOffset", size_t(0)) + a.value("byteOffset", size_t(0));
    const size_t count = a["count"];
    std::vector<std::string> elements;
    EXPECT_LE(start + (count ? (count - 1) * stride + elementSize : 0), view.value("byteOffset", size_t(0)) + view["byteLength"].get<size_t>());
    for (size_t i = 0; i < count; ++i) elements.push_back(f.bin.substr(start + i * stride, elementSize));
    return elements;
}

template <class T> std::vector<T> accessorValues(const GlbFile& f, size_t accessor) {
    std::vector<T> values;
    for (const std::string& e : accessorElements(f, accessor)) {
        EXPECT_EQ(e.size() % sizeof(T), 0u);
        for (size_t at = 0; at < e.size(); at += sizeof(T)) {
            T v;
            std::memcpy(&v, e.data() + at, sizeof(T));
            values.push_back(v);
        }
    }
    return values;
}

// Indices of an index accessor, whatever their width.
inline std::vector<uint32_t> indexValues(const GlbFile& f, size_t accessor) {
    const int componentType = f.json["accessors"][accessor]["componentType"];
    if (componentType == 5125) return accessorValues<uint32_t>(f, accessor);
    const std::vector<uint16_t> narrow = accessorValues<uint16_t>(f, accessor);
    return {narrow.begin(), narrow.end()};
}

} // namespace voxc::test
