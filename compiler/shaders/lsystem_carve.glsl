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
    precise float nearestCentre = 3.4028234663852886e38;
    for (int i = 0; i < centreCount; ++i) {
        if (pointSetFloat(centreItem + 2 * i + 1) >= nearestCentre) break;
        int at = centres + 4 * pointSets.words[centreItem + 2 * i];
        precise float dx = p.x - pointSetFloat(at);
        precise float dy = p.y - pointSetFloat(at + 1);
        precise float dz = p.z - pointSetFloat(at + 2);
        precise float scale = pointSetFloat(at + 3);
        precise float d2 = (dx * dx + dy * dy + dz * dz) * (scale * scale);
        nearestCentre = d2 < nearestCentre ? d2 : nearestCentre;
    }

    int segments = pointSets.words[header + 1];
    int segmentItem = pointSets.words[list + 2];
    int segmentCount = pointSets.words[list + 3];
    precise float nearestSegment = 3.4028234663852886e38;
    for (int i = 0; i < segmentCount; ++i) {
        if (pointSetFloat(segmentItem + 2 * i + 1) >= nearestSegment) break;
        int at = segments + 7 * pointSets.words[segmentItem + 2 * i];
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
        nearestSegment = d2 < nearestSegment ? d2 : nearestSegment;
    }
    precise float centre = sqrt(nearestCentre);
    precise float segment = sqrt(nearestSegment);
    return vec2(centre < centreReach ? centre : centreReach, segment < segmentReach ? segment : segmentReach);
}
