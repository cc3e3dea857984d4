#pragma once
// Fractal noise along a row of points whose y and z are the same: the host's field rows
// (voxc/interp/FieldRows.h) evaluate fbm, turbulence, ridged and perlin3 of a position this way.
// Each result equals the builtin's single-point evaluation bit for bit (tests/interp FieldRows).
// Why a row: with y and z fixed, a perlin3's hashes and gradients belong to the lattice cell
// along x, not to the point. Per octave the row's cells get a table (their hashes made once for
// every row of the same y and z cells, the gradients' y and z parts once per row) and each point
// pays only its x fraction, eight gradient sums and seven lerps. Where the CPU has AVX-512,
// sixteen points read their cells' entries by register permutes, or by broadcasts when they
// share one cell.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace voxc {

// How an octave's noise n becomes its term (noise::fbm, noise::turbulence, noise::ridged).
enum class FractalFold : uint8_t { Sum, Absolute, Ridged };

// Reusable tables of one thread's rows: no allocation per row once the widest row was seen.
class FractalRow {
public:
    // out[i] = the fractal of `fold` at (x[i], y, z) for i < n: fbm (Sum), turbulence (Absolute)
    // or ridged with these octaves, lacunarity, gain and seed; perlin3(p, seed) is Sum with one octave.
    void evaluate(FractalFold fold, const float* x, float y, float z, int32_t octaves, float lacunarity, float gain,
                  uint32_t seed, size_t n, float* out);

    // The lowest and highest finite x of a row (lo > hi: none), and whether all are finite.
    struct PointRange {
        float lo = INFINITY, hi = -INFINITY;
        bool allFinite = true;
        bool empty() const { return !(lo <= hi); }
    };
    // What an octave's points do with their noise n: `store` it, or add its term (amplitude * n,
    // amplitude * |n| for Absolute) to the sum, the `first` octave setting it.
    struct OctaveTerm {
        FractalFold fold;
        float amplitude;
        bool first;
        bool store;
    };

private:
    // evaluate's body, compiled for each instruction set (voxc::atHostSimd).
    static void octaveSum(FractalRow& row, FractalFold fold, const float* x, float y, float z, int32_t octaves,
                          float lacunarity, float gain, uint32_t seed, size_t n, float* out);
    // The fractal's octave `octave`: perlin3((x[i] * frequency, qy, qz), seed) into out[i] by `term`.
    static void perlinOctave(FractalRow& row, int32_t octave, const float* x, float frequency, PointRange range,
                             float qy, float qz, uint32_t seed, OctaveTerm term, size_t n, float* out);

    // One octave's gradient hashes along a row of lattice y Y, per corner (y0z0, y1z0, y0z1,
    // y1z1) and lattice x: the same for every row whose y lies in that lattice cell, whose z lies
    // in the same cell and whose points span the same cells, so made once for all of them.
    struct RowHashes {
        bool made = false;
        uint32_t seed = 0;
        int X0 = 0, Z = 0;
        size_t entries = 0;
        std::vector<int32_t> hashes;         // [corner * stride + j]: the hash & 15
        std::vector<float> lowCoefficients;  // its gradient's coefficient of x, at a cell's low corner
        std::vector<float> highCoefficients; // ... and at a cell's high corner (x - 1)
    };

    std::vector<float> scaled_;                  // x[i] * frequency
    std::vector<float> noise_;                   // one octave's perlin3
    std::vector<float> weight_;                  // ridged's weight per point
    std::vector<float> parts_;                   // [corner * stride + j]: the gradient without its x term
    std::vector<RowHashes> rowHashes_;           // [octave * 256 + Y], made as rows need them
};

} // namespace voxc
