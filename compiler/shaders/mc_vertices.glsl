#version 450
// GPU marching cubes, pass 2, one invocation per vertex (the host lists each with its
// owner cell and axis, in global edge order, the mesh's vertex order): the crossing, normal and
// material of the vertex. The arithmetic is the CPU mesher's, operation for operation
// (`precise`: no fused multiply-adds), so positions and normals agree bit for bit where the
// device rounds as IEEE 754 requires. A vertex to an invocation keeps every lane busy (an
// invocation per cell ran the body of each axis any lane of its group owned).

layout(local_size_x = 64) in;

layout(set = 0, binding = 11) uniform usamplerBuffer vertexEdgeTexels; // per vertex: its owner cell's slot | axis << 30
// Two texels per vertex: position xyz and normal x, then normal yz and material (float bits);
// two texel stores, where seven words of a storage buffer were seven passes over the lanes.
layout(set = 0, binding = 4, rgba32ui) uniform writeonly uimageBuffer vertices;

// The samples a vertex reads lie from its edge's lower sample - 1 to its upper sample + 1 along
// each axis: per axis the address parts (mc_common.glsl, axisPart) of offsets -1 to 2 from the
// lower sample, so that a sample costs two additions (densityAt computes a whole address, and a
// fast path beside it would cost as much again: lavapipe runs both sides of a branch).
uint parts[3][4];
bool partInside[3][4];
bvec3 upperStep = bvec3(false); // the edge's axis

void openSamples(ivec3 lower, int axis) {
    for (int o = 0; o < 4; ++o) {
        parts[0][o] = axisPart(0, lower.x + o - 1, partInside[0][o]);
        parts[1][o] = axisPart(1, lower.y + o - 1, partInside[1][o]);
        parts[2][o] = axisPart(2, lower.z + o - 1, partInside[2][o]);
    }
    upperStep = equal(ivec3(axis), ivec3(0, 1, 2));
}

// The sample at offset d (each -1 to 1) from the lower sample, or from the upper one where
// `fromUpper`: as densityAt reads it.
float sampleNear(const ivec3 d, bool fromUpper) {
    const bvec3 shifted = bvec3(fromUpper && upperStep.x, fromUpper && upperStep.y, fromUpper && upperStep.z);
    uint address = 0u;
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
        const int o = d[a] + 1;
        address += shifted[a] ? parts[a][o + 1] : parts[a][o];
        inside = inside && (shifted[a] ? partInside[a][o + 1] : partInside[a][o]);
    }
    const float v = densityTexel(inside ? address : 0u);
    return !inside || isnan(v) || isinf(v) ? 0.0 : v;
}

vec3 gradientNear(bool fromUpper) {
    precise vec3 g = 0.5 * vec3(sampleNear(ivec3(1, 0, 0), fromUpper) - sampleNear(ivec3(-1, 0, 0), fromUpper),
                                sampleNear(ivec3(0, 1, 0), fromUpper) - sampleNear(ivec3(0, -1, 0), fromUpper),
                                sampleNear(ivec3(0, 0, 1), fromUpper) - sampleNear(ivec3(0, 0, -1), fromUpper));
    return g;
}

void writeVertex(uint index, ivec3 lower, int axis) {
    ivec3 step = ivec3(0);
    step[axis] = 1;
    const ivec3 upper = lower + step;
    const float iso = push.surface.x;
    openSamples(lower, axis);
    const float d0 = sampleNear(ivec3(0), false), d1 = sampleNear(ivec3(0), true);
    // In double, as voxc::marching_cubes::crossing: iso lies between the samples.
    const float t = clamp(float((double(iso) - double(d0)) / (double(d1) - double(d0))), push.surface.y, push.surface.z);
    precise vec3 position = vec3(push.gridOrigin.xyz + lower);
    position[axis] += t;
    precise vec3 gradient = (1.0 - t) * gradientNear(false) + t * gradientNear(true);
    precise float magnitude = sqrt((gradient.x * gradient.x + gradient.y * gradient.y) + gradient.z * gradient.z);
    precise vec3 normal;
    if (magnitude > 0.0 && !isinf(magnitude)) {
        normal = -gradient / magnitude;
    } else { // from the solid sample to the air one
        normal = vec3(0.0);
        normal[axis] = d0 > iso ? 1.0 : -1.0;
    }
    imageStore(vertices, int(2u * index), floatBitsToUint(vec4(position, normal.x)));
    imageStore(vertices, int(2u * index + 1u), uvec4(floatBitsToUint(normal.yz), materialAt(d0 > iso ? lower : upper), 0u));
}

void main() {
    const uint index = invocationIndex(64u);
    if (index >= push.pass.y) return;
    const uint edge = texelFetch(vertexEdgeTexels, int(index)).x;
    const uint slot = edge & 0x3fffffffu;
    writeVertex(index, cellOfSlot(slot), int(edge >> 30));
}
