#pragma once
// Writers of the files heightmap and mesh blocks read, for tests that make their inputs from
// analytic functions and shapes: greyscale PNG (libpng), .npy, float TIFF (libtiff), glTF binary,
// OBJ and PLY, and the two test shapes (an icosphere and a box).
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <png.h>
#include <tiffio.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace voxc::test {

inline void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

inline std::string readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// A PNG of `height` rows, each of width * channels * depth / 8 bytes, written by fillRow(y, row).
inline std::string pngBytes(int width, int height, int depth, int colourType, int channels,
                            const std::function<void(int, std::vector<png_byte>&)>& fillRow) {
    std::string out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) throw std::runtime_error("libpng failed");
    png_set_write_fn(
        png, &out,
        [](png_structp p, png_bytep data, png_size_t n) {
            static_cast<std::string*>(png_get_io_ptr(p))->append(reinterpret_cast<const char*>(data), n);
        },
        [](png_structp) {});
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), depth, colourType, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    std::vector<png_byte> row(size_t(width) * size_t(channels) * size_t(depth / 8));
    for (int y = 0; y < height; ++y) {
        fillRow(y, row);
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return out;
}

// Row-major pixels (row 0 first), 8 or 16 bits.
inline std::string greyPng(int width, int height, const std::vector<uint16_t>& pixels, int depth) {
    return pngBytes(width, height, depth, PNG_COLOR_TYPE_GRAY, 1, [&](int y, std::vector<png_byte>& row) {
        for (int x = 0; x < width; ++x) {
            const uint16_t v = pixels[size_t(y) * size_t(width) + size_t(x)];
            if (depth == 8) row[size_t(x)] = png_byte(v);
            else row[2 * size_t(x)] = png_byte(v >> 8), row[2 * size_t(x) + 1] = png_byte(v & 0xFF);
        }
    });
}

// An 8-bit RGB image of one grey (100, 100, 100): a valid PNG a heightmap does not take.
inline std::string rgbPng(int width, int height) {
    return pngBytes(width, height, 8, PNG_COLOR_TYPE_RGB, 3,
                    [](int, std::vector<png_byte>& row) { std::fill(row.begin(), row.end(), png_byte(100)); });
}

// A C-order .npy of shape (rows, columns) (or any `shape` text) holding `data`'s bytes.
inline std::string npy(const std::string& descr, const std::string& shape, const std::string& data) {
    std::string header = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
    while ((10 + header.size() + 1) % 64 != 0) header += ' ';
    header += '\n';
    std::string out = "\x93NUMPY";
    out += char(1), out += char(0);
    out += char(header.size() & 0xFF), out += char(header.size() >> 8);
    return out + header + data;
}

template <typename T>
std::string bytesOf(const std::vector<T>& values) {
    return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// A 32-bit float greyscale TIFF in strips, written by libtiff to `path`.
inline void floatTiff(const std::filesystem::path& path, int width, int height, const std::vector<float>& pixels) {
    TIFF* tiff = TIFFOpen(path.c_str(), "w");
    if (!tiff) throw std::runtime_error("cannot write " + path.string());
    TIFFSetField(tiff, TIFFTAG_IMAGEWIDTH, uint32_t(width));
    TIFFSetField(tiff, TIFFTAG_IMAGELENGTH, uint32_t(height));
    TIFFSetField(tiff, TIFFTAG_SAMPLESPERPIXEL, uint16_t(1));
    TIFFSetField(tiff, TIFFTAG_BITSPERSAMPLE, uint16_t(32));
    TIFFSetField(tiff, TIFFTAG_SAMPLEFORMAT, uint16_t(SAMPLEFORMAT_IEEEFP));
    TIFFSetField(tiff, TIFFTAG_PHOTOMETRIC, uint16_t(PHOTOMETRIC_MINISBLACK));
    TIFFSetField(tiff, TIFFTAG_PLANARCONFIG, uint16_t(PLANARCONFIG_CONTIG));
    TIFFSetField(tiff, TIFFTAG_ROWSPERSTRIP, uint32_t(4));
    for (int y = 0; y < height; ++y) {
        std::vector<float> row(pixels.begin() + y * width, pixels.begin() + (y + 1) * width);
        TIFFWriteScanline(tiff, row.data(), uint32_t(y), 0);
    }
    TIFFClose(tiff);
}

struct Shape {
    std::vector<glm::vec3> points;
    std::vector<glm::uvec3> triangles;
};

// An icosahedron subdivided `levels` times, projected onto the sphere of `radius` at the origin.
inline Shape icosphere(float radius, int levels) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    Shape s;
    for (glm::vec3 p : {glm::vec3(-1, t, 0), glm::vec3(1, t, 0), glm::vec3(-1, -t, 0), glm::vec3(1, -t, 0),
                        glm::vec3(0, -1, t), glm::vec3(0, 1, t), glm::vec3(0, -1, -t), glm::vec3(0, 1, -t),
                        glm::vec3(t, 0, -1), glm::vec3(t, 0, 1), glm::vec3(-t, 0, -1), glm::vec3(-t, 0, 1)})
        s.points.push_back(p / std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z));
    s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> middles;
        const auto middle = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto [it, inserted] = middles.emplace(key, uint32_t(s.points.size()));
            if (inserted) {
                const glm::vec3 m = (s.points[a] + s.points[b]) * 0.5f;
                s.points.push_back(m / std::sqrt(m.x * m.x + m.y * m.y + m.z * m.z));
            }
            return it->second;
        };
        std::vector<glm::uvec3> next;
        for (const glm::uvec3& f : s.triangles) {
            const uint32_t a = middle(f.x, f.y), b = middle(f.y, f.z), c = middle(f.z, f.x);
            next.insert(next.end(), {{f.x, a, c}, {f.y, b, a}, {f.z, c, b}, {a, b, c}});
        }
        s.triangles = std::move(next);
    }
    for (glm::vec3& p : s.points) p *= radius;
    return s;
}

// The box [lo, hi], two triangles a face, outward.
inline Shape box(glm::vec3 lo, glm::vec3 hi) {
    Shape s;
    for (int i = 0; i < 8; ++i) s.points.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        s.triangles.push_back({q[0], q[1], q[2]});
        s.triangles.push_back({q[0], q[2], q[3]});
    }
    return s;
}

// A glTF binary: one mesh, one triangle primitive, float positions and uint32 indices in one
// buffer. `dropBuffer` leaves the BIN chunk out while the JSON still names the buffer.
inline std::string glb(const Shape& shape, bool dropBuffer = false) {
    std::string bin = bytesOf(shape.points) + bytesOf(shape.triangles);
    while (bin.size() % 4) bin += '\0';
    glm::vec3 lo = shape.points[0], hi = shape.points[0];
    for (const glm::vec3& p : shape.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const size_t pointBytes = shape.points.size() * 12;
    nlohmann::json json = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"mode", 4}}}}}}},
        {"buffers", {{{"byteLength", bin.size()}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", pointBytes}},
          {{"buffer", 0}, {"byteOffset", pointBytes}, {"byteLength", shape.triangles.size() * 12}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", shape.points.size()}, {"type", "VEC3"},
           {"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}},
          {{"bufferView", 1}, {"componentType", 5125}, {"count", shape.triangles.size() * 3}, {"type", "SCALAR"}}}}};
    std::string text = json.dump();
    while (text.size() % 4) text += ' ';
    const auto word = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    std::string out = "glTF" + word(2) + word(0);
    out += word(uint32_t(text.size())) + "JSON" + text;
    if (!dropBuffer) out += word(uint32_t(bin.size())) + std::string("BIN\0", 4) + bin;
    const uint32_t length = uint32_t(out.size());
    std::memcpy(out.data() + 8, &length, 4);
    return out;
}

inline std::string obj(const Shape& shape) {
    std::string out = "# test shape\n";
    for (const glm::vec3& p : shape.points) out += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    for (const glm::uvec3& t : shape.triangles)
        out += "f " + std::to_string(t.x + 1) + " " + std::to_string(t.y + 1) + " " + std::to_string(t.z + 1) + "\n";
    return out;
}

// Binary little-endian PLY.
inline std::string ply(const Shape& shape) {
    std::string out = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(shape.points.size()) +
                      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                      std::to_string(shape.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
    out += bytesOf(shape.points);
    for (const glm::uvec3& t : shape.triangles) {
        out += char(3);
        out += bytesOf(std::vector<int32_t>{int32_t(t.x), int32_t(t.y), int32_t(t.z)});
    }
    return out;
}

} // namespace voxc::test
