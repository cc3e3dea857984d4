#include "voxc/vulkan/GpuMesher.h"

#include "DeviceBuffer.h"
#include "CommandSlot.h"
#include "ExecutorVoxels.h"
#include "GpuMesherCells.h"
#include "GpuMesherPipelines.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/MarchingCubes.h"

#include <fmt/format.h>
#include <glm/ext/vector_double3.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstring>
#include <functional>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace voxc {

using namespace vulkan_detail;

namespace {

constexpr uint32_t kGroupSize = 64;        // local size of the passes
constexpr uint32_t kTileSegments = kTileSide * kTileSide; // rows of a tile's cells along x
constexpr uint32_t kVertexWords = 8;       // position, normal, material, padding: two texels (mc_vertices.glsl)

struct Access {
    VkPipelineStageFlags stage;
    VkAccessFlags access;
};
constexpr Access kCompute{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
constexpr Access kTransfer{VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT};
constexpr Access kComputeOrTransfer{kCompute.stage | kTransfer.stage, kCompute.access | kTransfer.access};
constexpr Access kHostRead{VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT};

// Between dispatches: the next one starts only after the last one's writes are visible to it.
void memoryBarrier(const VulkanApi& api, VkCommandBuffer cmd, Access before, Access after) {
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = before.access;
    b.dstAccessMask = after.access;
    api.vkCmdPipelineBarrier(cmd, before.stage, after.stage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

std::string mib(uint64_t bytes) { return fmt::format("{:.1f} MiB", double(bytes) / (1 << 20)); }

uint32_t groupsOf(uint64_t items, uint32_t perGroup) { return uint32_t((items + perGroup - 1) / perGroup); }

constexpr uint32_t kSolidTileState = 0xffu, kAirTileState = 0xffu << 8; // all eight regions solid, all air

// The states of the voxel tiles (`n` per axis from world tile `tileFirst`) that the grid's tile
// ranges put on one side of iso, as mc_tiles.glsl would record them; the indices of the others
// (all of them without ranges), which mc_tiles.glsl reads, go to `unknown`. A tile's voxels
// outside the grid read 0, as there.
void knownTileStates(const TileRanges* ranges, float iso, glm::ivec3 tileFirst, glm::ivec3 n, const ChunkLayout& layout,
                     uint32_t* states, std::vector<uint32_t>& unknown) {
    unknown.clear();
    uint32_t i = 0;
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x, ++i) {
                if (!ranges) {
                    unknown.push_back(i);
                    continue;
                }
                const glm::ivec3 tile = tileFirst + glm::ivec3(x, y, z);
                const glm::ivec3 first = (tile << kTileShift) - layout.gridOrigin, last = first + int(kTileSide) - 1;
                float low = 0.0f, high = 0.0f;
                if (glm::all(glm::greaterThanEqual(last, glm::ivec3(0))) && glm::all(glm::lessThan(first, layout.gridSize))) {
                    const TileRanges::Range& range = ranges->at(tile);
                    low = range.low;
                    high = range.high;
                    if (glm::any(glm::lessThan(first, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(last, layout.gridSize))) {
                        low = std::min(low, 0.0f); // across the grid's border
                        high = std::max(high, 0.0f);
                    }
                }
                if (low > iso)
                    states[i] = kSolidTileState;
                else if (high <= iso)
                    states[i] = kAirTileState;
                else
                    unknown.push_back(i);
            }
}

// What the host makes of mc_tiles.glsl's tile states: the tiles of cells the later passes visit,
// ranked in tile order (z, then y, then x), and their segments in global key order.
struct TileLists {
    std::vector<uint32_t> activeTiles;  // by rank: the tile's index
    std::vector<uint32_t> segments;     // in global key order: rank * 64 + z * 8 + y within the tile
    // By rank, four words (mc_count.glsl): the tile's index, then the index in global key order of
    // its segment (y, z) within the tile = x + y * y' + z * z' (x wraps below 0 where the tile's
    // first rows are not listed).
    std::vector<uint32_t> countTiles;
    size_t crossedTiles = 0;
    size_t cells = 0;                   // the cells of the listed segments
    std::vector<uint8_t> chunkCrossed;  // per world chunk holding cells
    // Per row of tiles (y, z): its first rank, and the cells of one row of cells across its
    // listed tiles (a segment's cells are fewer at the grid's x ends).
    std::vector<uint32_t> rowStart;
    std::vector<size_t> rowCells;
};

// A tile of cells reads its voxel tile and the low x face, y face, z face, xy, xz and yz edges
// and corner of the voxel tiles after it: region r (bit r of a state) of the tile at offset r.
constexpr glm::ivec3 kRegionTile[8] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};

// Into `lists`, whose vectors keep their memory from one mesh to the next (growing them anew took
// a few tenths of a millisecond at 256^3).
void listTiles(const uint32_t* states, glm::ivec3 tileFirst, glm::ivec3 n, const ChunkLayout& layout, bool skip, TileLists& lists) {
    const glm::ivec3 v = n + 1; // voxel tiles per axis
    const glm::ivec3 chunkFirst = (layout.gridOrigin - 1) >> layout.chunkShift;
    const glm::ivec3 chunks = ((layout.gridOrigin + layout.gridSize - 1) >> layout.chunkShift) - chunkFirst + 1;
    lists.activeTiles.clear();
    lists.segments.clear();
    lists.countTiles.clear();
    lists.crossedTiles = 0;
    lists.cells = 0;
    lists.chunkCrossed.assign(size_t(chunks.x) * size_t(chunks.y) * size_t(chunks.z), 0);
    std::vector<uint32_t>& rowStart = lists.rowStart;
    rowStart.clear();
    lists.rowCells.clear();
    const glm::ivec3 firstCell = tileFirst << kTileShift;
    size_t tile = 0;
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y) {
            rowStart.push_back(uint32_t(lists.activeTiles.size()));
            size_t rowCells = 0;
            for (int x = 0; x < n.x; ++x, ++tile) {
                uint32_t solid = 0, air = 0;
                for (uint32_t r = 0; r < 8; ++r) {
                    const glm::ivec3 t = glm::ivec3(x, y, z) + kRegionTile[r];
                    const uint32_t state = states[size_t(t.x) + size_t(v.x) * (size_t(t.y) + size_t(v.y) * size_t(t.z))];
                    solid |= (state >> r) & 1u;
                    air |= (state >> (8 + r)) & 1u;
                }
                const bool crossed = solid && air;
                if (crossed) {
                    ++lists.crossedTiles;
                    const glm::ivec3 chunk = (((tileFirst + glm::ivec3(x, y, z)) << kTileShift) >> layout.chunkShift) - chunkFirst;
                    lists.chunkCrossed[size_t(chunk.x) + size_t(chunks.x) * (size_t(chunk.y) + size_t(chunks.y) * size_t(chunk.z))] = 1;
                }
                if (!crossed && skip) continue;
                lists.activeTiles.push_back(uint32_t(tile));
                const int tileX = firstCell.x + x * int(kTileSide) - layout.gridOrigin.x;
                rowCells += size_t(std::min(tileX + int(kTileSide), layout.gridSize.x) - std::max(tileX, -1));
            }
            lists.rowCells.push_back(rowCells);
        }
    rowStart.push_back(uint32_t(lists.activeTiles.size()));
    // Global key order: z, then y, then x; a row of cells (y, z) crosses the tiles of tile row
    // (y >> 3, z >> 3) in x order, which is their rank order. Rows outside the cells have none.
    auto insideCells = [&](int axis, int world) {
        const int local = world - layout.gridOrigin[axis];
        return local >= -1 && local < layout.gridSize[axis];
    };
    // The listed rows of tile t along `axis`: from `first` within the tile, `count` of them.
    auto listedRows = [&](int axis, int t, uint32_t& first) {
        uint32_t count = 0;
        first = 0;
        for (uint32_t i = kTileSide; i-- > 0;)
            if (insideCells(axis, firstCell[axis] + t * int(kTileSide) + int(i))) {
                first = i;
                ++count;
            }
        return count;
    };
    uint32_t layerFirst = 0; // the index of the first segment of the layer of tiles at z
    for (int z = 0; z < n.z; ++z) {
        uint32_t firstZ = 0;
        const uint32_t rowsZ = listedRows(2, z, firstZ);
        uint32_t perRow = 0; // segments per row of cells of the layer
        for (int y = 0; y < n.y; ++y) {
            const size_t row = size_t(z) * size_t(n.y) + size_t(y);
            uint32_t firstY = 0;
            perRow += (rowStart[row + 1] - rowStart[row]) * listedRows(1, y, firstY);
        }
        uint32_t before = 0; // the segments of a row of cells in the rows of tiles before y
        for (int y = 0; y < n.y; ++y) {
            const size_t row = size_t(z) * size_t(n.y) + size_t(y);
            uint32_t firstY = 0;
            const uint32_t rowsY = listedRows(1, y, firstY), tiles = rowStart[row + 1] - rowStart[row];
            for (uint32_t rank = rowStart[row]; rank < rowStart[row + 1]; ++rank)
                lists.countTiles.insert(lists.countTiles.end(), {lists.activeTiles[rank],
                                                                 layerFirst + before + (rank - rowStart[row]) - firstY * tiles - firstZ * perRow,
                                                                 tiles, perRow});
            before += tiles * rowsY;
        }
        layerFirst += perRow * rowsZ;
    }
    for (int z = 0; z < n.z; ++z)
        for (uint32_t inZ = 0; inZ < kTileSide; ++inZ) {
            if (!insideCells(2, firstCell.z + z * int(kTileSide) + int(inZ))) continue;
            for (int y = 0; y < n.y; ++y)
                for (uint32_t inY = 0; inY < kTileSide; ++inY) {
                    if (!insideCells(1, firstCell.y + y * int(kTileSide) + int(inY))) continue;
                    const size_t row = size_t(z) * size_t(n.y) + size_t(y);
                    for (uint32_t rank = rowStart[row]; rank < rowStart[row + 1]; ++rank)
                        lists.segments.push_back(rank * kTileSegments + inZ * kTileSide + inY);
                    lists.cells += lists.rowCells[row];
                }
        }
    VOXC_ASSERT(layerFirst == lists.segments.size());
}

// Per case: the crossed edges a cell of the case owns (those leaving its minimum corner: bit a
// for axis a) | its triangle count << 3 | the case << 19, the word of an active cell (makeTriangles
// and mc_materials.glsl read it).
std::array<uint32_t, 256> cellWords() {
    std::array<uint32_t, 256> words{};
    const auto& table = marching_cubes::caseTable();
    for (uint32_t mask = 0; mask < 256; ++mask) {
        // listCells takes a cell to be active when its case is neither all air nor all solid.
        VOXC_ASSERT((table[mask].triangleCount > 0) == (mask != 0 && mask != 255));
        VOXC_ASSERT(table[mask].triangleCount <= 15);
        const uint32_t lower = mask & 1u;
        const uint32_t owned = (lower ^ ((mask >> 1) & 1u)) | (lower ^ ((mask >> 2) & 1u)) << 1 | (lower ^ ((mask >> 4) & 1u)) << 2;
        words[mask] = owned | uint32_t(table[mask].triangleCount) << 3 | mask << 19;
    }
    return words;
}

// The host's step between the count and emit passes, over the segments' cases (mc_count.glsl) in
// global key order: the active cells (neither all air nor all solid: every other case has a
// triangle, which cellWords checks) with their first vertex and triangle, and every vertex
// with its owner cell and axis, in the CPU mesher's order (vertices by global edge, triangles by cell).
// Sequential and a few loads and stores per active cell: on lavapipe the same lists took a pass
// over every segment with a prefix sum before it, several times longer. `activeCells` gets
// kActiveCellWords per active cell, `vertexEdges` per vertex its owner's slot | axis << 30 (slots
// are below 2^30). Over the segments [begin, end), numbering their vertices and triangles from 0
// (listCellsInPieces moves them past the segments before); returns their vertex and triangle counts.
struct CellTotals {
    uint64_t vertices = 0, triangles = 0;
};

CellTotals listCells(const uint32_t* cases, const TileLists& lists, size_t begin, size_t end, glm::ivec3 tileFirst, glm::ivec3 n,
                     const ChunkLayout& layout, std::vector<uint32_t>& activeCells, std::vector<uint32_t>& vertexEdges) {
    static const std::array<uint32_t, 256> kCellWords = cellWords();
    activeCells.clear();
    vertexEdges.clear();
    uint64_t vertices = 0, triangles = 0;
    constexpr uint64_t kLow7 = 0x7f7f7f7f7f7f7f7full;
    // The high bit of each byte of `v` that is zero.
    auto zeroBytes = [](uint64_t v) { return ~(((v & kLow7) + kLow7) | v | kLow7); };
    for (size_t index = begin; index < end; ++index) {
        const uint64_t bytes = uint64_t(cases[2 * index]) | uint64_t(cases[2 * index + 1]) << 32;
        // A cell is active when its case is neither 0 nor 0xff; the cells past the grid read 0.
        uint64_t active = ~(zeroBytes(bytes) | zeroBytes(~bytes)) & ~kLow7;
        if (active == 0) continue;
        const uint32_t segment = lists.segments[index], tile = lists.activeTiles[segment / kTileSegments];
        const int32_t x = (tileFirst.x + int32_t(tile % uint32_t(n.x))) * int32_t(kTileSide) - layout.gridOrigin.x; // its first cell, grid-local
        // Byte i: the cell at slot firstSlot + i (mc_common.glsl).
        const uint32_t firstSlot = tile * kTileCells + segment % kTileSegments * kTileSide + uint32_t(std::max(x, -1) - x);
        for (; active != 0; active &= active - 1) {
            const uint32_t i = uint32_t(std::countr_zero(active)) / 8;
            const uint32_t word = kCellWords[(bytes >> (8 * i)) & 0xffu], slot = firstSlot + i, edges = word & 7u;
            activeCells.insert(activeCells.end(), {slot, uint32_t(vertices), uint32_t(triangles), word});
            triangles += (word >> 3) & 15u;
            if (edges == 0) continue;
            for (uint32_t left = edges; left != 0; left &= left - 1)
                vertexEdges.push_back(slot | uint32_t(std::countr_zero(left)) << 30);
            // The bits set in `edges` (3 bits), by a nibble per value: std::popcount is a library
            // call where the target has no popcnt instruction.
            vertices += (0x32212110u >> (4 * edges)) & 0xfu;
        }
    }
    return {vertices, triangles};
}

// A second thread for the host's steps between and after the passes, started once: a thread
// started for each step begins late while another process holds the second core (the scheduler
// lets a new thread wait its turn), and waiting for it to begin cost up to 3 ms a step at load 2.
class HelperThread {
public:
    HelperThread() : thread_([this] { loop(); }) {}
    HelperThread(const HelperThread&) = delete;
    HelperThread& operator=(const HelperThread&) = delete;
    ~HelperThread() {
        {
            std::lock_guard lock(mutex_);
            stop_ = true;
        }
        wake_.notify_one();
        thread_.join();
    }

    // Runs work(i) for i in [0, count) on the calling thread and the helper, each taking the next
    // i in turn. Once the caller runs out, it takes the job back where the helper has not woken
    // yet, and otherwise waits only for the piece the helper holds.
    void share(size_t count, const std::function<void(size_t)>& work) {
        std::atomic<size_t> next{0};
        auto run = [&] {
            for (size_t i = next++; i < count; i = next++) work(i);
        };
        if (count > 1) {
            std::lock_guard lock(mutex_);
            job_ = [&] {
                try {
                    run();
                } catch (...) {
                    next = count;
                    throw;
                }
            };
        }
        wake_.notify_one();
        std::exception_ptr failure;
        try {
            run();
        } catch (...) {
            next = count;
            failure = std::current_exception();
        }
        std::unique_lock lock(mutex_);
        job_ = nullptr; // not taken: the helper never starts it
        done_.wait(lock, [&] { return !busy_; });
        if (!failure) failure = std::exchange(helperFailure_, nullptr);
        helperFailure_ = nullptr;
        if (failure) std::rethrow_exception(failure);
    }

private:
    void loop() {
        std::unique_lock lock(mutex_);
        for (;;) {
            wake_.wait(lock, [&] { return stop_ || job_; });
            if (stop_) return;
            const std::function<void()> job = std::exchange(job_, nullptr);
            busy_ = true;
            lock.unlock();
            std::exception_ptr failure;
            try {
                job();
            } catch (...) {
                failure = std::current_exception();
            }
            lock.lock();
            helperFailure_ = failure;
            busy_ = false;
            done_.notify_all();
        }
    }

    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::function<void()> job_; // set while a share() call offers its pieces
    bool busy_ = false, stop_ = false;
    std::exception_ptr helperFailure_;
    std::thread thread_; // last: it starts once the members above exist
};

// listCells' lists over one piece of the segments, numbered from 0 within the piece.
struct CellPiece {
    std::vector<uint32_t> activeCells, vertexEdges;
    CellTotals totals;
    CellTotals first;          // the vertices and triangles of the pieces before
    size_t firstActiveWord = 0; // the words of their active cells
};

// Vertices or triangles per piece of the copy out of the device's buffers.
constexpr size_t kSplitRoom = 1024; // vertices the mesh's vectors have room for past the edges' (normal splits)
constexpr uint32_t kVertexPiece = 1u << 14; // vertices per piece of their copy: a few pieces a thread
constexpr uint32_t kCellPiece = 1u << 14;   // active cells per piece of the triangles

// Segments per piece of listCellsInPieces: a few pieces a 256^3 grid, one for a small grid.
constexpr size_t kSegmentsPerPiece = size_t(1) << 14;

// listCells over every segment, on this thread and the helper, in pieces of consecutive
// segments: each piece's lists are numbered from 0; then each piece's lists go to their place in
// the mapped `activeCells` and `vertexEdges` (`place`, given the totals, returns those buffers'
// words) with its first vertices and triangles moved past the pieces before, and each owner's
// word (owned edges | first vertex << 3) to its slot in `cellInfo` (written once there: written
// in the first step and moved in the second, a random access each time, the step took about 0.1
// ms more at 256^3). The result is listCells' over all the segments at once. The device waits for
// these lists, so the host's second core is otherwise idle (at 256^3 they took 2.5 ms on one
// thread).
CellTotals listCellsInPieces(HelperThread& helper, const uint32_t* cases, const TileLists& lists, glm::ivec3 tileFirst,
                             glm::ivec3 n, const ChunkLayout& layout, uint32_t* cellInfo, std::vector<CellPiece>& pieces,
                             const std::function<std::pair<uint32_t*, uint32_t*>(size_t activeWords, CellTotals)>& place) {
    const size_t count = lists.segments.size(), pieceCount = std::max<size_t>(1, count / kSegmentsPerPiece);
    pieces.resize(pieceCount);
    helper.share(pieceCount, [&](size_t p) {
        CellPiece& piece = pieces[p];
        piece.totals = listCells(cases, lists, count * p / pieceCount, count * (p + 1) / pieceCount, tileFirst, n, layout,
                                 piece.activeCells, piece.vertexEdges);
    });
    CellTotals all;
    size_t activeWords = 0;
    for (CellPiece& piece : pieces) {
        piece.first = all;
        piece.firstActiveWord = activeWords;
        all.vertices += piece.totals.vertices;
        all.triangles += piece.totals.triangles;
        activeWords += piece.activeCells.size();
    }
    const auto [activeOut, vertexOut] = place(activeWords, all);
    helper.share(pieceCount, [&](size_t p) {
        const CellPiece& piece = pieces[p];
        const uint32_t firstVertex = uint32_t(piece.first.vertices), firstTriangle = uint32_t(piece.first.triangles);
        std::memcpy(vertexOut + piece.first.vertices, piece.vertexEdges.data(), piece.vertexEdges.size() * sizeof(uint32_t));
        uint32_t* out = activeOut + piece.firstActiveWord;
        for (size_t i = 0; i < piece.activeCells.size(); i += kActiveCellWords) {
            const uint32_t* cell = &piece.activeCells[i];
            out[i] = cell[0];
            out[i + 1] = cell[1] + firstVertex;
            out[i + 2] = cell[2] + firstTriangle;
            out[i + 3] = cell[3];
            if ((cell[3] & 7u) != 0) cellInfo[cell[0]] = (cell[3] & 7u) | out[i + 1] << 3; // an owner's edges and first vertex
        }
    });
    return all;
}

} // namespace

struct GpuMarchingCubes::Impl {
    ExecutorVoxels source;
    VulkanContext::Impl& ctx;
    ChunkLayout layout;
    glm::ivec3 tileFirst{0}, tileCount{0}; // world 8^3 tiles holding cells
    uint32_t tiles = 0;                    // of cells; the voxel tiles are one more per axis
    uint32_t voxelTiles = 0;
    McPipelines pipelines;
    // Host-visible: tileStates (written by mc_tiles), the tiles it reads (unknownTiles), the lists
    // the host makes from their states (countTiles, the active tiles for mc_count) and from the
    // segments' cases (activeCells, vertexEdges), and `results` (the cases, then the vertices and
    // materials, where they are copied). segmentCases, vertices and cellMaterials: meshUse().
    DeviceBuffer tileStates, unknownTiles, countTiles, segmentCases, activeCells, vertexEdges, vertices, cellMaterials, results;
    // Per cell slot (the tiles of cells' every cell, mc_common.glsl) that owns vertices: its owned
    // edges | first vertex << 3, written by listCellsInPieces, read by makeTriangles.
    std::vector<uint32_t> cellInfo;
    TileLists tileLists;               // listTiles' lists, kept so that a repeated call reuses their memory
    std::vector<uint32_t> unknownTileList; // knownTileStates' list, likewise
    std::vector<CellPiece> cellPieces; // listCellsInPieces' lists, kept so that a repeated call reuses their memory
    std::vector<uint8_t> against;      // per vertex: its normal is to be re-derived (orientFlaggedNormals)
    std::vector<uint32_t> incident, incidentList; // and the triangles of those vertices (incidentTriangles)
    std::vector<glm::ivec3> tileCells;            // tileFirstCells
    HelperThread helper;               // the host's second thread for its steps
    // At the texel bindings: views of the executor's buffers and of these (bindAll).
    std::array<VkBufferView, kMcBindingCount> texelViews{};
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;

    Impl(VulkanExecutor& executor) : source(executor.deviceVoxels()), ctx(*source.context), layout(executor.layout()) {}
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl();

    void checkLimits() const;
    void createBuffers();
    void destroyTexelViews();
    // A buffer of at least `bytes` (storage, texels, transfer source/destination), replaced when
    // smaller; true when replaced (a new buffer may reuse the old handle's value, so callers
    // cannot compare handles to know whether descriptors need an update).
    bool ensureBuffer(DeviceBuffer& buffer, VkDeviceSize bytes, MemoryUse use);
    // Where the device's memory is the host's (a CPU device such as lavapipe, an integrated GPU),
    // the passes write the mesh into mapped memory that the host reads in place (HostAccess);
    // elsewhere into device memory, copied to a mapped buffer after the passes.
    MemoryUse meshUse() const { return unifiedMemory(ctx) ? MemoryUse::HostAccess : MemoryUse::Device; }
    // Copies `words` into the host-visible `buffer` for the device; true when the buffer was replaced.
    bool upload(DeviceBuffer& buffer, const std::vector<uint32_t>& words);
    // Points every binding at its buffer, through new texel views where it is read as texels.
    void bindAll();
    McPush push(const MeshOptions& options) const;
    // Records `groups` workgroups of `pass`, split over x and y where x alone is not enough.
    void dispatch(McPass pass, McPush& push, uint32_t groups, uint32_t items);
    void begin();
    void submit();
    void wait(); // for the last submit
    void submitAndWait();
};

GpuMarchingCubes::Impl::~Impl() {
    if (ctx.device) ctx.api.vkDeviceWaitIdle(ctx.device);
    if (fence) ctx.api.vkDestroyFence(ctx.device, fence, nullptr);
    if (commandPool) ctx.api.vkDestroyCommandPool(ctx.device, commandPool, nullptr);
    destroyTexelViews();
    for (DeviceBuffer* b : {&results, &cellMaterials, &vertices, &vertexEdges, &activeCells, &segmentCases, &countTiles,
                            &unknownTiles, &tileStates})
        destroyBuffer(ctx, *b);
    destroyMcPipelines(ctx, pipelines);
}

void GpuMarchingCubes::Impl::checkLimits() const {
    if (!ctx.shaderFloat64)
        throw UserError(fmt::format("the Vulkan device '{}' has no shaderFloat64, which marching cubes on the device needs "
                                    "(edge crossings are computed in double, as on the CPU); mesh on the host instead "
                                    "(voxc run --mesh-on host)",
                                    ctx.info.name));
    // The passes fetch the voxels as texels (mc_common.glsl).
    const uint64_t voxels = uint64_t(layout.chunkTotal()) * layout.chunkVoxels();
    const uint64_t maxTexels = ctx.properties.limits.maxTexelBufferElements;
    if (voxels > maxTexels)
        throw UserError(fmt::format("marching cubes on the device reads the {} voxels of the {}x{}x{} grid's chunks as "
                                    "texels, more than the Vulkan device '{}' can address ({}); mesh on the host instead "
                                    "(voxc run --mesh-on host) or use a smaller grid",
                                    voxels, layout.gridSize.x, layout.gridSize.y, layout.gridSize.z, ctx.info.name, maxTexels));
    const uint64_t maxRange = ctx.properties.limits.maxStorageBufferRange;
    // The largest buffer a pass binds as storage holds a byte per cell of the active tiles at most
    // (segmentCases); cells are named by slots below 2^30, as the vertex list needs, and triangle
    // places are 32-bit sums of up to 12 triangles per cell (both by the first test below); the
    // passes find a tile's coordinates from its index below 2^21 (mc_common.glsl, tileCoordinates).
    const uint64_t slots = uint64_t(tiles) * kTileCells;
    const uint64_t caseBytes = slots;
    if (slots * marching_cubes::kMaxTrianglesPerCell > UINT32_MAX || caseBytes > maxRange || voxelTiles >= (1u << 21))
        throw UserError(fmt::format("marching cubes on the device needs {} buffers for the {} cells of a {}x{}x{} grid's tiles, "
                                    "more than the Vulkan device '{}' can bind ({}); mesh on the host instead "
                                    "(voxc run --mesh-on host) or use a smaller grid",
                                    mib(caseBytes), slots, layout.gridSize.x, layout.gridSize.y, layout.gridSize.z,
                                    ctx.info.name, mib(maxRange)));
}

bool GpuMarchingCubes::Impl::ensureBuffer(DeviceBuffer& buffer, VkDeviceSize bytes, MemoryUse use) {
    if (buffer.buffer && buffer.size >= bytes) return false;
    destroyBuffer(ctx, buffer);
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT |
                                     VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                     VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    buffer = createBuffer(ctx, std::max<VkDeviceSize>(bytes, 16), usage, use);
    return true;
}

bool GpuMarchingCubes::Impl::upload(DeviceBuffer& buffer, const std::vector<uint32_t>& words) {
    const bool replaced = ensureBuffer(buffer, words.size() * sizeof(uint32_t), MemoryUse::HostAccess);
    std::memcpy(buffer.mapped, words.data(), words.size() * sizeof(uint32_t));
    flushForDevice(ctx, buffer); // the queue submit makes it visible to the device
    return replaced;
}

void GpuMarchingCubes::Impl::createBuffers() {
    ensureBuffer(tileStates, VkDeviceSize(voxelTiles) * sizeof(uint32_t), MemoryUse::HostAccess);
    // Placeholders until a mesh has active tiles and triangles: every binding of the set must name a buffer.
    for (DeviceBuffer* b : {&unknownTiles, &countTiles, &activeCells, &vertexEdges})
        ensureBuffer(*b, 16, MemoryUse::HostAccess);
    for (DeviceBuffer* b : {&segmentCases, &vertices, &cellMaterials}) ensureBuffer(*b, 16, meshUse());
    ensureBuffer(results, 16, MemoryUse::HostAccess);
}

void GpuMarchingCubes::Impl::bindAll() {
    std::array<VkBuffer, kMcBindingCount> buffers{};
    buffers[kMcTileStates] = tileStates.buffer;
    buffers[kMcSegmentCases] = segmentCases.buffer;
    struct View {
        McBinding binding;
        VkBuffer buffer;
        VkFormat format;
    };
    const View views[] = {{kMcDensityTexels, source.voxels, VK_FORMAT_R32_SFLOAT},
                          {kMcQuadTexels, source.voxels, VK_FORMAT_R32G32B32A32_SFLOAT},
                          {kMcMaterialTexels, source.materials, VK_FORMAT_R32_UINT},
                          {kMcUnknownTileTexels, unknownTiles.buffer, VK_FORMAT_R32_UINT},
                          {kMcCountTileTexels, countTiles.buffer, VK_FORMAT_R32G32B32A32_UINT},
                          {kMcActiveCellTexels, activeCells.buffer, VK_FORMAT_R32G32B32A32_UINT},
                          {kMcVertexEdgeTexels, vertexEdges.buffer, VK_FORMAT_R32_UINT},
                          {kMcCellMaterials, cellMaterials.buffer, VK_FORMAT_R32_UINT},
                          {kMcVertices, vertices.buffer, VK_FORMAT_R32G32B32A32_UINT}};
    destroyTexelViews();
    for (const View& view : views) {
        VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
        info.buffer = view.buffer;
        info.format = view.format;
        info.offset = 0;
        info.range = VK_WHOLE_SIZE;
        check(ctx.api.vkCreateBufferView(ctx.device, &info, nullptr, &texelViews[view.binding]), "vkCreateBufferView");
    }
    bindMcSet(ctx, pipelines, buffers, texelViews);
}

void GpuMarchingCubes::Impl::destroyTexelViews() {
    for (VkBufferView& view : texelViews) {
        if (view) ctx.api.vkDestroyBufferView(ctx.device, view, nullptr);
        view = VK_NULL_HANDLE;
    }
}

McPush GpuMarchingCubes::Impl::push(const MeshOptions& options) const {
    McPush p{};
    for (int a = 0; a < 3; ++a) {
        p.gridOrigin[a] = layout.gridOrigin[a];
        p.gridSize[a] = layout.gridSize[a];
        p.chunkBase[a] = layout.chunkBase[a];
        p.tileFirst[a] = tileFirst[a];
        p.tileCount[a] = tileCount[a];
    }
    p.gridOrigin[3] = layout.chunkShift;
    p.chunkBase[3] = layout.chunkCount.x;
    p.tileFirst[3] = layout.chunkCount.y;
    const float margin = marching_cubes::crossingMargin(layout);
    p.surface[0] = options.iso;
    p.surface[1] = margin;
    p.surface[2] = 1.0f - margin;
    return p;
}

void GpuMarchingCubes::Impl::dispatch(McPass pass, McPush& push, uint32_t groups, uint32_t items) {
    const uint32_t maxX = ctx.properties.limits.maxComputeWorkGroupCount[0];
    const uint32_t x = std::min(groups, maxX), y = (groups + x - 1) / x;
    VOXC_ASSERT(y <= ctx.properties.limits.maxComputeWorkGroupCount[1]); // groups < 2^32 / 64 by checkLimits
    push.pass[0] = x;
    push.pass[1] = items;
    ctx.api.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines.pipelines[pass]);
    ctx.api.vkCmdPushConstants(cmd, pipelines.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(McPush), &push);
    ctx.api.vkCmdDispatch(cmd, x, y, 1);
}

void GpuMarchingCubes::Impl::begin() {
    check(ctx.api.vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(ctx.api.vkBeginCommandBuffer(cmd, &info), "vkBeginCommandBuffer");
    // The executor's writes (and this mesher's earlier reads of its own buffers) come first.
    memoryBarrier(ctx.api, cmd, kComputeOrTransfer, kComputeOrTransfer);
    ctx.api.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines.layout, 0, 1, &pipelines.set, 0, nullptr);
}

void GpuMarchingCubes::Impl::submit() {
    check(ctx.api.vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    info.commandBufferCount = 1;
    info.pCommandBuffers = &cmd;
    check(ctx.api.vkQueueSubmit(ctx.queue, 1, &info, fence), "vkQueueSubmit");
}

void GpuMarchingCubes::Impl::wait() {
    check(ctx.api.vkWaitForFences(ctx.device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(ctx.api.vkResetFences(ctx.device, 1, &fence), "vkResetFences");
}

void GpuMarchingCubes::Impl::submitAndWait() {
    submit();
    wait();
}

GpuMarchingCubes::GpuMarchingCubes(VulkanExecutor& executor) : impl_(std::make_unique<Impl>(executor)) {
    Impl& s = *impl_;
    const glm::ivec3 last = (s.layout.gridOrigin + s.layout.gridSize - 1) >> kTileShift;
    s.tileFirst = (s.layout.gridOrigin - 1) >> kTileShift; // the cells run from -1 to gridSize - 1
    s.tileCount = last - s.tileFirst + 1;
    s.tiles = uint32_t(s.tileCount.x) * uint32_t(s.tileCount.y) * uint32_t(s.tileCount.z);
    s.voxelTiles = uint32_t(s.tileCount.x + 1) * uint32_t(s.tileCount.y + 1) * uint32_t(s.tileCount.z + 1);
    s.checkLimits();
    s.tileCells = tileFirstCells(s.tileFirst, s.tileCount, s.layout);
    createMcPipelines(s.ctx, s.source.hasMaterials, s.pipelines);
    s.createBuffers();
    s.bindAll();
    const CommandSlot slot = createCommandSlot(s.ctx);
    s.commandPool = slot.pool;
    s.cmd = slot.commands;
    s.fence = slot.fence;
}

GpuMarchingCubes::~GpuMarchingCubes() = default;

Mesh GpuMarchingCubes::mesh(const MeshOptions& options, MeshStats* stats) {
    Impl& s = *impl_;
    if (!s.source.hasRun) throw InternalError("GPU marching cubes: the executor has not run, its voxel buffer holds no grid");
    const VulkanApi& api = s.ctx.api;
    McPush push = s.push(options);

    // The voxel tiles' states (from the executor's tile ranges where they settle a tile, else
    // from its voxels), then on the host the tiles of cells the surface crosses (all of them when
    // uniform regions are not skipped) and their segments.
    const std::optional<TileRanges>& ranges = *s.source.tileRanges;
    std::vector<uint32_t>& unknown = s.unknownTileList;
    knownTileStates(ranges && options.skipUniformChunks ? &*ranges : nullptr, options.iso, s.tileFirst, s.tileCount + 1, s.layout,
                    static_cast<uint32_t*>(s.tileStates.mapped), unknown);
    flushForDevice(s.ctx, s.tileStates); // the queue submit makes it visible to the device
    if (!unknown.empty()) {
        if (s.upload(s.unknownTiles, unknown)) s.bindAll();
        s.begin();
        s.dispatch(kMcTiles, push, groupsOf(unknown.size(), kGroupSize), uint32_t(unknown.size()));
        memoryBarrier(api, s.cmd, kCompute, kHostRead);
        s.submitAndWait();
    }
    invalidateForHost(s.ctx, s.tileStates);
    TileLists& lists = s.tileLists;
    listTiles(static_cast<const uint32_t*>(s.tileStates.mapped), s.tileFirst, s.tileCount, s.layout, options.skipUniformChunks,
              lists);
    if (stats) {
        *stats = MeshStats{lists.chunkCrossed.size(), 0};
        if (options.skipUniformChunks)
            stats->skippedChunks = size_t(std::count(lists.chunkCrossed.begin(), lists.chunkCrossed.end(), uint8_t(0)));
        stats->tiles = s.tiles;
        stats->activeTiles = lists.crossedTiles;
        stats->cellsVisited = lists.cells;
    }
    Mesh mesh;
    const uint32_t segmentCount = uint32_t(lists.segments.size());
    if (segmentCount == 0) return mesh;

    // The cases of the segments' cells, then on the host the lists of the active cells and the
    // vertices (cellInfo; activeCells and vertexEdges in place).
    bool rebind = s.upload(s.countTiles, lists.countTiles);
    const uint32_t tileCount = uint32_t(lists.activeTiles.size());
    const VkDeviceSize caseBytes = VkDeviceSize(segmentCount) * 2 * sizeof(uint32_t);
    const bool inPlace = s.meshUse() == MemoryUse::HostAccess;
    rebind |= s.ensureBuffer(s.segmentCases, caseBytes, s.meshUse());
    s.cellInfo.resize(size_t(s.tiles) * kTileCells); // allocated by the first mesh
    if (!inPlace) s.ensureBuffer(s.results, caseBytes, MemoryUse::HostAccess); // bound to no pass
    if (rebind) s.bindAll();
    s.begin();
    s.dispatch(kMcCount, push, groupsOf(tileCount, kGroupSize), tileCount);
    const DeviceBuffer* caseSource = &s.segmentCases;
    if (!inPlace) {
        memoryBarrier(api, s.cmd, kCompute, kTransfer);
        const VkBufferCopy copy{0, 0, caseBytes};
        api.vkCmdCopyBuffer(s.cmd, s.segmentCases.buffer, s.results.buffer, 1, &copy);
        memoryBarrier(api, s.cmd, kTransfer, kHostRead);
        caseSource = &s.results;
    } else {
        memoryBarrier(api, s.cmd, kCompute, kHostRead);
    }
    s.submitAndWait();
    invalidateForHost(s.ctx, *caseSource);
    // Emit into buffers of the counted size, written as texels (two a vertex, one an active cell's
    // material), over the active cells' list read as texels (one a cell). At most
    // maxTexelBufferElements texels a buffer, and below 2^29 vertices: cellInfo keeps a first
    // vertex above 3 bits of a word.
    bool replaced = false;
    size_t activeWords = 0;
    const CellTotals cells = listCellsInPieces(
        s.helper, static_cast<const uint32_t*>(caseSource->mapped), lists, s.tileFirst, s.tileCount, s.layout,
        s.cellInfo.data(), s.cellPieces, [&](size_t words, CellTotals totals) {
            const uint64_t maxCells = s.ctx.properties.limits.maxTexelBufferElements;
            const uint64_t maxVertices = std::min<uint64_t>(maxCells / 2, (uint64_t(1) << 29) - 1);
            const uint64_t activeCount = words / kActiveCellWords;
            if (totals.vertices > maxVertices || activeCount > maxCells)
                throw UserError(fmt::format("the mesh has {} vertices in {} cells, more than marching cubes on the Vulkan "
                                            "device '{}' can write ({} vertices, {} cells); mesh on the host instead "
                                            "(voxc run --mesh-on host)",
                                            totals.vertices, activeCount, s.ctx.info.name, maxVertices, maxCells));
            activeWords = words;
            replaced |= s.ensureBuffer(s.activeCells, words * sizeof(uint32_t), MemoryUse::HostAccess);
            replaced |= s.ensureBuffer(s.vertexEdges, totals.vertices * sizeof(uint32_t), MemoryUse::HostAccess);
            return std::pair(static_cast<uint32_t*>(s.activeCells.mapped), static_cast<uint32_t*>(s.vertexEdges.mapped));
        });
    if (cells.triangles == 0) return mesh;
    const uint32_t vertexCount = uint32_t(cells.vertices), triangleCount = uint32_t(cells.triangles);
    const uint32_t activeCount = uint32_t(activeWords / kActiveCellWords);
    // The queue submit makes them visible to the device.
    for (DeviceBuffer* b : {&s.activeCells, &s.vertexEdges}) flushForDevice(s.ctx, *b);
    const uint64_t vertexBytes = uint64_t(vertexCount) * kVertexWords * sizeof(uint32_t);
    const bool materials = s.source.hasMaterials;
    // Where the executor's materials are mapped (lavapipe, an integrated GPU), the host votes the
    // triangles' materials as it tests the triangles (HostVote: from the vertices' materials, and
    // the mapped words for a solid corner that ends no crossed edge; on lavapipe the device pass
    // cost more CPU time); elsewhere mc_materials.glsl does.
    const DeviceBuffer* mappedMaterials = materials ? s.source.mappedMaterials : nullptr;
    const bool deviceVote = materials && !mappedMaterials;
    const uint64_t materialBytes = deviceVote ? uint64_t(activeCount) * sizeof(uint32_t) : 0;
    replaced |= s.ensureBuffer(s.vertices, vertexBytes, s.meshUse());
    replaced |= s.ensureBuffer(s.cellMaterials, materialBytes, s.meshUse());
    if (!inPlace) s.ensureBuffer(s.results, vertexBytes + materialBytes, MemoryUse::HostAccess); // bound to no pass
    if (replaced) s.bindAll();
    // The vertices and the triangles' materials on the device, over the host's lists alone, while
    // the host makes the triangles.
    s.begin();
    s.dispatch(kMcEmitVertices, push, groupsOf(vertexCount, kGroupSize), vertexCount);
    if (deviceVote) s.dispatch(kMcEmitMaterials, push, groupsOf(activeCount, kGroupSize), activeCount);
    if (inPlace) {
        memoryBarrier(api, s.cmd, kCompute, kHostRead);
    } else {
        memoryBarrier(api, s.cmd, kCompute, kTransfer);
        const VkBufferCopy vertexCopy{0, 0, vertexBytes};
        api.vkCmdCopyBuffer(s.cmd, s.vertices.buffer, s.results.buffer, 1, &vertexCopy);
        if (deviceVote) {
            const VkBufferCopy materialCopy{0, vertexBytes, materialBytes};
            api.vkCmdCopyBuffer(s.cmd, s.cellMaterials.buffer, s.results.buffer, 1, &materialCopy);
        }
        memoryBarrier(api, s.cmd, kTransfer, kHostRead);
    }
    s.submit();
    // The vertices' vectors with room for the copies orientFlaggedNormals may append (growing
    // them took about 0.4 ms at 256^3).
    mesh.positions.reserve(vertexCount + kSplitRoom);
    mesh.normals.reserve(vertexCount + kSplitRoom);
    mesh.vertexMaterials.reserve(vertexCount + kSplitRoom);
    mesh.positions.resize(vertexCount);
    mesh.normals.resize(vertexCount);
    mesh.vertexMaterials.resize(vertexCount);
    mesh.triangles.resize(size_t(triangleCount) * 3);
    mesh.triangleMaterials.resize(triangleCount);
    const uint32_t* activeCells = static_cast<const uint32_t*>(s.activeCells.mapped);
    const size_t cellPieces = groupsOf(activeCount, kCellPiece);
    std::optional<HostVote> vote;
    if (mappedMaterials) {
        // Its writes are visible to the host: the count pass's submit ended with a barrier from
        // every earlier compute write to host reads, and was waited for.
        invalidateForHost(s.ctx, *mappedMaterials);
        vote.emplace(static_cast<const uint32_t*>(mappedMaterials->mapped), s.layout, s.tileCells);
    }
    s.helper.share(cellPieces, [&](size_t piece) {
        makeTriangles(activeCells, piece * kCellPiece, std::min<size_t>(activeCount, (piece + 1) * kCellPiece),
                      s.cellInfo.data(), s.cellInfo.size(), s.tileCount, mesh.triangles.data());
    });
    s.wait();
    const uint32_t* vertexWords = nullptr;
    const uint32_t* materialWords = nullptr;
    if (inPlace) {
        invalidateForHost(s.ctx, s.vertices);
        vertexWords = static_cast<const uint32_t*>(s.vertices.mapped);
        if (deviceVote) {
            invalidateForHost(s.ctx, s.cellMaterials);
            materialWords = static_cast<const uint32_t*>(s.cellMaterials.mapped);
        }
    } else {
        invalidateForHost(s.ctx, s.results);
        vertexWords = static_cast<const uint32_t*>(s.results.mapped);
        materialWords = vertexWords + vertexBytes / sizeof(uint32_t);
    }

    // The mesh out of the device's buffers on this thread and the helper, in pieces of vertices,
    // then of active cells (a few milliseconds at 256^3).
    auto vec3At = [&](size_t w) {
        glm::vec3 v;
        std::memcpy(&v, &vertexWords[w], sizeof v);
        return v;
    };
    // The host mesher's last step (orientNormalsToFaces) in its two parts. The vertices whose
    // normal is zero or faces away from one of their triangles are flagged as the mesh is copied
    // (vertices first, then triangles, each on both threads); a flag is only ever set to 1, so the
    // result does not depend on the threads.
    const size_t vertexPieces = groupsOf(vertexCount, kVertexPiece);
    std::vector<uint8_t>& against = s.against;
    against.assign(vertexCount, 0);
    auto flag = [&](uint32_t v) { std::atomic_ref<uint8_t>(against[v]).store(1, std::memory_order_relaxed); };
    s.helper.share(vertexPieces, [&](size_t piece) {
        for (size_t v = piece * kVertexPiece; v < std::min<size_t>(vertexCount, (piece + 1) * kVertexPiece); ++v) {
            const size_t w = v * kVertexWords;
            mesh.positions[v] = vec3At(w);
            const glm::vec3 normal = vec3At(w + 3);
            mesh.normals[v] = normal;
            mesh.vertexMaterials[v] = uint8_t(vertexWords[w + 6]);
            if (normal == glm::vec3(0.0f)) flag(uint32_t(v));
        }
    });
    // The triangles after the vertices, a cell's at a time: their material, and each tested (as
    // triangleNormal and orientNormalsToFaces' test).
    std::atomic<bool> inRange{true};
    s.helper.share(cellPieces, [&](size_t piece) {
        bool pieceInRange = true;
        for (size_t i = piece * kCellPiece; i < std::min<size_t>(activeCount, (piece + 1) * kCellPiece); ++i) {
            const uint32_t* cell = &activeCells[i * kActiveCellWords];
            const uint32_t first = cell[2], count = (cell[3] >> 3) & 15u;
            if (deviceVote) std::fill_n(mesh.triangleMaterials.begin() + first, count, uint8_t(materialWords[i]));
            bool cellInRange = true;
            for (size_t t = first; t < first + count; ++t) {
                const uint32_t* corner = &mesh.triangles[t * 3];
                if (corner[0] >= vertexCount || corner[1] >= vertexCount || corner[2] >= vertexCount) {
                    pieceInRange = cellInRange = false;
                    continue;
                }
                const glm::dvec3 a(mesh.positions[corner[0]]), b(mesh.positions[corner[1]]), c(mesh.positions[corner[2]]);
                const glm::dvec3 face = glm::cross(b - a, c - a);
                if (face == glm::dvec3(0.0)) continue;
                for (size_t k = 0; k < 3; ++k)
                    if (glm::dot(glm::dvec3(mesh.normals[corner[k]]), face) < 0.0) flag(corner[k]);
            }
            if (vote && cellInRange)
                std::fill_n(mesh.triangleMaterials.begin() + first, count,
                            (*vote)(cell, &mesh.triangles[size_t(first) * 3], mesh.vertexMaterials.data()));
        }
        if (!pieceInRange) inRange = false;
    });
    if (!inRange) throw InternalError("GPU marching cubes: a triangle names a vertex past the counted ones");
    // Then their triangles, from the cells around their edges, and their new normals.
    incidentTriangles(mesh, against, static_cast<const uint32_t*>(s.vertexEdges.mapped),
                      static_cast<const uint32_t*>(s.activeCells.mapped), activeCount, s.tileCells, s.incident, s.incidentList);
    orientFlaggedNormals(mesh, against, s.incident, s.incidentList);
    return mesh;
}

} // namespace voxc
