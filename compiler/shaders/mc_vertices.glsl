#version 450
// GPU marching cubes, pass 2, one invocation per vertex (the host lists each with its
// owner cell and axis, in global edge order, the mesh's vertex order): the crossing, normal and
// material of the vertex. The arithmetic is the CPU mesher's, operation for operation
// (`precise`: no fused multiply-adds), so positions and normals agree bit for bit where the
// device rounds as IEEE 754 requires. A vertex to an invocation keeps every lane busy (an
// invocation per cell ran the body of each axis any lane of its group owned).

layout(local_size_x = 64) in;

layout(set = 0, binding = 8) uniform usamplerBuffer vertexEdgeTexels; // per vertex: its owner cell's slot | axis << 30
// Two texels per vertex: position xyz and normal x, then normal yz and material (float bits);
// two texel stores, where seven words of a storage buffer were seven passes over the lanes.
layout(set = 0, binding = 3, rgba32ui) uniform writeonly uimageBuffer vertices;

// The samples a vertex reads lie from its edge's lower sample - 1 to its upper sample + 1 along
// the edge's axis and within 1 of either across it: per axis the address parts (mc_common.glsl,
// axisPart) of offsets -1 to 2 from the lower sample, so that a sample costs two additions
// (densityAt computes a whole address, and a fast path beside it would cost as much again:
// lavapipe runs both sides of a branch). They are named along the edge (axis a) and the two axes
// after it (u = a + 1, v = a + 2, mod 3), so that each of the 12 samples is fetched once: the
// lower sample's gradient takes the upper sample where it steps +1 along the edge, the upper
// one's the lower sample where it steps -1 (14 fetches, those two twice, before).
uint along[4], acrossU[4], acrossV[4];
bool alongInside[4], acrossUInside[4], acrossVInside[4];

void openSamples(ivec3 lower, int axis) {
    uint parts[3][4];
    bool inside[3][4];
    for (int o = 0; o < 4; ++o) {
        parts[0][o] = axisPart(0, lower.x + o - 1, inside[0][o]);
        parts[1][o] = axisPart(1, lower.y + o - 1, inside[1][o]);
        parts[2][o] = axisPart(2, lower.z + o - 1, inside[2][o]);
    }
    for (int o = 0; o < 4; ++o) { // selects, not a variable index: lavapipe keeps those arrays in memory
        along[o] = axis == 0 ? parts[0][o] : axis == 1 ? parts[1][o] : parts[2][o];
        acrossU[o] = axis == 0 ? parts[1][o] : axis == 1 ? parts[2][o] : parts[0][o];
        acrossV[o] = axis == 0 ? parts[2][o] : axis == 1 ? parts[0][o] : parts[1][o];
        alongInside[o] = axis == 0 ? inside[0][o] : axis == 1 ? inside[1][o] : inside[2][o];
        acrossUInside[o] = axis == 0 ? inside[1][o] : axis == 1 ? inside[2][o] : inside[0][o];
        acrossVInside[o] = axis == 0 ? inside[2][o] : axis == 1 ? inside[0][o] : inside[1][o];
    }
}

// The sample at offsets (a, u, v) (a from -1 to 2, u and v from -1 to 1) from the lower sample,
// as densityAt reads it.
float sampleAt(const int a, const int u, const int v) {
    const bool inside = alongInside[a + 1] && acrossUInside[u + 1] && acrossVInside[v + 1];
    const float d = densityTexel(inside ? along[a + 1] + acrossU[u + 1] + acrossV[v + 1] : 0u);
    return !inside || isnan(d) || isinf(d) ? 0.0 : d;
}

// A gradient's components along the edge and across it, in x, y, z.
vec3 inGrid(float a, float u, float v, int axis) {
    return axis == 0 ? vec3(a, u, v) : axis == 1 ? vec3(v, a, u) : vec3(u, v, a);
}

void writeVertex(uint index, ivec3 lower, int axis) {
    const float iso = push.surface.x;
    openSamples(lower, axis);
    const float d0 = sampleAt(0, 0, 0), d1 = sampleAt(1, 0, 0);
    // In double, as voxc::marching_cubes::crossing: iso lies between the samples.
    const float t = clamp(float((double(iso) - double(d0)) / (double(d1) - double(d0))), push.surface.y, push.surface.z);
    precise vec3 position = vec3(push.gridOrigin.xyz + lower);
    position[axis] += t;
    // Central differences at the lower and the upper sample, as the CPU mesher's gradient.
    precise vec3 lowerGradient = 0.5 * inGrid(d1 - sampleAt(-1, 0, 0), sampleAt(0, 1, 0) - sampleAt(0, -1, 0),
                                              sampleAt(0, 0, 1) - sampleAt(0, 0, -1), axis);
    precise vec3 upperGradient = 0.5 * inGrid(sampleAt(2, 0, 0) - d0, sampleAt(1, 1, 0) - sampleAt(1, -1, 0),
                                              sampleAt(1, 0, 1) - sampleAt(1, 0, -1), axis);
    precise vec3 gradient = (1.0 - t) * lowerGradient + t * upperGradient;
    precise float magnitude = sqrt((gradient.x * gradient.x + gradient.y * gradient.y) + gradient.z * gradient.z);
    precise vec3 normal;
    if (magnitude > 0.0 && !isinf(magnitude)) {
        normal = -gradient / magnitude;
    } else { // from the solid sample to the air one
        normal = vec3(0.0);
        normal[axis] = d0 > iso ? 1.0 : -1.0;
    }
    // The material of the solid sample, as materialAt, at the address the density was read from.
    const bool lowerSolid = d0 > iso;
    const bool materialInside = kHasMaterials && (lowerSolid ? alongInside[1] : alongInside[2]) && acrossUInside[1] && acrossVInside[1];
    const uint materialAddress = (lowerSolid ? along[1] : along[2]) + acrossU[1] + acrossV[1];
    const uint material = materialInside ? texelFetch(materialTexels, int(materialAddress)).x & 0xffu : 0u;
    imageStore(vertices, int(2u * index), floatBitsToUint(vec4(position, normal.x)));
    imageStore(vertices, int(2u * index + 1u), uvec4(floatBitsToUint(normal.yz), material, 0u));
}

void main() {
    const uint index = invocationIndex(64u);
    if (index >= push.pass.y) return;
    const uint edge = texelFetch(vertexEdgeTexels, int(index)).x;
    const uint slot = edge & 0x3fffffffu;
    writeVertex(index, cellOfSlot(slot), int(edge >> 30));
}
