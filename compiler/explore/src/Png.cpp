#include "voxc/explore/Png.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"

#include <zlib.h>

namespace voxc::explore {

namespace {

void appendBigEndian(std::string& out, uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(char((value >> shift) & 0xFF));
}

// length, type, data, CRC-32 of type and data.
void appendChunk(std::string& out, const char type[4], const std::string& data) {
    appendBigEndian(out, uint32_t(data.size()));
    const std::string typed = std::string(type, 4) + data;
    out += typed;
    appendBigEndian(out, uint32_t(crc32(0L, reinterpret_cast<const Bytef*>(typed.data()), uInt(typed.size()))));
}

} // namespace

std::string encodePng(const Image& image) {
    std::string header;
    appendBigEndian(header, uint32_t(image.width));
    appendBigEndian(header, uint32_t(image.height));
    header += std::string("\x08\x02\x00\x00\x00", 5); // bit depth 8, truecolour, deflate, filter 0, no interlace

    const size_t rowBytes = size_t(image.width) * 3;
    std::string raw;
    raw.reserve((rowBytes + 1) * size_t(image.height));
    for (int y = 0; y < image.height; ++y) {
        raw.push_back('\0'); // filter type None
        raw.append(reinterpret_cast<const char*>(image.rgb.data()) + size_t(y) * rowBytes, rowBytes);
    }
    uLongf compressedSize = compressBound(uLong(raw.size()));
    std::string compressed(compressedSize, '\0');
    if (compress2(reinterpret_cast<Bytef*>(compressed.data()), &compressedSize,
                  reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()), Z_BEST_COMPRESSION) != Z_OK)
        throw InternalError("zlib could not compress the PNG image data");
    compressed.resize(compressedSize);

    std::string png("\x89PNG\r\n\x1a\n", 8);
    appendChunk(png, "IHDR", header);
    appendChunk(png, "IDAT", compressed);
    appendChunk(png, "IEND", "");
    return png;
}

void writePng(const std::string& path, const Image& image) { writeFileAtomically(path, encodePng(image)); }

} // namespace voxc::explore
