#version 450
// <<COMPONENTS>>
#include "mg_common.glsl"
// Multigrid pass: one invocation per cell of level push.coarse, over its children in level
// push.fine (z, then y, then x order, as the host's sum). Mode push.halved.w:
//   0: the mean of the children's residuals (0 at fixed children) becomes the coarse right-hand
//      side, and the coarse correction starts at 0 (every cell, fixed ones too);
//   1: the mean of the fixed children's values becomes the coarse value, 0 without any (the
//      full-multigrid start's Dirichlet values).

layout(local_size_x = 64) in;

void main() {
    const ivec4 cl = push.coarse;
    const ivec3 q = ivec3(gl_GlobalInvocationID);
    if (q.x >= cl.x || q.y >= cl.y || q.z >= cl.z) return;
    const ivec3 h = push.halved.xyz;
    const ivec3 first = q << h;
    const ivec3 last = min(first + h, push.fine.xyz - 1);
    const uint ci = cellIndex(cl, q);
    const bool residuals = push.halved.w == 0;
    for (int c = 0; c < COMPONENTS; ++c) {
        precise float sum = 0.0;
        int count = 0;
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x) {
                    const ivec3 p = ivec3(x, y, z);
                    const uint i = cellIndex(push.fine, p);
                    const bool pinned = fixedCell[i] != 0u;
                    if (residuals) {
                        sum += pinned ? 0.0 : residualAt(c, p, i, loadF(c, i));
                        ++count;
                    } else if (pinned) {
                        sum += loadU(c, i);
                        ++count;
                    }
                }
        precise float mean = count > 0 ? sum / float(count) : 0.0;
        if (residuals) {
            storeF(c, ci, mean);
            storeU(c, ci, 0.0);
        } else {
            storeU(c, ci, mean);
        }
    }
}
