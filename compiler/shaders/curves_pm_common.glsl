// The Perona-Malik sweep passes' buffers: the normal field's two ping-pong halves are two
// bindings (each stays under a device's storage-binding limit where one buffer of both would not),
// push.size.w the source half.

layout(std430, set = 0, binding = 0) readonly buffer Flags { uint flags[]; }; // bit 0 set, bit 1 fixed
layout(std430, set = 0, binding = 1) buffer NormalsEven { float normalsEven[]; }; // half 0, xyz per cell
layout(std430, set = 0, binding = 2) buffer Units { float units[]; };             // xyz per cell
layout(std430, set = 0, binding = 3) buffer NormalsOdd { float normalsOdd[]; };   // half 1, xyz per cell

vec3 loadNormal(int source, uint i) {
    return source == 0 ? vec3(normalsEven[i * 3u], normalsEven[i * 3u + 1u], normalsEven[i * 3u + 2u])
                      : vec3(normalsOdd[i * 3u], normalsOdd[i * 3u + 1u], normalsOdd[i * 3u + 2u]);
}

void storeNormal(int source, uint i, vec3 v) {
    if (source == 0) normalsEven[i * 3u] = v.x, normalsEven[i * 3u + 1u] = v.y, normalsEven[i * 3u + 2u] = v.z;
    else normalsOdd[i * 3u] = v.x, normalsOdd[i * 3u + 1u] = v.y, normalsOdd[i * 3u + 2u] = v.z;
}

vec3 loadUnit(uint i) { return vec3(units[i * 3u], units[i * 3u + 1u], units[i * 3u + 2u]); }
