#include "voxc/stages/SolveCache.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Sha256.h"
#include "voxc/generators/curves/Scene.h"
#include "voxc/generators/terrain/Block.h"

#include <cstring>
#include <dlfcn.h>
#include <fmt/format.h>
#include <fstream>
#include <memory>
#include <mutex>
#include <sys/stat.h>

namespace voxc::stages {

namespace {

constexpr size_t kDigestHexSize = 64;
constexpr std::string_view kMagic = "voxc solve table 1\n";

struct CountState {
    std::mutex mutex;
    SolveCacheCounts counts;
};

CountState& countState() {
    static CountState instance;
    return instance;
}

// Which build of voxc this is: the file holding this code (the voxc executable, libvoxc.so) by its
// path, size and modification time, so a rebuilt solver never reads an older build's tables.
const std::string& buildIdentity() {
    static const std::string identity = [] {
        Dl_info info{};
        struct stat file{};
        if (dladdr(reinterpret_cast<const void*>(&buildIdentity), &info) == 0 || !info.dli_fname ||
            stat(info.dli_fname, &file) != 0)
            return std::string("unknown build");
        return fmt::format("{} {} {}.{:09}", info.dli_fname, file.st_size, file.st_mtim.tv_sec, file.st_mtim.tv_nsec);
    }();
    return identity;
}

// The key's text: every number exactly (hex floats), one field after another.
class KeyText {
public:
    KeyText& operator<<(double v) { return add(fmt::format("{:a}", v)); }
    KeyText& operator<<(float v) { return add(fmt::format("{:a}", v)); }
    template <typename Integer>
        requires std::is_integral_v<Integer>
    KeyText& operator<<(Integer v) { return add(fmt::format("{}", int64_t(v))); }
    KeyText& operator<<(std::string_view v) { return add(fmt::format("{}:{}", v.size(), v)); }
    KeyText& operator<<(const glm::dvec2& v) { return *this << v.x << v.y; }
    KeyText& operator<<(const glm::dvec3& v) { return *this << v.x << v.y << v.z; }
    KeyText& operator<<(const glm::ivec3& v) { return *this << v.x << v.y << v.z; }
    template <typename T>
    KeyText& operator<<(const std::optional<T>& v) {
        if (!v) return add("none");
        return *this << *v;
    }
    const std::string& text() const { return text_; }

private:
    KeyText& add(const std::string& field) {
        text_ += field;
        text_ += ' ';
        return *this;
    }
    std::string text_;
};

void curvesKey(KeyText& key, const curves::Scene& scene) {
    key << "curves" << scene.curves.size();
    for (const curves::FeatureCurve& curve : scene.curves) {
        key << curve.seed << curve.points.size();
        for (const glm::dvec3& point : curve.points) key << point;
        key << curve.constraints.size();
        for (const curves::ConstraintPoint& c : curve.constraints)
            key << c.t << c.left << c.right << c.amplitude << c.roughness << c.material;
    }
    const curves::Options& o = scene.options;
    key << scene.box.min << scene.box.size << int(o.normals) << o.k << o.sweeps << int(o.propagate) << int(o.seedValue)
        << o.smoothPasses << scene.noiseFrequency << scene.noiseSeed;
    // The inputs' geometry by the digest of its doubles (a heightmap's columns may be millions).
    const curves::InputOptions& i = scene.inputOptions;
    key << scene.inputs.size() << i.deadZone << i.amplitude << i.roughness << i.material;
    for (const std::shared_ptr<const curves::InputSurface>& input : scene.inputs) {
        const auto bytes = [](const auto& values) {
            return sha256Hex(std::string_view(reinterpret_cast<const char*>(values.data()),
                                              values.size() * sizeof(values[0])));
        };
        key << int(input->kind) << input->triangles.size() << bytes(input->triangles) << input->heights.size()
            << bytes(input->heights);
    }
}

void terrainKey(KeyText& key, const terrain::TerrainBlock& block) {
    const terrain::TerrainMap& map = block.map;
    const terrain::Domain& d = map.domain;
    key << "terrain" << d.origin << d.size << d.minLevel << d.maxLevel << d.maxHeight << map.splines.size();
    for (const terrain::Spline& spline : map.splines) {
        key << spline.controlPoints.size();
        for (const glm::dvec3& point : spline.controlPoints) key << point;
        key << spline.metaPoints.size();
        for (const terrain::MetaPoint& m : spline.metaPoints)
            key << m.u << m.radius << m.left << m.right << m.hardness << m.noiseAmplitude << m.noiseRoughness << m.warpLow
                << m.warpHigh << m.rain << m.capacity;
        key << spline.minLevel << spline.maxLevel << spline.samplings;
    }
    key << map.noise.amplitude << map.noise.scale << map.noise.seed << map.diffusion.multiplier
        << int(map.diffusion.rule) << map.diffusion.isotropicGradient << map.diffusion.thesisProlongation;
    key << block.erosion.has_value();
    if (block.erosion) {
        const terrain::ErosionParams& p = block.erosion->params;
        key << p.pipeArea << p.gravity << p.pipeLength << p.cellSize << p.capacity << p.suspension << p.deposition
            << p.evaporation << p.rainMax << p.rainMin << p.radiusMax << p.radiusMin << p.dt << p.depthLimit << p.minTilt
            << p.uniformRain << int(p.transport) << int(p.rain) << p.seed << block.erosion->levelSteps.size();
        for (const auto& [level, steps] : block.erosion->levelSteps) key << level << steps;
        key << block.erosion->drainSteps << block.erosion->thesisProlongation;
    }
    key << block.base << block.ramp << block.material << block.depositMaterial << block.depositThreshold
        << block.worldOrigin << block.worldSize;
}

// The entry's body, little by little.
class Writer {
public:
    template <typename T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
    }
    template <typename T>
    void put(const std::vector<T>& values) {
        static_assert(std::is_trivially_copyable_v<T>);
        put(uint64_t(values.size()));
        bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }
    void put(const std::string& text) {
        put(uint64_t(text.size()));
        bytes_ += text;
    }
    std::string& bytes() { return bytes_; }

private:
    std::string bytes_;
};

// Reads what Writer wrote; false once anything ran past the end or was absurd.
class Reader {
public:
    explicit Reader(std::string_view bytes) : bytes_(bytes) {}
    template <typename T>
    bool get(T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        if (bytes_.size() < sizeof(T)) return false;
        std::memcpy(&value, bytes_.data(), sizeof(T));
        bytes_.remove_prefix(sizeof(T));
        return true;
    }
    template <typename T>
    bool get(std::vector<T>& values) {
        uint64_t count = 0;
        if (!get(count) || count > bytes_.size() / sizeof(T)) return false;
        values.resize(count);
        std::memcpy(values.data(), bytes_.data(), count * sizeof(T));
        bytes_.remove_prefix(count * sizeof(T));
        return true;
    }
    bool get(std::string& text) {
        uint64_t count = 0;
        if (!get(count) || count > bytes_.size()) return false;
        text.assign(bytes_.substr(0, count));
        bytes_.remove_prefix(count);
        return true;
    }
    bool done() const { return bytes_.empty(); }

private:
    std::string_view bytes_;
};

std::string serialise(const SolveTable& table) {
    Writer out;
    out.put(table.min);
    out.put(table.size);
    out.put(table.density);
    out.put(table.material);
    out.put(table.source);
    out.put(table.notes);
    out.put(uint64_t(table.solves.size()));
    for (const SolveSummary& solve : table.solves) {
        out.put(solve.name);
        out.put(solve.levels);
        out.put(solve.residuals);
        out.put(solve.fullMultigrid);
    }
    out.put(uint8_t(table.terrainMaps != nullptr));
    if (table.terrainMaps) {
        out.put(table.terrainMaps->side);
        out.put(table.terrainMaps->height);
        out.put(table.terrainMaps->water);
        out.put(table.terrainMaps->sediment);
        out.put(table.terrainMaps->difference);
    }
    return std::move(out.bytes());
}

std::optional<SolveTable> deserialise(std::string_view bytes) {
    Reader in(bytes);
    SolveTable table;
    uint64_t solves = 0;
    if (!in.get(table.min) || !in.get(table.size) || !in.get(table.density) || !in.get(table.material) ||
        !in.get(table.source) || !in.get(table.notes) || !in.get(solves) || solves > bytes.size())
        return std::nullopt;
    table.solves.resize(solves);
    for (SolveSummary& solve : table.solves)
        if (!in.get(solve.name) || !in.get(solve.levels) || !in.get(solve.residuals) || !in.get(solve.fullMultigrid))
            return std::nullopt;
    uint8_t hasMaps = 0;
    if (!in.get(hasMaps)) return std::nullopt;
    if (hasMaps) {
        TerrainMaps maps;
        if (!in.get(maps.side) || !in.get(maps.height) || !in.get(maps.water) || !in.get(maps.sediment) ||
            !in.get(maps.difference))
            return std::nullopt;
        const size_t cells = size_t(std::max(maps.side, 0)) * size_t(std::max(maps.side, 0));
        if (maps.side <= 0 || maps.height.size() != cells || maps.water.size() != cells ||
            maps.sediment.size() != cells || maps.difference.size() != cells)
            return std::nullopt;
        table.terrainMaps = std::make_shared<const TerrainMaps>(std::move(maps));
    }
    const bool sized = table.size.x > 0 && table.size.y > 0 && table.size.z > 0 &&
                       table.density.size() == table.cellCount() &&
                       (table.material.empty() || table.material.size() == table.density.size());
    if (!in.done() || !sized) return std::nullopt;
    return table;
}

std::filesystem::path entryPath(const std::filesystem::path& directory, const std::string& key) {
    return directory / "solves" / (key + ".table");
}

} // namespace

bool hasSolve(const std::filesystem::path& directory, const std::string& key) {
    std::error_code ignored;
    return std::filesystem::is_regular_file(entryPath(directory, key), ignored);
}

SolveCacheCounts solveCacheCounts() {
    const std::lock_guard lock(countState().mutex);
    return countState().counts;
}

void countSolve(bool hit, bool corrupted) {
    const std::lock_guard lock(countState().mutex);
    SolveCacheCounts& counts = countState().counts;
    ++(hit ? counts.hits : counts.solved);
    counts.corrupted += corrupted;
}

std::string solveKey(const CurvesBlock& block, bool onDevice) {
    KeyText key;
    key << fmt::format("voxc {}", VOXC_VERSION) << buildIdentity() << (onDevice ? "device" : "host");
    if (block.scene) curvesKey(key, *block.scene);
    if (block.terrain) terrainKey(key, *block.terrain);
    return sha256Hex(key.text());
}

std::optional<SolveTable> readSolve(const std::filesystem::path& directory, const std::string& key, bool& corrupted) {
    corrupted = false;
    std::ifstream in(entryPath(directory, key), std::ios::binary | std::ios::ate);
    if (!in) return std::nullopt;
    // One read into an unfilled buffer of the file's size: a stringstream grows by copies and a
    // zeroed string is written twice, which for a 200 MB terrain table cost more than the hash.
    const std::streamoff size = in.tellg();
    if (size < 0) return std::nullopt;
    const std::unique_ptr<char[]> bytes(new char[size_t(size)]);
    in.seekg(0);
    if (!in.read(bytes.get(), size)) return std::nullopt;
    const std::string_view contents(bytes.get(), size_t(size));
    corrupted = true;
    const size_t head = kMagic.size() + kDigestHexSize + 1;
    if (contents.size() <= head || !contents.starts_with(kMagic) || contents[head - 1] != '\n') return std::nullopt;
    const std::string_view body = contents.substr(head);
    if (sha256Hex(body) != contents.substr(kMagic.size(), kDigestHexSize)) return std::nullopt;
    std::optional<SolveTable> table = deserialise(body);
    corrupted = !table;
    return table;
}

void writeSolve(const std::filesystem::path& directory, const std::string& key, const SolveTable& table) {
    try {
        const std::filesystem::path path = entryPath(directory, key);
        std::error_code ec;
        std::filesystem::create_directories(path.parent_path(), ec);
        const std::string body = serialise(table);
        writeFileAtomically(path.string(), std::string(kMagic) + sha256Hex(body) + "\n" + body);
    } catch (const std::exception&) {
    }
}

} // namespace voxc::stages
