// Declarations the curves' solve passes share (runtime/vulkan/src/GpuCurves.cpp builds them into
// SolvePrograms; the host loops they reproduce are compiler/generators/src/curves/Diffuse.cpp and
// Propagate.cpp, docs/curves.md "What runs where"). Cells are x fastest, then y, then z. Every
// float result is `precise`: the host computes the same operations in the same order without
// fused multiply-adds, so lavapipe's results are the host's bit for bit.

layout(push_constant) uniform Push {
    ivec4 size;   // xyz: the box's cells per axis; w: the pass's source half / axis / rule
    ivec4 origin; // xyz: the box's first voxel (grid-local); w: the pass's second integer
    vec4 value;   // x: the pass's float (Perona-Malik k, noise frequency)
    ivec4 extra;  // x: the noise seed
} push;

// The six face neighbours in the fixed order of every host loop: -x, +x, -y, +y, -z, +z.
const ivec3 kNeighbours[6] = ivec3[6](ivec3(-1, 0, 0), ivec3(1, 0, 0), ivec3(0, -1, 0), ivec3(0, 1, 0),
                                      ivec3(0, 0, -1), ivec3(0, 0, 1));

uint cellCount() { return uint(push.size.x * push.size.y * push.size.z); }
uint cellIndex(ivec3 p) { return uint(p.x + push.size.x * (p.y + push.size.y * p.z)); }
ivec3 cellOf(uint i) {
    const uint row = uint(push.size.x), slice = uint(push.size.x * push.size.y);
    return ivec3(int(i % row), int(i / row % uint(push.size.y)), int(i / slice));
}
bool inBox(ivec3 p) { return all(greaterThanEqual(p, ivec3(0))) && all(lessThan(p, push.size.xyz)); }
// The cell of a one-invocation-per-cell dispatch (groups: ceil(x / 64), y, z), or -1 outside.
ivec3 dispatchedCell() {
    const ivec3 p = ivec3(gl_GlobalInvocationID);
    return inBox(p) ? p : ivec3(-1);
}
