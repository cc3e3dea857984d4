// Point sets (voxc/program/PointSet.h): the capped distances from a world position to the nearest
// centre and the nearest segment of a set, read from the per-chunk lists of the run's chunk table
// (the points whose reach meets the chunk). Written operation for operation as
// voxc::pointSetDistances, every float result `precise`: squared distances, the nearest kept
// by `<`, one sqrt, the cap. Capping makes the lists' contents beyond the reach irrelevant, so
// the interpreter's lists (another chunk size) give the same floats.
//
// Buffer (voxc::pointSetWords), ints, floats stored as their bits:
//   words[s]         header offset h of point set s
//   words[h + 0..4]  centre data offset, segment data offset, chunk list table offset,
//                    centre reach, segment reach
//   centre data      x, y, z per centre
//   segment data     from.xyz, delta.xyz, 1 / |delta|^2 per segment
//   list table       per chunk-table entry: first centre item, centre count, first segment
//                    item, segment count (items: point indices, absolute word offsets)

layout(std430, set = 0, binding = 10) readonly buffer PointSets {
    int words[];
} pointSets;

float pointSetFloat(int at) { return intBitsToFloat(pointSets.words[at]); }

vec2 pointSetDistances(int set, vec3 p) {
    int header = pointSets.words[set];
    float centreReach = pointSetFloat(header + 3);
    float segmentReach = pointSetFloat(header + 4);
    int chunkShift = findMSB(push.gridOrigin.w);
    ivec3 entry = (ivec3(floor(p)) >> chunkShift) - push.chunkBase.xyz;
    if (any(lessThan(entry, ivec3(0))) || any(greaterThanEqual(entry, push.chunkCount.xyz)))
        return vec2(centreReach, segmentReach);
    int list = pointSets.words[header + 2] + 4 * (entry.x + push.chunkCount.x * (entry.y + push.chunkCount.y * entry.z));

    int centres = pointSets.words[header];
    int firstCentre = pointSets.words[list];
    int centreCount = pointSets.words[list + 1];
    precise float nearestCentre = 3.4028234663852886e38;
    for (int i = 0; i < centreCount; ++i) {
        int at = centres + 3 * pointSets.words[firstCentre + i];
        precise float dx = p.x - pointSetFloat(at);
        precise float dy = p.y - pointSetFloat(at + 1);
        precise float dz = p.z - pointSetFloat(at + 2);
        precise float d2 = dx * dx + dy * dy + dz * dz;
        nearestCentre = d2 < nearestCentre ? d2 : nearestCentre;
    }

    int segments = pointSets.words[header + 1];
    int firstSegment = pointSets.words[list + 2];
    int segmentCount = pointSets.words[list + 3];
    precise float nearestSegment = 3.4028234663852886e38;
    for (int i = 0; i < segmentCount; ++i) {
        int at = segments + 7 * pointSets.words[firstSegment + i];
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
