#version 450
// <<HEADER>>

// The second pass of a speleothem stage: one invocation per (x, z) column writes every feature
// that reaches its column, found in the air mask of the grid before the stage at (x, z) and,
// for hoodoos, at the three columns at -1 offsets (voxc::caves::growSpeleothemColumn). Each
// invocation writes only its own column.

#include "common.glsl"
#include "speleothem_air.glsl"
// <<PARAMETERS>>
#include "random.glsl"
#include "noise_common.glsl"
#include "noise_permutation.glsl"
#include "noise_simplex3.glsl"
#include "speleothems.glsl"

// <<DISPATCH_SHAPE>>

void main() {
    ivec3 first = ivec3(gl_GlobalInvocationID) * ANCHORS_PER_INVOCATION;
    if (any(greaterThanEqual(first, push.anchorCount.xyz))) return;
    ivec3 last = min(first + ANCHORS_PER_INVOCATION, push.anchorCount.xyz);

    for (int z = first.z; z < last.z; ++z) {
        for (int x = first.x; x < last.x; ++x) {
            ivec2 column = (push.anchorStart.xyz + ivec3(x, 0, z) * push.anchorStep.xyz).xz;
            speleothemGrowFrom(column, column);
            if (SPELEOTHEM_KIND == 3) {
                if (column.x > 0) speleothemGrowFrom(column - ivec2(1, 0), column);
                if (column.y > 0) speleothemGrowFrom(column - ivec2(0, 1), column);
                if (column.x > 0 && column.y > 0) speleothemGrowFrom(column - ivec2(1, 1), column);
            }
        }
    }
}
