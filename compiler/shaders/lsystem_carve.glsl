// Point sets (voxc/program/PointSet.h): the capped distances from a world position to the nearest
// centre (each scaled by its own factor) and the nearest segment of a set, read from the lists of
// the position's cell (a world-aligned cube of 8 voxels: the points whose reach meets it, sorted
// by a lower bound of their squared distance to the cell). Written operation for operation as
// voxc::pointSetDistances, every float result `precise`: squared distances, the nearest kept by
// `<`, the loop left at the first lower bound not below the nearest, one sqrt, the cap. Capping
// makes the lists' contents beyond the reach irrelevant, so every backend computes the same floats.
//
// Buffer (voxc::pointSetWords), ints, floats stored as their bits:
//   words[s]          header offset h of point set s
//   words[h + 0..12]  centre data offset, segment data offset, cell table offset, centre reach,
//                     segment reach, log2 cell size, first cell xyz, cell counts xyz, clearance
//                     (PointSet::clearance, for stages after the carve that keep it air)
//   centre data       x, y, z, scale per centre
//   segment data      from.xyz, delta.xyz, 1 / |delta|^2 per segment
//   items             (point index, lower bound of the squared distance) pairs
//   cell table        per cell (x fastest): first centre item, centre count, first segment item,
//                     segment count (first items as absolute word offsets)

layout(std430, set = 0, binding = 10) readonly buffer PointSets {
    int words[];
} pointSets;

float pointSetFloat(int at) { return intBitsToFloat(pointSets.words[at]); }

// The list loops visit POINT_SET_BLOCK items per iteration (1 or 8), as straight-line steps,
// because lavapipe (llvmpipe) caps the loop iterations of one invocation group at 65535 for all its
// loops together and silently leaves every loop after that: a cell may list kMaxPointSetPerCell
// (8,192) centres and as many segments, so a voxel takes at most 2 * 8192 / POINT_SET_BLOCK + 2
// iterations here, and field kernels that read a point set walk at most kPointSetAnchorsAlongY
// voxels per invocation (codegen/FieldKernel.cpp). Every step of a block costs all its loads,
// live or not, and most lookups end after a step or two, so field kernels whose lists are short
// enough define POINT_SET_BLOCK 1 (codegen's fieldPointSetListBlock); stamp and speleothem
// kernels, whose bounds the check counts in blocks of kPointSetListBlock, keep 8. A step reads
// item min(i, count - 1), always in the list, and keeps its distance only while `live`: before
// the list's end and before the first lower bound not below the nearest so far (every later one
// is not either), so the nearest is the one a loop over the items one by one finds. No branch:
// the driver compiles it quickly and the lanes of a group do not diverge. A field kernel whose
// point is its column's (x and z fixed, y along the walk) takes these steps through
// point_set_column.glsl instead, once per cell for the voxels of a block of 8 in that cell (at
// most 2 cells: 4 * (8192 / POINT_SET_BLOCK + 1) iterations a block), and walks 32 voxels.
#ifndef POINT_SET_BLOCK
#define POINT_SET_BLOCK 8
#endif
#if POINT_SET_BLOCK != 1 && POINT_SET_BLOCK != 8
#error POINT_SET_BLOCK is 1 or 8
#endif

void pointSetCentreStep(vec3 p, int centres, int item, int i, int count, inout bool live, inout float nearest) {
    int j = min(i, count - 1);
    live = live && i < count && pointSetFloat(item + 2 * j + 1) < nearest;
    int at = centres + 4 * pointSets.words[item + 2 * j];
    precise float dx = p.x - pointSetFloat(at);
    precise float dy = p.y - pointSetFloat(at + 1);
    precise float dz = p.z - pointSetFloat(at + 2);
    precise float scale = pointSetFloat(at + 3);
    precise float d2 = (dx * dx + dy * dy + dz * dz) * (scale * scale);
    nearest = live && d2 < nearest ? d2 : nearest;
}

void pointSetSegmentStep(vec3 p, int segments, int item, int i, int count, inout bool live, inout float nearest) {
    int j = min(i, count - 1);
    live = live && i < count && pointSetFloat(item + 2 * j + 1) < nearest;
    int at = segments + 7 * pointSets.words[item + 2 * j];
    precise float px = p.x - pointSetFloat(at);
    precise float py = p.y - pointSetFloat(at + 1);
    precise float pz = p.z - pointSetFloat(at + 2);
    precise float ex = pointSetFloat(at + 3);
    precise float ey = pointSetFloat(at + 4);
    precise float ez = pointSetFloat(at + 5);
    precise float along = (px * ex + py * ey + pz * ez) * pointSetFloat(at + 6);
    precise float t = along < 0.0 ? 0.0 : (along > 1.0 ? 1.0 : along);
    precise float dx = px - t * ex;
    precise float dy = py - t * ey;
    precise float dz = pz - t * ez;
    precise float d2 = dx * dx + dy * dy + dz * dz;
    nearest = live && d2 < nearest ? d2 : nearest;
}

vec2 pointSetDistances(int set, vec3 p) {
    int header = pointSets.words[set];
    float centreReach = pointSetFloat(header + 3);
    float segmentReach = pointSetFloat(header + 4);
    ivec3 firstCell = ivec3(pointSets.words[header + 6], pointSets.words[header + 7], pointSets.words[header + 8]);
    ivec3 cellCount = ivec3(pointSets.words[header + 9], pointSets.words[header + 10], pointSets.words[header + 11]);
    ivec3 cell = (ivec3(floor(p)) >> pointSets.words[header + 5]) - firstCell;
    if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, cellCount)))
        return vec2(centreReach, segmentReach);
    int list = pointSets.words[header + 2] + 4 * (cell.x + cellCount.x * (cell.y + cellCount.y * cell.z));

    int centres = pointSets.words[header];
    int centreItem = pointSets.words[list];
    int centreCount = pointSets.words[list + 1];
    float nearestCentre = 3.4028234663852886e38;
    bool live = true;
    for (int i = 0; live && i < centreCount; i += POINT_SET_BLOCK) {
        // The steps written out (a constant loop here could stay a loop).
        pointSetCentreStep(p, centres, centreItem, i, centreCount, live, nearestCentre);
#if POINT_SET_BLOCK == 8
        pointSetCentreStep(p, centres, centreItem, i + 1, centreCount, live, nearestCentre);
        pointSetCentreStep(p, centres, centreItem, i + 2, centreCount, live, nearestCentre);
        pointSetCentreStep(p, centres, centreItem, i + 3, centreCount, live, nearestCentre);
        pointSetCentreStep(p, centres, centreItem, i + 4, centreCount, live, nearestCentre);
        pointSetCentreStep(p, centres, centreItem, i + 5, centreCount, live, nearestCentre);
        pointSetCentreStep(p, centres, centreItem, i + 6, centreCount, live, nearestCentre);
        pointSetCentreStep(p, centres, centreItem, i + 7, centreCount, live, nearestCentre);
#endif
    }

    int segments = pointSets.words[header + 1];
    int segmentItem = pointSets.words[list + 2];
    int segmentCount = pointSets.words[list + 3];
    float nearestSegment = 3.4028234663852886e38;
    live = true;
    for (int i = 0; live && i < segmentCount; i += POINT_SET_BLOCK) {
        pointSetSegmentStep(p, segments, segmentItem, i, segmentCount, live, nearestSegment);
#if POINT_SET_BLOCK == 8
        pointSetSegmentStep(p, segments, segmentItem, i + 1, segmentCount, live, nearestSegment);
        pointSetSegmentStep(p, segments, segmentItem, i + 2, segmentCount, live, nearestSegment);
        pointSetSegmentStep(p, segments, segmentItem, i + 3, segmentCount, live, nearestSegment);
        pointSetSegmentStep(p, segments, segmentItem, i + 4, segmentCount, live, nearestSegment);
        pointSetSegmentStep(p, segments, segmentItem, i + 5, segmentCount, live, nearestSegment);
        pointSetSegmentStep(p, segments, segmentItem, i + 6, segmentCount, live, nearestSegment);
        pointSetSegmentStep(p, segments, segmentItem, i + 7, segmentCount, live, nearestSegment);
#endif
    }
    precise float centre = sqrt(nearestCentre);
    precise float segment = sqrt(nearestSegment);
    return vec2(centre < centreReach ? centre : centreReach, segment < segmentReach ? segment : segmentReach);
}
