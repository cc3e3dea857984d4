// Gradient noise: Perlin's improved noise and simplex noise (mirrors: noise_perlin3.glsl, noise_simplex3.glsl).
#include "Noise.h"
#include "NoiseCommon.h"

namespace voxc::noise {

uint32_t substream(uint32_t seed, uint32_t stream) { return seed + stream * 0x9E3779B9u; }

float perlin3(glm::vec3 p, uint32_t seed) {
    if (!finite(p)) return kNaN;
    const float fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
    const int X = (latticeIndex(fx) + seedOffset(seed, 0)) & 255;
    const int Y = (latticeIndex(fy) + seedOffset(seed, 1)) & 255;
    const int Z = (latticeIndex(fz) + seedOffset(seed, 2)) & 255;
    const float x = p.x - fx, y = p.y - fy, z = p.z - fz;
    const float u = fade(x), v = fade(y), w = fade(z);
    const int A = perm(X) + Y, AA = perm(A) + Z, AB = perm(A + 1) + Z;
    const int B = perm(X + 1) + Y, BA = perm(B) + Z, BB = perm(B + 1) + Z;
    const float x1 = x - 1.0f, y1 = y - 1.0f, z1 = z - 1.0f;
    const float l00 = lerp(u, grad(perm(AA), x, y, z), grad(perm(BA), x1, y, z));
    const float l10 = lerp(u, grad(perm(AB), x, y1, z), grad(perm(BB), x1, y1, z));
    const float l01 = lerp(u, grad(perm(AA + 1), x, y, z1), grad(perm(BA + 1), x1, y, z1));
    const float l11 = lerp(u, grad(perm(AB + 1), x, y1, z1), grad(perm(BB + 1), x1, y1, z1));
    return lerp(w, lerp(v, l00, l10), lerp(v, l01, l11));
}

namespace {

constexpr float kSkew = 0.333333343f;   // (sqrt(4) - 1) / 3 = 1/3, as a float
constexpr float kUnskew = 0.166666672f; // (1 - 1/sqrt(4)) / 3 = 1/6
constexpr float kSimplexScale = 76.0f;  // brings the extremes to about +-1 (measured, tests/functions)

// One corner's contribution: (0.5 - r^2)^4 * (gradient . offset), zero outside radius sqrt(0.5).
float simplexCorner(int hash, float x, float y, float z) {
    float t = 0.5f - x * x - y * y - z * z;
    if (t <= 0.0f) return 0.0f;
    t = t * t;
    return t * t * grad(hash, x, y, z);
}

} // namespace

float simplex3(glm::vec3 p, uint32_t seed) {
    // Skew to the cubic lattice, find the cell and the simplex inside it (by the order of the
    // offsets), unskew each corner back and sum the four corner kernels.
    const float s = (p.x + p.y + p.z) * kSkew;
    const float fi = std::floor(p.x + s), fj = std::floor(p.y + s), fk = std::floor(p.z + s);
    if (!finite({fi, fj, fk})) return kNaN; // p not finite, or the skew overflowed
    const float t = (fi + fj + fk) * kUnskew;
    const float x0 = p.x - (fi - t), y0 = p.y - (fj - t), z0 = p.z - (fk - t);
    int i1, j1, k1, i2, j2, k2;
    if (x0 >= y0) {
        if (y0 >= z0) { i1 = 1; j1 = 0; k1 = 0; i2 = 1; j2 = 1; k2 = 0; }
        else if (x0 >= z0) { i1 = 1; j1 = 0; k1 = 0; i2 = 1; j2 = 0; k2 = 1; }
        else { i1 = 0; j1 = 0; k1 = 1; i2 = 1; j2 = 0; k2 = 1; }
    } else {
        if (y0 < z0) { i1 = 0; j1 = 0; k1 = 1; i2 = 0; j2 = 1; k2 = 1; }
        else if (x0 < z0) { i1 = 0; j1 = 1; k1 = 0; i2 = 0; j2 = 1; k2 = 1; }
        else { i1 = 0; j1 = 1; k1 = 0; i2 = 1; j2 = 1; k2 = 0; }
    }
    const float x1 = x0 - float(i1) + kUnskew, y1 = y0 - float(j1) + kUnskew, z1 = z0 - float(k1) + kUnskew;
    const float x2 = x0 - float(i2) + 2.0f * kUnskew, y2 = y0 - float(j2) + 2.0f * kUnskew,
                z2 = z0 - float(k2) + 2.0f * kUnskew;
    const float x3 = x0 - 0.5f, y3 = y0 - 0.5f, z3 = z0 - 0.5f; // 1 - 3 * (1/6)
    const int I = latticeIndex(fi) + seedOffset(seed, 0);
    const int J = latticeIndex(fj) + seedOffset(seed, 1);
    const int K = latticeIndex(fk) + seedOffset(seed, 2);
    const auto hash = [&](int di, int dj, int dk) { return perm(I + di + perm(J + dj + perm(K + dk))); };
    const float n0 = simplexCorner(hash(0, 0, 0), x0, y0, z0);
    const float n1 = simplexCorner(hash(i1, j1, k1), x1, y1, z1);
    const float n2 = simplexCorner(hash(i2, j2, k2), x2, y2, z2);
    const float n3 = simplexCorner(hash(1, 1, 1), x3, y3, z3);
    return kSimplexScale * (n0 + n1 + n2 + n3);
}

} // namespace voxc::noise
