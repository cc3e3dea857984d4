// fbm, turbulence and perlin3 along a field kernel's column: the same bits as noiseOctaveSum
// (noise_fractal.glsl) and noisePerlin3 for every voxel, with the work shared where it can be.
// Why: on llvmpipe a perlin3 is mostly its seven permutation reads (a private-array gather each)
// and its eight gradient selections. The codegen (FieldKernel.cpp) takes this path for a call
// whose argument's x and z are the same along the column and whose y depends on y alone, so per
// octave the x/z lattice work is done once per column, the hashes and the gradients' x/z parts
// once per lattice cell along y (loops whose trip counts are the same in every lane, so llvmpipe
// really skips), and each voxel pays only its y fraction, eight adds and seven lerps.
// Requires noise_common.glsl, noise_permutation.glsl, noise_perlin3.glsl and, from the kernel,
// COLUMN_BLOCK, the array noiseColumnValues[sites][COLUMN_BLOCK] and noiseColumnArgY(site, y): the
// argument's y at voxel y.

// One octave's column constants: the scaled x and z, their lattice cells and fade weights.
struct NoiseColumnOctave {
    bool finiteXZ;
    float x, x1, z, z1, u, w;
    int X, Z;
    ivec2 hX;
    int offsetY;
};

NoiseColumnOctave noiseColumnOctave(float px, float pz, float frequency, uint seed) {
    NoiseColumnOctave o;
    precise float qx = px * frequency;
    precise float qz = pz * frequency;
    o.finiteXZ = isFiniteFloat(qx) && isFiniteFloat(qz);
    precise float fx = floor(qx);
    precise float fz = floor(qz);
    precise float x = qx - fx;
    precise float z = qz - fz;
    precise float x1 = x - 1.0;
    precise float z1 = z - 1.0;
    o.x = x;
    o.z = z;
    o.x1 = x1;
    o.z1 = z1;
    o.u = noiseFade(x);
    o.w = noiseFade(z);
    ivec3 offset = noiseSeedOffset(seed);
    o.X = (noiseLatticeIndex(fx) + offset.x) & 255;
    o.Z = (noiseLatticeIndex(fz) + offset.z) & 255;
    o.hX = noisePermPair(o.X);
    o.offsetY = offset.y;
    return o;
}

// noiseGrad(hash, x, y, z) with x and z fixed: (+-u) + (+-v) where at most one of u, v is y, so it
// is part + (+-y) (IEEE addition commutes) or, without y, the constant part itself.
struct NoiseColumnGradient {
    float part;
    uint ySign; // XORed into y's bits: the sign flip of -y
    bool usesY;
};

NoiseColumnGradient noiseColumnGradient(int hash, float x, float z) {
    int h = hash & 15;
    uint uSign = uint(h) << 31;                  // (h & 1) != 0: -u
    uint vSign = (uint(h) << 30) & 0x80000000u;  // (h & 2) != 0: -v
    NoiseColumnGradient g;
    if (h < 4) { // u = x, v = y
        g.part = uintBitsToFloat(floatBitsToUint(x) ^ uSign);
        g.ySign = vSign;
        g.usesY = true;
    } else if (h >= 8) { // u = y, v = x (h = 12, 14) or z
        g.part = uintBitsToFloat(floatBitsToUint((h & 13) == 12 ? x : z) ^ vSign);
        g.ySign = uSign;
        g.usesY = true;
    } else { // u = x, v = z
        precise float r = uintBitsToFloat(floatBitsToUint(x) ^ uSign) + uintBitsToFloat(floatBitsToUint(z) ^ vSign);
        g.part = r;
        g.ySign = 0u;
        g.usesY = false;
    }
    return g;
}

float noiseColumnGradientAt(NoiseColumnGradient g, float y) {
    precise float r = g.part + uintBitsToFloat(floatBitsToUint(y) ^ g.ySign);
    return g.usesY ? r : g.part;
}

// The eight corners' gradients of one lattice cell, in noisePerlin3's corner order.
struct NoiseColumnCell {
    NoiseColumnGradient g000, g100, g010, g110, g001, g101, g011, g111;
};

NoiseColumnCell noiseColumnCell(NoiseColumnOctave o, float fy) {
    int Y = (noiseLatticeIndex(fy) + o.offsetY) & 255;
    ivec2 hA = noisePermPair(o.hX.x + Y);
    ivec2 hB = noisePermPair(o.hX.y + Y);
    ivec2 hAA = noisePermPair(hA.x + o.Z);
    ivec2 hAB = noisePermPair(hA.y + o.Z);
    ivec2 hBA = noisePermPair(hB.x + o.Z);
    ivec2 hBB = noisePermPair(hB.y + o.Z);
    NoiseColumnCell c;
    c.g000 = noiseColumnGradient(hAA.x, o.x, o.z);
    c.g100 = noiseColumnGradient(hBA.x, o.x1, o.z);
    c.g010 = noiseColumnGradient(hAB.x, o.x, o.z);
    c.g110 = noiseColumnGradient(hBB.x, o.x1, o.z);
    c.g001 = noiseColumnGradient(hAA.y, o.x, o.z1);
    c.g101 = noiseColumnGradient(hBA.y, o.x1, o.z1);
    c.g011 = noiseColumnGradient(hAB.y, o.x, o.z1);
    c.g111 = noiseColumnGradient(hBB.y, o.x1, o.z1);
    return c;
}

// noisePerlin3 at (x, qy, z) of the octave, qy in the cell whose floor is fy.
float noiseColumnPerlin(NoiseColumnOctave o, NoiseColumnCell c, float qy, float fy) {
    if (!(o.finiteXZ && isFiniteFloat(qy))) return noiseNaN();
    precise float y = qy - fy;
    precise float y1 = y - 1.0;
    float v = noiseFade(y);
    float l00 = noiseLerp(o.u, noiseColumnGradientAt(c.g000, y), noiseColumnGradientAt(c.g100, y));
    float l10 = noiseLerp(o.u, noiseColumnGradientAt(c.g010, y1), noiseColumnGradientAt(c.g110, y1));
    float l01 = noiseLerp(o.u, noiseColumnGradientAt(c.g001, y), noiseColumnGradientAt(c.g101, y));
    float l11 = noiseLerp(o.u, noiseColumnGradientAt(c.g011, y1), noiseColumnGradientAt(c.g111, y1));
    return noiseLerp(o.w, noiseLerp(v, l00, l10), noiseLerp(v, l01, l11));
}

// noiseColumnValues[site][y - firstY] = noiseOctaveSum(p, ...) of kind 0 (fbm) or 1 (turbulence)
// for firstY <= y < lastY, p = (px, noiseColumnArgY(site, y), pz). Octave by octave, each voxel's
// sum takes its terms in noiseOctaveSum's order, so the same bits.
void noiseColumnFill(int site, int firstY, int lastY, float px, float pz, int octaves, float lacunarity, float gain,
                     uint seed, int kind) {
    precise float amplitude = 1.0;
    precise float frequency = 1.0;
    int count = min(max(octaves, 1), 16);
    for (int k = 0; k < count; ++k) {
        NoiseColumnOctave o = noiseColumnOctave(px, pz, frequency, noiseSubstream(seed, uint(k)));
        int y = firstY;
        precise float qy = noiseColumnArgY(site, y) * frequency;
        while (y < lastY) {
            precise float fy = floor(qy);
            NoiseColumnCell cell = noiseColumnCell(o, fy);
            bool inCell = true;
            while (inCell) {
                float n = noiseColumnPerlin(o, cell, qy, fy);
                precise float weighted = amplitude * (kind == 0 ? n : abs(n));
                float before = noiseColumnValues[site][y - firstY];
                precise float sum = before + weighted;
                noiseColumnValues[site][y - firstY] = k == 0 ? weighted : sum;
                ++y;
                qy = noiseColumnArgY(site, y) * frequency;
                // Not `floor(qy) == fy` for a non-finite qy: NaN never equals, so each such voxel is a cell.
                inCell = y < lastY && floor(qy) == fy;
            }
        }
        amplitude = amplitude * gain;
        frequency = frequency * lacunarity;
    }
}
