#version 450
// <<HEADER>>

// Every rule of this sweep can never match, so the sweep leaves the grid as it is. The
// kernel still exists so that each sweep of the dispatch plan has one.

#include "common.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

void main() {
}
