// NumPy .npy format version 1.0: magic "\x93NUMPY", version bytes 1 0, a little-endian uint16
// header length, then a Python dict literal padded with spaces and ending in '\n' so the data
// starts at a multiple of 64 bytes.
#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/grid/Grid.h"

#include <bit>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <iterator>

namespace voxc {

static_assert(std::endian::native == std::endian::little, "npy I/O writes host floats as '<f4'");

namespace {

constexpr char kMagic[] = "\x93NUMPY";
constexpr size_t kMagicLength = 6;
constexpr size_t kPreambleLength = kMagicLength + 2 + 2; // magic, version, header length

std::string npyHeader(glm::ivec3 size) {
    std::string dict = fmt::format("{{'descr': '<f4', 'fortran_order': False, 'shape': ({}, {}, {}), }}", size.x, size.y, size.z);
    const size_t unpadded = kPreambleLength + dict.size() + 1; // +1 for the trailing newline
    dict.append((64 - unpadded % 64) % 64, ' ');
    dict.push_back('\n');
    return dict;
}

[[noreturn]] void malformed(const std::string& path, const std::string& why) {
    throw UserError(fmt::format("'{}' is not a float32 3-D .npy file: {}", path, why));
}

// Returns the text after `'key':` in the header dict, with leading spaces skipped.
std::string_view valueOf(std::string_view dict, std::string_view key, const std::string& path) {
    const std::string quoted = fmt::format("'{}':", key);
    const size_t at = dict.find(quoted);
    if (at == std::string_view::npos) malformed(path, fmt::format("header has no '{}'", key));
    std::string_view rest = dict.substr(at + quoted.size());
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    return rest;
}

glm::ivec3 parseShape(std::string_view value, const std::string& path) {
    if (value.empty() || value.front() != '(') malformed(path, "shape is not a tuple");
    const size_t close = value.find(')');
    if (close == std::string_view::npos) malformed(path, "shape is not a tuple");
    std::string_view items = value.substr(1, close - 1);
    glm::ivec3 shape{0};
    int count = 0;
    while (true) {
        while (!items.empty() && (items.front() == ' ' || items.front() == ',')) items.remove_prefix(1);
        if (items.empty()) break;
        size_t digits = 0;
        while (digits < items.size() && items[digits] >= '0' && items[digits] <= '9') ++digits;
        if (digits == 0 || digits > 9 || count == 3) malformed(path, "shape must be three non-negative integers");
        shape[count++] = std::stoi(std::string(items.substr(0, digits)));
        items.remove_prefix(digits);
    }
    if (count != 3) malformed(path, "shape must have three dimensions");
    return shape;
}

} // namespace

void writeNpy(const std::string& path, const DenseGrid& grid) {
    const glm::ivec3 s = grid.size();
    const std::string header = npyHeader(s);
    VOXC_ASSERT(header.size() <= 0xffff);
    writeFileAtomically(path, [&](std::ostream& out) {
        out.write(kMagic, kMagicLength);
        const char preamble[4] = {1, 0, char(header.size() & 0xff), char(header.size() >> 8)};
        out.write(preamble, 4);
        out.write(header.data(), std::streamsize(header.size()));
        // C order puts z fastest, the transpose of DenseGrid's x-fastest storage.
        std::vector<float> row(size_t(s.z));
        for (int x = 0; x < s.x; ++x)
            for (int y = 0; y < s.y; ++y) {
                for (int z = 0; z < s.z; ++z) row[size_t(z)] = grid.at({x, y, z});
                out.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
            }
    });
}

DenseGrid readNpy(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw UserError(fmt::format("cannot read '{}'", path));
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < kPreambleLength || bytes.compare(0, kMagicLength, kMagic) != 0) malformed(path, "bad magic");
    if (bytes[6] != 1 || bytes[7] != 0) malformed(path, "only format version 1.0 is supported");
    const size_t headerLength = size_t(uint8_t(bytes[8])) | size_t(uint8_t(bytes[9])) << 8;
    if (bytes.size() < kPreambleLength + headerLength) malformed(path, "truncated header");
    const std::string_view dict(bytes.data() + kPreambleLength, headerLength);

    if (valueOf(dict, "descr", path).substr(0, 5) != "'<f4'") malformed(path, "dtype is not '<f4'");
    const std::string_view order = valueOf(dict, "fortran_order", path);
    const bool fortran = order.starts_with("True");
    if (!fortran && !order.starts_with("False")) malformed(path, "fortran_order is not True or False");
    const glm::ivec3 shape = parseShape(valueOf(dict, "shape", path), path);

    DenseGrid grid(shape);
    const size_t count = grid.data().size();
    const size_t dataStart = kPreambleLength + headerLength;
    if (bytes.size() - dataStart != count * sizeof(float)) malformed(path, "data size does not match the shape");
    std::vector<float> values(count);
    std::memcpy(values.data(), bytes.data() + dataStart, count * sizeof(float));
    if (fortran) {
        // Fortran order is x fastest, exactly DenseGrid's storage.
        grid.data() = std::move(values);
        return grid;
    }
    size_t i = 0;
    for (int x = 0; x < shape.x; ++x)
        for (int y = 0; y < shape.y; ++y)
            for (int z = 0; z < shape.z; ++z) grid.at({x, y, z}) = values[i++];
    return grid;
}

} // namespace voxc
