#pragma once
// Branch connection (§III-B.3, docs/architecture.md "Connections"): endpoints are shuffled, each
// becomes a line start with probability `chance`, the next accepted endpoint within
// `maxDistance` ends the line; lines are distorted by curl noise with a sin(pi t) taper so they
// end exactly at both endpoints.
#include "voxc/generators/lsystem/Turtle.h"

namespace voxc::lsystem {

struct ConnectParams {
    double chance = 0.5;
    double maxDistance = 64.0;       // 16 default steps
    double frequency = 1.0 / 32.0;   // curl noise, cycles per voxel
    double amplitude = 4.0;          // voxels; every point stays within it of the straight line
    double spacing = 4.0;            // length of one polyline segment (the step length)
};

// Throws UserError for parameters out of range (chance outside [0, 1], spacing <= 0, ...).
void checkConnectParams(const ConnectParams& params);

// Appends the connections of skeleton.endpoints to skeleton.connections. Their points count
// against Limits::maxSegments with the skeleton's segments, checked before each line is built.
void connectBranches(Skeleton& skeleton, const ConnectParams& params, uint32_t seed, const Limits& limits);

} // namespace voxc::lsystem
