#version 450
// Sediment transport (terrain::transportSediment). `mei`: Mei's backward bilinear sample from the
// clamped departure point. `conservative`: the documented gather: the 3×3 sources in row-major
// order, each a source with sediment whose clamped arrival point's bilinear footprint covers this
// cell adding s1·(w_x·w_y), starting from +0 (the host scatters in the same order).
#include "erosion_common.glsl"

void main() {
    int i = cellOfInvocation();
    if (i < 0) return;
    int x = i % push.grid.x, y = i / push.grid.x;
    int w = push.grid.x, h = push.grid.y;
    float scale = constant(kDt);
    float cell = constant(kCellSize);
    if (push.mode.x != 0) {
        precise float backX = float(x) - (load(kVelocityU, i) * scale) / cell;
        precise float backY = float(y) - (load(kVelocityV, i) * scale) / cell;
        float sx = stdClamp(backX, 0.0, float(w - 1));
        float sy = stdClamp(backY, 0.0, float(h - 1));
        int x0 = int(floor(sx)), y0 = int(floor(sy));
        int x1 = min(x0 + 1, w - 1), y1 = min(y0 + 1, h - 1);
        precise float fx = sx - float(x0);
        precise float fy = sy - float(y0);
        precise float low = (1.0 - fx) * load(kSuspended, x0, y0) + fx * load(kSuspended, x1, y0);
        precise float high = (1.0 - fx) * load(kSuspended, x0, y1) + fx * load(kSuspended, x1, y1);
        precise float sampled = low * (1.0 - fy) + high * fy;
        store(kSediment, i, sampled);
        return;
    }
    precise float sum = 0.0;
    for (int sy = y - 1; sy <= y + 1; ++sy) {
        for (int sx = x - 1; sx <= x + 1; ++sx) {
            if (sx < 0 || sy < 0 || sx >= w || sy >= h) continue;
            float sediment = load(kSuspended, sx, sy);
            if (sediment == 0.0) continue;
            precise float aheadX = float(sx) + (load(kVelocityU, sx, sy) * scale) / cell;
            precise float aheadY = float(sy) + (load(kVelocityV, sx, sy) * scale) / cell;
            float tx = stdClamp(aheadX, 0.0, float(w - 1));
            float ty = stdClamp(aheadY, 0.0, float(h - 1));
            float floorX = floor(tx), floorY = floor(ty);
            precise float fx = tx - floorX;
            precise float fy = ty - floorY;
            precise float wx0 = 1.0 - fx;
            precise float wy0 = 1.0 - fy;
            int ix = int(floorX), iy = int(floorY);
            // The source's weights for this cell, as the host's scatter gives them (zero weights skipped).
            precise float weight = -1.0;
            if (iy == y) {
                if (ix == x) weight = wx0 * wy0;
                else if (ix + 1 == x && fx != 0.0) weight = fx * wy0;
            } else if (iy + 1 == y && fy != 0.0) {
                if (ix == x) weight = wx0 * fy;
                else if (ix + 1 == x && fx != 0.0) weight = fx * fy;
            }
            if (weight >= 0.0) sum = sum + sediment * weight;
        }
    }
    store(kSediment, i, sum);
}
