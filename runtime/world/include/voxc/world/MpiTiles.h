#pragma once
// `mpirun -np N voxc world ...`: the tiles spread over N processes with Open MPI. Rank 0 runs
// writeWorld (the resume check, index.json, progress) and hands each pending tile to the next
// rank that asks, so cheap tiles (uniform air or rock) and expensive ones (surface) balance
// themselves; ranks 1..N-1 compute tiles and write their files. Tiles are computed by the same
// code as in one process, so the files are byte-identical to a single process's; the index is
// written in tile order. Every rank needs the same file and the output directory on a shared
// filesystem (docs/scale.md).
#include "voxc/world/Tiles.h"

#include <functional>

namespace voxc::world {

// True when this process was started by mpirun with more than one rank.
bool startedByMpiWithRanks();

// Initialises MPI, runs `makeOptions` (the check and the device, once per rank), then rank 0's
// writeWorld or a worker's loop, and finalises. A rank's error aborts every rank (MPI_Abort with
// exit code 1 for a user error, 2 otherwise) after printing it. Returns rank 0's summary; on
// the other ranks a summary with `tiles` 0.
WorldSummary writeWorldOnRanks(const Program& program, const WorldOptions& options);

} // namespace voxc::world
