#pragma once
// Skeleton export as text (the driver writes it): JSON with every field of the skeleton, and OBJ
// polylines (`l` elements) to load beside a mesh. Coordinates are printed in the shortest form
// that reads back to the same double, so both are deterministic.
#include "voxc/generators/lsystem/Turtle.h"

#include <ostream>
#include <string>

namespace voxc::lsystem {

// Written as it is made, element by element: memory stays that of the skeleton, not of a JSON
// tree of it (nlohmann's dump(1) layout, keys in the order below).
void writeSkeletonJson(std::ostream& out, const Skeleton& skeleton);
std::string skeletonJson(const Skeleton& skeleton);

// One `l` polyline per run of segments that continue each other on one branch (object
// `skeleton`) and one per connection (object `connections`).
void writeSkeletonObj(std::ostream& out, const Skeleton& skeleton);
std::string skeletonObj(const Skeleton& skeleton);

} // namespace voxc::lsystem
