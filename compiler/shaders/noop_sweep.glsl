#version 450
// <<HEADER>>

// Every rule of this sweep can never match, so the sweep leaves the grid as it is. The
// kernel still exists so that each sweep of the dispatch plan has one.

#include "common.glsl"

// <<DISPATCH_SHAPE>>

void main() {
}
