#version 450
// Erosion and deposition (terrain::erodeAndDeposit): the tilt from the bed (surface without
// water, clamped neighbours), the capacity C = (((K_c·sinφ)·|V|)·s(x, y))·room, then the amount
// moved between S_h and the suspended sediment, clamped by the depth limit E. Writes the other
// S_h channel (ping-pong) and the suspended sediment.
#include "erosion_common.glsl"

float bedAt(int x, int y) {
    return load(kSurface, clamp(x, 0, push.grid.x - 1), clamp(y, 0, push.grid.y - 1));
}

void main() {
    int i = cellOfInvocation();
    if (i < 0) return;
    int x = i % push.grid.x, y = i / push.grid.x;
    float b = load(kSurface, i);
    precise float riseX = b - stdMin(bedAt(x - 1, y), bedAt(x + 1, y));
    precise float riseY = b - stdMin(bedAt(x, y - 1), bedAt(x, y + 1));
    float px = stdClamp(riseX, 0.0, 1.0);
    float py = stdClamp(riseY, 0.0, 1.0);
    precise float q = px * px + py * py;
    precise float tilt = sqrt(q / (1.0 + q));
    float sinTilt = stdMax(tilt, constant(kMinTilt));
    float u = load(kVelocityU, i), v = load(kVelocityV, i);
    precise float speed = sqrt(u * u + v * v);
    float sh = load(push.grid.z, i), s = load(kSediment, i);
    float e = constant(kDepthLimit);
    precise float headroom = (e - abs(sh)) / e;
    float room = constant(kLimited) != 0.0 ? stdMax(0.0, headroom) : 1.0;
    precise float c = (((constant(kCapacity) * sinTilt) * speed) * load(kCapacityField, i)) * room;
    if (c > s) {
        precise float wanted = constant(kSuspensionRate) * (c - s);
        precise float left = e + sh;
        float amount = stdMax(0.0, stdMin(wanted, left));
        precise float lowered = sh - amount;
        precise float lifted = s + amount;
        store(push.grid.w, i, lowered);
        store(kSuspended, i, lifted);
    } else {
        precise float wanted = constant(kDepositionRate) * (s - c);
        precise float left = e - sh;
        float amount = stdMax(0.0, stdMin(wanted, left));
        precise float raised = sh + amount;
        precise float dropped = s - amount;
        store(push.grid.w, i, raised);
        store(kSuspended, i, dropped);
    }
}
