#version 450
// GPU marching cubes, pass 4, one invocation per vertex (mc_compact.glsl lists each with its
// owner cell and axis, in global edge order, the mesh's vertex order): the crossing, normal and
// material of the vertex. The arithmetic is the CPU mesher's, operation for operation
// (`precise`: no fused multiply-adds), so positions and normals agree bit for bit where the
// device rounds as IEEE 754 requires. A vertex to an invocation keeps every lane busy (an
// invocation per cell ran the body of each axis any lane of its group owned).

layout(local_size_x = 64) in;

layout(set = 0, binding = 17) uniform usamplerBuffer vertexEdgeTexels; // per vertex: its owner cell's slot | axis << 30
// Seven words per vertex: position xyz and normal xyz (float bits), material.
layout(std430, set = 0, binding = 6) writeonly buffer Vertices {
    uint word[];
} vertices;

// The samples a vertex reads (its edge's lower sample - 1 to its upper sample + 1) are read
// from one base address where they all lie in the grid and in the lower sample's chunk, as most
// do, and otherwise through densityAt, which finds each one's chunk: the same values.
bool windowInside = false;
uint windowBase = 0u;
ivec3 windowOrigin = ivec3(0);

void openWindow(ivec3 lower, ivec3 upper) {
    const int side = 1 << push.gridOrigin.w;
    const ivec3 inChunk = (push.gridOrigin.xyz + lower) & (side - 1);
    windowInside = all(greaterThanEqual(lower, ivec3(1))) && all(lessThan(upper + 1, push.gridSize.xyz)) &&
                   all(greaterThanEqual(inChunk, ivec3(1))) && all(lessThan(inChunk + (upper - lower) + 1, ivec3(side)));
    windowBase = voxelAddress(lower);
    windowOrigin = lower;
}

float sampleAt(ivec3 p) {
    if (!windowInside) return densityAt(p);
    const int side = 1 << push.gridOrigin.w;
    const ivec3 d = p - windowOrigin;
    const float v = densityTexel(uint(int(windowBase) + d.x + side * (d.y + side * d.z)));
    return isnan(v) || isinf(v) ? 0.0 : v;
}

vec3 gradientAt(ivec3 p) {
    precise vec3 g = 0.5 * vec3(sampleAt(p + ivec3(1, 0, 0)) - sampleAt(p - ivec3(1, 0, 0)),
                                sampleAt(p + ivec3(0, 1, 0)) - sampleAt(p - ivec3(0, 1, 0)),
                                sampleAt(p + ivec3(0, 0, 1)) - sampleAt(p - ivec3(0, 0, 1)));
    return g;
}

void writeVertex(uint index, ivec3 lower, int axis) {
    ivec3 step = ivec3(0);
    step[axis] = 1;
    const ivec3 upper = lower + step;
    const float iso = push.surface.x;
    openWindow(lower, upper);
    const float d0 = sampleAt(lower), d1 = sampleAt(upper);
    // In double, as voxc::marching_cubes::crossing: iso lies between the samples.
    const float t = clamp(float((double(iso) - double(d0)) / (double(d1) - double(d0))), push.surface.y, push.surface.z);
    precise vec3 position = vec3(push.gridOrigin.xyz + lower);
    position[axis] += t;
    precise vec3 gradient = (1.0 - t) * gradientAt(lower) + t * gradientAt(upper);
    precise float magnitude = sqrt((gradient.x * gradient.x + gradient.y * gradient.y) + gradient.z * gradient.z);
    precise vec3 normal;
    if (magnitude > 0.0 && !isinf(magnitude)) {
        normal = -gradient / magnitude;
    } else { // from the solid sample to the air one
        normal = vec3(0.0);
        normal[axis] = d0 > iso ? 1.0 : -1.0;
    }
    const uint base = index * 7u;
    vertices.word[base] = floatBitsToUint(position.x);
    vertices.word[base + 1u] = floatBitsToUint(position.y);
    vertices.word[base + 2u] = floatBitsToUint(position.z);
    vertices.word[base + 3u] = floatBitsToUint(normal.x);
    vertices.word[base + 4u] = floatBitsToUint(normal.y);
    vertices.word[base + 5u] = floatBitsToUint(normal.z);
    vertices.word[base + 6u] = materialAt(d0 > iso ? lower : upper);
}

void main() {
    const uint index = invocationIndex(64u);
    if (index >= push.pass.z) return;
    const uint edge = texelFetch(vertexEdgeTexels, int(index)).x;
    const uint slot = edge & 0x3fffffffu;
    writeVertex(index, cellOfSlot(activeTile(slot >> 9), slot), int(edge >> 30));
}
