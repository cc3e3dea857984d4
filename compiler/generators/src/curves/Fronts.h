#pragma once
// The host's two fronts (material, surface) in two steps: prepare reserves a front's fields and
// scratch, grow fills them (no reallocation), sets layer 0 and values every other cell
// (growLayers, single-threaded). The host runs the two grows side by side on two threads
// (solveCurves); preparing both on the calling thread first keeps their fields in its heap, which
// the solve reuses and backs with huge pages (HeapReuse.h): a field a new thread allocates comes
// from that thread's own malloc arena, fresh memory in small pages. Filling them in grow puts
// the first touches of their pages (21 bytes a box cell in all) on both threads instead of this
// one alone; where the caller gives up the constraints' material ids and seed surface values, the
// fields are those, so the solve takes 6 bytes a box cell less fresh memory.
#include "Bfs.h"

#include "voxc/generators/curves/Diffuse.h"
#include "voxc/generators/curves/Propagate.h"

namespace voxc::curves {

struct MaterialFront {
    MaterialField field;
    std::vector<FrontLayer> layer; // 0 on Omega_R, then the BFS layer
    FrontOrder order; // growLayers' scratch
};
// `constraintMaterial`: the constraints' own ids, given up (the caller owns the constraints and
// reads them no more), become the field in place (the seeds keep theirs), or null.
MaterialFront prepareMaterial(const Constraints& constraints, std::vector<uint16_t>* constraintMaterial);
void growMaterial(const Constraints& constraints, MaterialFront& front);

struct SurfaceFront {
    SurfaceField field;
    FrontOrder order; // growLayers' scratch
};
// `constraintSurface`: the constraints' own seed values, given up likewise, or null.
SurfaceFront prepareSurface(const Constraints& constraints, Field3* constraintSurface);
void growSurface(const Constraints& constraints, const Field3& nx, const Field3& ny, const Field3& nz, PropagateRule rule,
                 SurfaceFront& front);

} // namespace voxc::curves
