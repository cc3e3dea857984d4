// Declarations every multigrid pass shares (runtime/vulkan/src/GpuMultigrid.cpp builds the
// passes into a SolveProgram; the host schedule they reproduce is compiler/generators/src/curves/
// Multigrid.cpp, docs/curves.md "Linear solves"). COMPONENTS (2 or 3) is defined before this.
// Every level's cells sit at push offsets in one array per quantity (x fastest, then y, then z).
// Every float result is `precise`: the host computes the same operations in the same order
// without fused multiply-adds, so lavapipe's results are bit for bit the host's.

layout(push_constant) uniform Push {
    ivec4 fine;   // xyz: the level a pass works on (the finer of two); w: its first cell
    ivec4 coarse; // xyz: the next coarser level; w: its first cell
    ivec4 halved; // xyz: 1 where the coarse level halves the axis; w: colour / mode / add
    vec4 weight;  // xyz: the fine level's stencil weight per axis (4^-scale); w: the smoother's over-relaxation
} push;

layout(std430, set = 0, binding = 0) readonly buffer Mask { uint fixedCell[]; };
// Per cell its COMPONENTS values side by side: one buffer, no per-component selection.
layout(std430, set = 0, binding = 1) buffer Unknowns { float u[]; };
layout(std430, set = 0, binding = 2) buffer RightHandSides { float f[]; };
layout(std430, set = 0, binding = 3) buffer Measure { uint maxResidualBits; };

float loadU(int c, uint i) { return u[i * uint(COMPONENTS) + uint(c)]; }
float loadF(int c, uint i) { return f[i * uint(COMPONENTS) + uint(c)]; }
void storeU(int c, uint i, float v) { u[i * uint(COMPONENTS) + uint(c)] = v; }
void storeF(int c, uint i, float v) { f[i * uint(COMPONENTS) + uint(c)] = v; }

uint cellIndex(ivec4 level, ivec3 p) { return uint(level.w + p.x + level.x * (p.y + level.y * p.z)); }

// f - sum_j w_j (u_j - u_i) over the in-box neighbours in the order -x, +x, -y, +y, -z, +z.
float residualAt(int c, ivec3 p, uint i, float f) {
    const ivec4 l = push.fine;
    const uint row = uint(l.x), slice = uint(l.x * l.y);
    const float ui = loadU(c, i);
    precise float lap = 0.0;
    if (p.x > 0) lap += push.weight.x * (loadU(c, i - 1u) - ui);
    if (p.x + 1 < l.x) lap += push.weight.x * (loadU(c, i + 1u) - ui);
    if (p.y > 0) lap += push.weight.y * (loadU(c, i - row) - ui);
    if (p.y + 1 < l.y) lap += push.weight.y * (loadU(c, i + row) - ui);
    if (p.z > 0) lap += push.weight.z * (loadU(c, i - slice) - ui);
    if (p.z + 1 < l.z) lap += push.weight.z * (loadU(c, i + slice) - ui);
    precise float r = f - lap;
    return r;
}
