#version 450
// <<COMPONENTS>>
#include "mg_common.glsl"
// Multigrid pass: one red-black over-relaxed Gauss-Seidel half sweep on level push.fine, colour
// push.halved.w (cells with (x + y + z) & 1 == colour). u_i += omega * (g - u_i), omega =
// push.weight.w, g = (sum_j w_j u_j - f_i) / sum_j w_j over the in-box neighbours, both sums
// from 0 in neighbour order; fixed cells keep their values. A
// colour's cells read only the other colour, so the parallel sweep is the host's serial one.
// One invocation per cell of the colour: x = 2 * id.x + parity.

layout(local_size_x = 64) in;

void main() {
    const ivec4 l = push.fine;
    const int y = int(gl_GlobalInvocationID.y), z = int(gl_GlobalInvocationID.z);
    const int x = 2 * int(gl_GlobalInvocationID.x) + ((y + z + push.halved.w) & 1);
    if (x >= l.x || y >= l.y || z >= l.z) return;
    const ivec3 p = ivec3(x, y, z);
    const uint i = cellIndex(l, p);
    if (fixedCell[i] != 0u) return;
    const uint row = uint(l.x), slice = uint(l.x * l.y);
    for (int c = 0; c < COMPONENTS; ++c) {
        precise float sum = 0.0, weights = 0.0;
        if (p.x > 0) { sum += push.weight.x * loadU(c, i - 1u); weights += push.weight.x; }
        if (p.x + 1 < l.x) { sum += push.weight.x * loadU(c, i + 1u); weights += push.weight.x; }
        if (p.y > 0) { sum += push.weight.y * loadU(c, i - row); weights += push.weight.y; }
        if (p.y + 1 < l.y) { sum += push.weight.y * loadU(c, i + row); weights += push.weight.y; }
        if (p.z > 0) { sum += push.weight.z * loadU(c, i - slice); weights += push.weight.z; }
        if (p.z + 1 < l.z) { sum += push.weight.z * loadU(c, i + slice); weights += push.weight.z; }
        if (weights > 0.0) {
            const float ui = loadU(c, i);
            precise float gaussSeidel = (sum - loadF(c, i)) / weights;
            precise float value = ui + push.weight.w * (gaussSeidel - ui);
            storeU(c, i, value);
        }
    }
}
