#include "voxc/builtins/Shapes.h"

#include "functions/NoiseCommon.h"
#include "voxc/program/Random.h"

#include <cmath>

namespace voxc {

namespace {

// Ken Perlin's reference permutation (Improved Noise, 2002).
const int kPermutation[256] = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103, 30,  69,  142,
    8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,  197, 62,  94,  252, 219, 203,
    117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174, 20,  125, 136, 171, 168, 68,  175, 74,  165,
    71,  134, 139, 48,  27,  166, 77,  146, 158, 231, 83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,
    55,  46,  245, 40,  244, 102, 143, 54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,
    18,  169, 200, 196, 135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250,
    124, 123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,  182, 189,
    28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,
    129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104, 218, 246, 97,  228, 251, 34,
    242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,  51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,
    181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114,
    67,  29,  24,  72,  243, 141, 128, 195, 78,  66,  215, 61,  156, 180};

// Eight 2D gradient directions: the four diagonals and the four axes.
float gradient(int hash, float x, float y) {
    switch (hash & 7) {
    case 0: return x + y;
    case 1: return -x + y;
    case 2: return x - y;
    case 3: return -x - y;
    case 4: return x;
    case 5: return -x;
    case 6: return y;
    default: return -y;
    }
}

} // namespace

std::span<const int, 256> perlinPermutation() { return kPermutation; }

float perlin2(float x, float y) {
    const float fx = std::floor(x);
    const float fy = std::floor(y);
    const int X = int(fx) & 255;
    const int Y = int(fy) & 255;
    const float xf = x - fx;
    const float yf = y - fy;
    const float u = noise::fade(xf);
    const float v = noise::fade(yf);
    const int aa = noise::perm(noise::perm(X) + Y);
    const int ab = noise::perm(noise::perm(X) + Y + 1);
    const int ba = noise::perm(noise::perm(X + 1) + Y);
    const int bb = noise::perm(noise::perm(X + 1) + Y + 1);
    const float x1 = noise::lerp(u, gradient(aa, xf, yf), gradient(ba, xf - 1.0f, yf));
    const float x2 = noise::lerp(u, gradient(ab, xf, yf - 1.0f), gradient(bb, xf - 1.0f, yf - 1.0f));
    return noise::lerp(v, x1, x2);
}

float heightfieldHeight(const HeightfieldParams& params, uint32_t seed, int worldX, int worldZ) {
    float height = params.base;
    float amplitude = params.amplitude;
    float frequency = params.frequency;
    for (int octave = 0; octave < params.octaves; ++octave) {
        // Integer lattice offsets per octave decorrelate octaves and seeds without losing precision.
        const uint32_t h = mix32(seed ^ mix32(uint32_t(octave) + 0x68u));
        const float offsetX = float(h & 1023u);
        const float offsetZ = float((h >> 10) & 1023u);
        height = height + amplitude * perlin2(float(worldX) * frequency + offsetX, float(worldZ) * frequency + offsetZ);
        amplitude = amplitude * params.gain;
        frequency = frequency * params.lacunarity;
    }
    return height;
}

} // namespace voxc
