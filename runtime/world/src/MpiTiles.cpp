#include "voxc/world/MpiTiles.h"

#include "voxc/core/Errors.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <mpi.h>
#include <string>
#include <thread>

namespace voxc::world {

namespace {

constexpr int kTag = 7;
constexpr size_t kDigestSize = 64; // SHA-256 in hex

// A worker's message to rank 0: the tile it finished (-1 on its first message) and its files'
// hashes (the mesh's all zero bytes when the tile has no mesh file).
struct Finished {
    int64_t tile = -1;
    char voxels[kDigestSize] = {};
    char mesh[kDigestSize] = {};
};

// Open MPI's blocking receive polls without sleeping, so a rank waiting in it takes a whole core
// from the ranks computing tiles beside it (rank 0 waits seconds per tile). Tiles take seconds,
// so a millisecond of latency costs nothing.
void sleepUntilMessage(int source) {
    for (int arrived = 0;;) {
        MPI_Iprobe(source, kTag, MPI_COMM_WORLD, &arrived, MPI_STATUS_IGNORE);
        if (arrived) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

// Every rank's arrival, waited for the same way, so a worker out of tiles leaves its core to the
// ones still computing (MPI_Finalize's own wait polls too).
void sleepingBarrier() {
    MPI_Request request;
    MPI_Ibarrier(MPI_COMM_WORLD, &request);
    for (int done = 0;;) {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

// Rank 0: answers every worker's message with the next pending tile, or -1 when none is left.
void coordinate(int ranks, const std::vector<int64_t>& pending, const TileDone& done) {
    size_t next = 0;
    int working = ranks - 1;
    while (working > 0) {
        Finished message;
        MPI_Status status;
        sleepUntilMessage(MPI_ANY_SOURCE);
        MPI_Recv(&message, int(sizeof message), MPI_BYTE, MPI_ANY_SOURCE, kTag, MPI_COMM_WORLD, &status);
        if (message.tile >= 0)
            done(message.tile, {std::string(message.voxels, kDigestSize),
                                message.mesh[0] ? std::string(message.mesh, kDigestSize) : std::string()});
        const int64_t tile = next < pending.size() ? pending[next++] : -1;
        if (tile < 0) --working;
        MPI_Send(&tile, 1, MPI_INT64_T, status.MPI_SOURCE, kTag, MPI_COMM_WORLD);
    }
}

// Ranks 1..N-1: ask for a tile, compute it, report it, until rank 0 says none is left.
void work(const Program& program, const WorldOptions& options) {
    Finished message;
    while (true) {
        MPI_Send(&message, int(sizeof message), MPI_BYTE, 0, kTag, MPI_COMM_WORLD);
        int64_t tile = -1;
        MPI_Recv(&tile, 1, MPI_INT64_T, 0, kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (tile < 0) return;
        const TileDigests digests = writeTile(program, options, tile);
        message = Finished{tile};
        std::memcpy(message.voxels, digests.voxels.data(), kDigestSize);
        std::memcpy(message.mesh, digests.mesh.data(), digests.mesh.size());
    }
}

} // namespace

bool startedByMpiWithRanks() {
    const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
    return size && std::atoi(size) > 1;
}

WorldSummary writeWorldOnRanks(const Program& program, const WorldOptions& options) {
    MPI_Init(nullptr, nullptr);
    int rank = 0, ranks = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    WorldSummary summary;
    try {
        if (rank == 0) {
            summary = writeWorld(program, options, [&](const std::vector<int64_t>& pending, const ComputeTile&,
                                                       const TileDone& done) { coordinate(ranks, pending, done); });
        } else {
            WorldOptions quiet = options;
            quiet.progress = nullptr;
            work(program, quiet);
        }
    } catch (const UserError& error) {
        std::cerr << "voxc: error (rank " << rank << "): " << error.what() << "\n";
        MPI_Abort(MPI_COMM_WORLD, 1);
    } catch (const std::exception& error) {
        std::cerr << "voxc: internal error (rank " << rank << "): " << error.what() << "\n";
        MPI_Abort(MPI_COMM_WORLD, 2);
    }
    sleepingBarrier();
    MPI_Finalize();
    return summary;
}

} // namespace voxc::world
