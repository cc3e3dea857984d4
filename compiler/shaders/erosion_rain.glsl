#version 450
// Rain (terrain::addRain): a drop adds intensity · w inside its disc (dx² + dy² <= R², integer
// cell indices, the drop drawn on the host by terrain::dropAt); uniform rain adds (dt · r) · w.
#include "erosion_common.glsl"

void main() {
    int i = cellOfInvocation();
    if (i < 0) return;
    float w = load(kRain, i);
    float d = load(kWater, i);
    if (push.mode.x == 0) {
        precise float uniformRain = d + push.values.x * w;
        store(kWater, i, uniformRain);
        return;
    }
    int x = i % push.grid.x, y = i / push.grid.x;
    precise float dx = float(x) - push.values.z;
    precise float dy = float(y) - push.values.w;
    precise float distanceSquared = dx * dx + dy * dy;
    if (distanceSquared <= push.values.y) {
        precise float rained = d + push.values.x * w;
        store(kWater, i, rained);
    }
}
