// Point-set lookups along a field kernel's column: pointSetDistances(set, vec3(px, y, pz)) bit for
// bit at the up to 8 voxels of a block (a kernel that fills along the column has COLUMN_BLOCK 8,
// codegen's kPointSetColumnBlock, and walks 32 voxels per invocation), with the work of the voxels
// that share a list cell done once for all of them.
// Why: on llvmpipe a lookup is mostly its loads (a gather each): per list step an item, its lower
// bound and the point's 4 or 7 floats. Here the voxels of one cell take every step together, so a
// step loads these once for up to 8 voxels, and only the distances are per voxel (x and z are the
// column's, so dx and dz are shared too).
// Same floats: a voxel's nearest is the least distance over the items the steps visit, and they
// go on while some voxel of the cell is live (a lower bound below its nearest so far), so every
// item its own lookup would visit is visited; the others are not nearer (no distance is below its
// lower bound) and `<` keeps the first of equal distances, which have the same bits. The steps'
// operations are pointSetCentreStep's and pointSetSegmentStep's, per voxel, in the same order.
// Requires lsystem_carve.glsl (its buffer, POINT_SET_BLOCK) and, from the kernel,
// pointSetColumnArgY(site, y): the point's y at voxel index y of the column walk.

// The largest of the 8 voxels' nearest so far; the voxels outside the cell being stepped hold -1,
// so they neither count here nor take a distance (none is below -1).
float pointSetColumnWorst(vec4 lo, vec4 hi) {
    vec4 m = max(lo, hi);
    return max(max(m.x, m.y), max(m.z, m.w));
}

void pointSetColumnCentreStep(float px, float pz, vec4 yLo, vec4 yHi, int centres, int item, int i, int count,
                              inout bool live, inout vec4 nearestLo, inout vec4 nearestHi) {
    int j = min(i, count - 1);
    live = live && i < count && pointSetFloat(item + 2 * j + 1) < pointSetColumnWorst(nearestLo, nearestHi);
    int at = centres + 4 * pointSets.words[item + 2 * j];
    precise float dx = px - pointSetFloat(at);
    float cy = pointSetFloat(at + 1);
    precise float dz = pz - pointSetFloat(at + 2);
    precise float scale = pointSetFloat(at + 3);
    precise float dx2 = dx * dx;
    precise float dz2 = dz * dz;
    precise float scale2 = scale * scale;
    precise vec4 dyLo = yLo - cy;
    precise vec4 dyHi = yHi - cy;
    precise vec4 d2Lo = (dx2 + dyLo * dyLo + dz2) * scale2;
    precise vec4 d2Hi = (dx2 + dyHi * dyHi + dz2) * scale2;
    nearestLo = live ? mix(nearestLo, d2Lo, lessThan(d2Lo, nearestLo)) : nearestLo;
    nearestHi = live ? mix(nearestHi, d2Hi, lessThan(d2Hi, nearestHi)) : nearestHi;
}

// The segment's distance squared from (px, y, pz), as pointSetSegmentStep computes it per voxel.
vec4 pointSetColumnSegmentDistance2(float px, float pz, vec4 y, vec3 from, vec3 delta, float inverseLength2) {
    precise float qx = px - from.x;
    precise float qz = pz - from.z;
    precise vec4 qy = y - from.y;
    precise float qxex = qx * delta.x;
    precise float qzez = qz * delta.z;
    precise vec4 along = (qxex + qy * delta.y + qzez) * inverseLength2;
    precise vec4 t = mix(mix(along, vec4(1.0), greaterThan(along, vec4(1.0))), vec4(0.0), lessThan(along, vec4(0.0)));
    precise vec4 dx = qx - t * delta.x;
    precise vec4 dy = qy - t * delta.y;
    precise vec4 dz = qz - t * delta.z;
    precise vec4 d2 = dx * dx + dy * dy + dz * dz;
    return d2;
}

void pointSetColumnSegmentStep(float px, float pz, vec4 yLo, vec4 yHi, int segments, int item, int i, int count,
                               inout bool live, inout vec4 nearestLo, inout vec4 nearestHi) {
    int j = min(i, count - 1);
    live = live && i < count && pointSetFloat(item + 2 * j + 1) < pointSetColumnWorst(nearestLo, nearestHi);
    int at = segments + 7 * pointSets.words[item + 2 * j];
    vec3 from = vec3(pointSetFloat(at), pointSetFloat(at + 1), pointSetFloat(at + 2));
    vec3 delta = vec3(pointSetFloat(at + 3), pointSetFloat(at + 4), pointSetFloat(at + 5));
    float inverseLength2 = pointSetFloat(at + 6);
    vec4 d2Lo = pointSetColumnSegmentDistance2(px, pz, yLo, from, delta, inverseLength2);
    vec4 d2Hi = pointSetColumnSegmentDistance2(px, pz, yHi, from, delta, inverseLength2);
    nearestLo = live ? mix(nearestLo, d2Lo, lessThan(d2Lo, nearestLo)) : nearestLo;
    nearestHi = live ? mix(nearestHi, d2Hi, lessThan(d2Hi, nearestHi)) : nearestHi;
}

bvec4 pointSetColumnBoth(bvec4 a, bvec4 b) { return bvec4(a.x && b.x, a.y && b.y, a.z && b.z, a.w && b.w); }

// A block of 8 list entries takes the step at i, then these seven (none at a block of 1).
#if POINT_SET_BLOCK == 8
#define POINT_SET_COLUMN_NEXT_SEVEN(step, items, item, count) \
    step(px, pz, yLo, yHi, items, item, i + 1, count, live, nearestLo, nearestHi); \
    step(px, pz, yLo, yHi, items, item, i + 2, count, live, nearestLo, nearestHi); \
    step(px, pz, yLo, yHi, items, item, i + 3, count, live, nearestLo, nearestHi); \
    step(px, pz, yLo, yHi, items, item, i + 4, count, live, nearestLo, nearestHi); \
    step(px, pz, yLo, yHi, items, item, i + 5, count, live, nearestLo, nearestHi); \
    step(px, pz, yLo, yHi, items, item, i + 6, count, live, nearestLo, nearestHi); \
    step(px, pz, yLo, yHi, items, item, i + 7, count, live, nearestLo, nearestHi)
#else
#define POINT_SET_COLUMN_NEXT_SEVEN(step, items, item, count)
#endif

// values[s] = pointSetDistances(set, vec3(px, pointSetColumnArgY(site, blockY + s), pz)) for the
// voxels blockY + s before blockEnd (at most 8 of them); the other entries are unused.
void pointSetColumnFill(int site, int set, float px, float pz, int blockY, int blockEnd, out vec2 values[8]) {
    int lastY = blockEnd - 1;
    vec4 yLo = vec4(pointSetColumnArgY(site, min(blockY, lastY)), pointSetColumnArgY(site, min(blockY + 1, lastY)),
                    pointSetColumnArgY(site, min(blockY + 2, lastY)), pointSetColumnArgY(site, min(blockY + 3, lastY)));
    vec4 yHi = vec4(pointSetColumnArgY(site, min(blockY + 4, lastY)), pointSetColumnArgY(site, min(blockY + 5, lastY)),
                    pointSetColumnArgY(site, min(blockY + 6, lastY)), pointSetColumnArgY(site, min(blockY + 7, lastY)));
    ivec4 slot = ivec4(blockY) + ivec4(0, 1, 2, 3);
    bvec4 leftLo = lessThan(slot, ivec4(blockEnd));
    bvec4 leftHi = lessThan(slot + 4, ivec4(blockEnd));

    int header = pointSets.words[set];
    float centreReach = pointSetFloat(header + 3);
    float segmentReach = pointSetFloat(header + 4);
    int cellShift = pointSets.words[header + 5];
    ivec3 firstCell = ivec3(pointSets.words[header + 6], pointSets.words[header + 7], pointSets.words[header + 8]);
    ivec3 cellCount = ivec3(pointSets.words[header + 9], pointSets.words[header + 10], pointSets.words[header + 11]);
    ivec2 cellXZ = (ivec2(floor(vec2(px, pz))) >> cellShift) - firstCell.xz;
    bool insideXZ = all(greaterThanEqual(cellXZ, ivec2(0))) && all(lessThan(cellXZ, cellCount.xz));
    ivec4 cellYLo = (ivec4(floor(yLo)) >> cellShift) - firstCell.y;
    ivec4 cellYHi = (ivec4(floor(yHi)) >> cellShift) - firstCell.y;
    int cellTable = pointSets.words[header + 2];
    int centres = pointSets.words[header];
    int segments = pointSets.words[header + 1];

    const float none = 3.4028234663852886e38;
    vec4 centreLo = vec4(none), centreHi = vec4(none), segmentLo = vec4(none), segmentHi = vec4(none);
    bvec4 outsideLo = bvec4(false), outsideHi = bvec4(false);
    // One pass per cell the voxels meet, the cell of the first voxel not yet done first. The
    // voxels' y is the same in every lane, so every lane takes as many passes.
    while (any(leftLo) || any(leftHi)) {
        int cellY = leftLo.x ? cellYLo.x : leftLo.y ? cellYLo.y : leftLo.z ? cellYLo.z : leftLo.w ? cellYLo.w :
                    leftHi.x ? cellYHi.x : leftHi.y ? cellYHi.y : leftHi.z ? cellYHi.z : cellYHi.w;
        bvec4 inLo = pointSetColumnBoth(leftLo, equal(cellYLo, ivec4(cellY)));
        bvec4 inHi = pointSetColumnBoth(leftHi, equal(cellYHi, ivec4(cellY)));
        leftLo = pointSetColumnBoth(leftLo, not(inLo));
        leftHi = pointSetColumnBoth(leftHi, not(inHi));
        bool inside = insideXZ && cellY >= 0 && cellY < cellCount.y;
        // Outside the cells a voxel's distances are the caps (pointSetDistances).
        outsideLo = inside ? outsideLo : bvec4(ivec4(outsideLo) | ivec4(inLo));
        outsideHi = inside ? outsideHi : bvec4(ivec4(outsideHi) | ivec4(inHi));
        int list = cellTable + 4 * (cellXZ.x + cellCount.x * (cellY + cellCount.y * cellXZ.y));
        int centreItem = inside ? pointSets.words[list] : 0;
        int centreCount = inside ? pointSets.words[list + 1] : 0;
        int segmentItem = inside ? pointSets.words[list + 2] : 0;
        int segmentCount = inside ? pointSets.words[list + 3] : 0;

        vec4 nearestLo = mix(vec4(-1.0), vec4(none), inLo);
        vec4 nearestHi = mix(vec4(-1.0), vec4(none), inHi);
        bool live = true;
        for (int i = 0; live && i < centreCount; i += POINT_SET_BLOCK) {
            pointSetColumnCentreStep(px, pz, yLo, yHi, centres, centreItem, i, centreCount, live, nearestLo, nearestHi);
            POINT_SET_COLUMN_NEXT_SEVEN(pointSetColumnCentreStep, centres, centreItem, centreCount);
        }
        centreLo = mix(centreLo, nearestLo, inLo);
        centreHi = mix(centreHi, nearestHi, inHi);

        nearestLo = mix(vec4(-1.0), vec4(none), inLo);
        nearestHi = mix(vec4(-1.0), vec4(none), inHi);
        live = true;
        for (int i = 0; live && i < segmentCount; i += POINT_SET_BLOCK) {
            pointSetColumnSegmentStep(px, pz, yLo, yHi, segments, segmentItem, i, segmentCount, live, nearestLo, nearestHi);
            POINT_SET_COLUMN_NEXT_SEVEN(pointSetColumnSegmentStep, segments, segmentItem, segmentCount);
        }
        segmentLo = mix(segmentLo, nearestLo, inLo);
        segmentHi = mix(segmentHi, nearestHi, inHi);
    }

    // One sqrt and the caps, as pointSetDistances.
    precise vec4 centreDistanceLo = sqrt(centreLo);
    precise vec4 centreDistanceHi = sqrt(centreHi);
    precise vec4 segmentDistanceLo = sqrt(segmentLo);
    precise vec4 segmentDistanceHi = sqrt(segmentHi);
    vec4 cLo = mix(vec4(centreReach), centreDistanceLo, pointSetColumnBoth(lessThan(centreDistanceLo, vec4(centreReach)), not(outsideLo)));
    vec4 cHi = mix(vec4(centreReach), centreDistanceHi, pointSetColumnBoth(lessThan(centreDistanceHi, vec4(centreReach)), not(outsideHi)));
    vec4 sLo = mix(vec4(segmentReach), segmentDistanceLo, pointSetColumnBoth(lessThan(segmentDistanceLo, vec4(segmentReach)), not(outsideLo)));
    vec4 sHi = mix(vec4(segmentReach), segmentDistanceHi, pointSetColumnBoth(lessThan(segmentDistanceHi, vec4(segmentReach)), not(outsideHi)));
    values[0] = vec2(cLo.x, sLo.x);
    values[1] = vec2(cLo.y, sLo.y);
    values[2] = vec2(cLo.z, sLo.z);
    values[3] = vec2(cLo.w, sLo.w);
    values[4] = vec2(cHi.x, sHi.x);
    values[5] = vec2(cHi.y, sHi.y);
    values[6] = vec2(cHi.z, sHi.z);
    values[7] = vec2(cHi.w, sHi.w);
}
