#pragma once
// Skeleton export as text (the driver writes it): JSON with every field of the skeleton, and OBJ
// polylines (`l` elements) to load beside a mesh. Coordinates are printed in the shortest form
// that reads back to the same double, so both are deterministic.
#include "voxc/generators/lsystem/Turtle.h"

#include <string>

namespace voxc::lsystem {

std::string skeletonJson(const Skeleton& skeleton);

// One `l` polyline per run of segments that continue each other on one branch (object
// `skeleton`) and one per connection (object `connections`).
std::string skeletonObj(const Skeleton& skeleton);

} // namespace voxc::lsystem
