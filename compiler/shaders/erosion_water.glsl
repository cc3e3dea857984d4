#version 450
// Water and velocity (terrain::updateWaterAndVelocity): d2 = d1 + (dt·(in − out)) / l_x², and
// where the mean depth exceeds 1e-6 the velocity from the mean of the through-flows, clamped to
// ±(0.5·l_x)/dt.
#include "erosion_common.glsl"

float fluxOrZero(int channel, int x, int y) {
    return (x < 0 || y < 0 || x >= push.grid.x || y >= push.grid.y) ? 0.0 : load(channel, x, y);
}

void main() {
    int i = cellOfInvocation();
    if (i < 0) return;
    int x = i % push.grid.x, y = i / push.grid.x;
    float fl = load(kFluxL, i), fr = load(kFluxR, i), ft = load(kFluxT, i), fb = load(kFluxB, i);
    float inRight = fluxOrZero(kFluxR, x - 1, y), inLeft = fluxOrZero(kFluxL, x + 1, y);
    float inTop = fluxOrZero(kFluxT, x, y - 1), inBottom = fluxOrZero(kFluxB, x, y + 1);
    precise float inflow = ((inRight + inLeft) + inTop) + inBottom;
    precise float outflow = ((fl + fr) + ft) + fb;
    float d1 = load(kWater, i);
    precise float change = (constant(kDt) * (inflow - outflow)) / constant(kArea);
    precise float d2 = d1 + change;
    precise float mean = (d1 + d2) * 0.5;
    float u = 0.0, v = 0.0;
    if (mean > 1e-6) {
        precise float flowX = 0.5 * ((inRight - fl) + (fr - inLeft));
        precise float flowY = 0.5 * ((inTop - fb) + (ft - inBottom));
        precise float depth = constant(kCellSize) * mean;
        precise float rawU = flowX / depth;
        precise float rawV = flowY / depth;
        float limit = constant(kSpeedLimit);
        u = stdClamp(rawU, -limit, limit);
        v = stdClamp(rawV, -limit, limit);
    }
    store(kWater, i, d2);
    store(kVelocityU, i, u);
    store(kVelocityV, i, v);
}
