// NumPy .npy format version 1.0: magic "\x93NUMPY", version bytes 1 0, a little-endian uint16
// header length, then a Python dict literal padded with spaces and ending in '\n' so the data
// starts at a multiple of 64 bytes.
#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/grid/Grid.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <functional>
#include <fmt/format.h>
#include <fstream>
#include <iterator>

namespace voxc {

static_assert(std::endian::native == std::endian::little, "npy I/O writes host floats as '<f4'");

namespace {

constexpr char kMagic[] = "\x93NUMPY";
constexpr size_t kMagicLength = 6;
constexpr size_t kPreambleLength = kMagicLength + 2 + 2; // magic, version, header length

std::string npyHeader(glm::ivec3 size, const char* descr) {
    std::string dict = fmt::format("{{'descr': '{}', 'fortran_order': False, 'shape': ({}, {}, {}), }}", descr, size.x, size.y, size.z);
    const size_t unpadded = kPreambleLength + dict.size() + 1; // +1 for the trailing newline
    dict.append((64 - unpadded % 64) % 64, ' ');
    dict.push_back('\n');
    return dict;
}

// `kind` says what the reader wanted, e.g. "float32".
[[noreturn]] void malformed(const std::string& path, const char* kind, const std::string& why) {
    throw UserError(fmt::format("'{}' is not a {} 3-D .npy file: {}", path, kind, why));
}

// Returns the text after `'key':` in the header dict, with leading spaces skipped.
std::string_view valueOf(std::string_view dict, std::string_view key, const std::string& path, const char* kind) {
    const std::string quoted = fmt::format("'{}':", key);
    const size_t at = dict.find(quoted);
    if (at == std::string_view::npos) malformed(path, kind, fmt::format("header has no '{}'", key));
    std::string_view rest = dict.substr(at + quoted.size());
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    return rest;
}

glm::ivec3 parseShape(std::string_view value, const std::string& path, const char* kind) {
    if (value.empty() || value.front() != '(') malformed(path, kind, "shape is not a tuple");
    const size_t close = value.find(')');
    if (close == std::string_view::npos) malformed(path, kind, "shape is not a tuple");
    std::string_view items = value.substr(1, close - 1);
    glm::ivec3 shape{0};
    int count = 0;
    while (true) {
        while (!items.empty() && (items.front() == ' ' || items.front() == ',')) items.remove_prefix(1);
        if (items.empty()) break;
        size_t digits = 0;
        while (digits < items.size() && items[digits] >= '0' && items[digits] <= '9') ++digits;
        if (digits == 0 || digits > 9 || count == 3) malformed(path, kind, "shape must be three non-negative integers");
        shape[count++] = std::stoi(std::string(items.substr(0, digits)));
        items.remove_prefix(digits);
    }
    if (count != 3) malformed(path, kind, "shape must have three dimensions");
    return shape;
}

// A whole .npy file whose header passed the checks; the bytes from dataStart are exactly the elements.
struct NpyArray {
    glm::ivec3 shape;
    bool fortranOrder;
    std::string bytes;
    size_t dataStart;
};

// Reads the file and checks the magic, the version, the dtype (any of `descrs`) and the size.
NpyArray readArray(const std::string& path, std::initializer_list<std::string_view> descrs, size_t elementSize, const char* kind) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw UserError(fmt::format("cannot read '{}'", path));
    NpyArray array{};
    array.bytes.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string& bytes = array.bytes;
    if (bytes.size() < kPreambleLength || bytes.compare(0, kMagicLength, kMagic) != 0) malformed(path, kind, "bad magic");
    if (bytes[6] != 1 || bytes[7] != 0) malformed(path, kind, "only format version 1.0 is supported");
    const size_t headerLength = size_t(uint8_t(bytes[8])) | size_t(uint8_t(bytes[9])) << 8;
    if (bytes.size() < kPreambleLength + headerLength) malformed(path, kind, "truncated header");
    const std::string_view dict(bytes.data() + kPreambleLength, headerLength);

    const std::string_view descr = valueOf(dict, "descr", path, kind);
    if (std::none_of(descrs.begin(), descrs.end(), [&](std::string_view d) { return descr.starts_with(d); }))
        malformed(path, kind, fmt::format("dtype is not {}", *descrs.begin()));
    const std::string_view order = valueOf(dict, "fortran_order", path, kind);
    array.fortranOrder = order.starts_with("True");
    if (!array.fortranOrder && !order.starts_with("False")) malformed(path, kind, "fortran_order is not True or False");
    array.shape = parseShape(valueOf(dict, "shape", path, kind), path, kind);
    array.dataStart = kPreambleLength + headerLength;
    const size_t count = size_t(array.shape.x) * size_t(array.shape.y) * size_t(array.shape.z);
    if (bytes.size() - array.dataStart != count * elementSize) malformed(path, kind, "data size does not match the shape");
    return array;
}

// Writes the header and calls `row(x, y, out)` for every (x, y) in C order (z fastest).
void writeArray(OutputFiles& outputs, const std::string& path, glm::ivec3 shape, const char* descr,
                const std::function<void(int, int, std::ostream&)>& row) {
    const std::string header = npyHeader(shape, descr);
    VOXC_ASSERT(header.size() <= 0xffff);
    outputs.add(path, [&](std::ostream& out) {
        out.write(kMagic, kMagicLength);
        const char preamble[4] = {1, 0, char(header.size() & 0xff), char(header.size() >> 8)};
        out.write(preamble, 4);
        out.write(header.data(), std::streamsize(header.size()));
        for (int x = 0; x < shape.x; ++x)
            for (int y = 0; y < shape.y; ++y) row(x, y, out);
    });
}

} // namespace

void writeFloatNpy(OutputFiles& outputs, const std::string& path, glm::ivec3 size, std::span<const float> values) {
    VOXC_ASSERT(values.size() == size_t(size.x) * size_t(size.y) * size_t(size.z));
    // C order puts z fastest, the transpose of the x-fastest storage.
    std::vector<float> row(size_t(size.z));
    writeArray(outputs, path, size, "<f4", [&](int x, int y, std::ostream& out) {
        for (int z = 0; z < size.z; ++z) row[size_t(z)] = values[size_t(x) + size_t(size.x) * (size_t(y) + size_t(size.y) * size_t(z))];
        out.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
    });
}

void writeNpy(OutputFiles& outputs, const std::string& path, const DenseGrid& grid) {
    writeFloatNpy(outputs, path, grid.size(), grid.data());
}

void writeNpy(const std::string& path, const DenseGrid& grid) {
    OutputFiles outputs;
    writeNpy(outputs, path, grid);
    outputs.commit();
}

DenseGrid readNpy(const std::string& path) {
    const NpyArray array = readArray(path, {"'<f4'"}, sizeof(float), "float32");
    DenseGrid grid(array.shape);
    std::vector<float> values(grid.data().size());
    std::memcpy(values.data(), array.bytes.data() + array.dataStart, values.size() * sizeof(float));
    if (array.fortranOrder) {
        // Fortran order is x fastest, exactly DenseGrid's storage.
        grid.data() = std::move(values);
        return grid;
    }
    size_t i = 0;
    for (int x = 0; x < array.shape.x; ++x)
        for (int y = 0; y < array.shape.y; ++y)
            for (int z = 0; z < array.shape.z; ++z) grid.at({x, y, z}) = values[i++];
    return grid;
}

void writeMaterialNpy(OutputFiles& outputs, const std::string& path, const DenseGrid& grid) {
    std::string values(size_t(grid.size().z), '\0');
    writeArray(outputs, path, grid.size(), "|u1", [&](int x, int y, std::ostream& out) {
        for (int z = 0; z < grid.size().z; ++z) values[size_t(z)] = char(grid.materialAt({x, y, z}));
        out.write(values.data(), std::streamsize(values.size()));
    });
}

void writeMaterialNpy(const std::string& path, const DenseGrid& grid) {
    OutputFiles outputs;
    writeMaterialNpy(outputs, path, grid);
    outputs.commit();
}

void readMaterialNpy(const std::string& path, DenseGrid& grid) {
    // A single byte has no byte order: NumPy writes '|u1', other writers '<u1' or '>u1'.
    const NpyArray array = readArray(path, {"'|u1'", "'<u1'", "'>u1'"}, 1, "uint8");
    if (array.shape != grid.size())
        throw UserError(fmt::format("'{}' has shape ({}, {}, {}) but the grid is ({}, {}, {})", path, array.shape.x, array.shape.y,
                                    array.shape.z, grid.size().x, grid.size().y, grid.size().z));
    const uint8_t* values = reinterpret_cast<const uint8_t*>(array.bytes.data() + array.dataStart);
    size_t i = 0;
    if (array.fortranOrder) {
        for (uint8_t& material : grid.materials()) material = values[i++];
        return;
    }
    for (int x = 0; x < array.shape.x; ++x)
        for (int y = 0; y < array.shape.y; ++y)
            for (int z = 0; z < array.shape.z; ++z) grid.materialAt({x, y, z}) = values[i++];
}

} // namespace voxc
