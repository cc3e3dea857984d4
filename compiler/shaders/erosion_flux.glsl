#version 450
// Outflow fluxes (terrain::updateFlux): f' = max(0, f + (((dt·A)·g)·(h − h_D)) / l) towards each
// neighbour inside the grid, 0 outside; scaled by K = min(1, (d·l_x²) / (Σf'·dt)) when Σf' > 0.
#include "erosion_common.glsl"

float outflow(float flux, float level, int nx, int ny) {
    if (nx < 0 || ny < 0 || nx >= push.grid.x || ny >= push.grid.y) return 0.0;
    precise float drop = level - load(kSurface, nx, ny);
    precise float change = (constant(kCoefficient) * drop) / constant(kPipeLength);
    precise float raised = flux + change;
    return stdMax(0.0, raised);
}

void main() {
    int i = cellOfInvocation();
    if (i < 0) return;
    int x = i % push.grid.x, y = i / push.grid.x;
    float d = load(kWater, i);
    float level = load(kSurface, i);
    precise float fl = outflow(load(kFluxL, i), level, x - 1, y);
    precise float fr = outflow(load(kFluxR, i), level, x + 1, y);
    precise float ft = outflow(load(kFluxT, i), level, x, y + 1);
    precise float fb = outflow(load(kFluxB, i), level, x, y - 1);
    precise float total = ((fl + fr) + ft) + fb;
    if (total > 0.0) {
        precise float held = d * constant(kArea);
        precise float leaving = total * constant(kDt);
        precise float ratio = held / leaving;
        float k = stdMin(1.0, ratio);
        fl = k * fl;
        fr = k * fr;
        ft = k * ft;
        fb = k * fb;
    }
    store(kFluxL, i, fl);
    store(kFluxR, i, fr);
    store(kFluxT, i, ft);
    store(kFluxB, i, fb);
}
