#include "CompileCacheEntries.h"

#include "voxc/core/Sha256.h"
#include "voxc/core/AtomicWrite.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <glslang/build_info.h>
#include <mutex>
#include <sstream>

namespace voxc::codegen {

namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;
constexpr size_t kDigestHexSize = 64;

struct CacheState {
    std::mutex mutex;
    std::optional<std::filesystem::path> directory;
    CompileCacheCounts counts;
};

thread_local SpirvMemo* memoInScope = nullptr;

std::string memoKey(std::string_view kernelName, const std::string& glsl) {
    std::string key(kernelName);
    key += '\n';
    return key += glsl;
}

CacheState& state() {
    static CacheState instance;
    return instance;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::string_view asBytes(const std::vector<uint32_t>& words) {
    return {reinterpret_cast<const char*>(words.data()), words.size() * sizeof(uint32_t)};
}

// Everything besides the GLSL text that decides the SPIR-V.
std::string keyOf(std::string_view kernelName, const std::string& glsl) {
    const std::string salt = fmt::format("voxc {} glslang {}.{}.{} vulkan1.1 spv1.3\n", VOXC_VERSION,
                                         GLSLANG_VERSION_MAJOR, GLSLANG_VERSION_MINOR, GLSLANG_VERSION_PATCH);
    return sha256Hex(salt + std::string(kernelName) + "\n" + glsl);
}

// An entry: the SPIR-V's digest in hex, a newline, then the SPIR-V words.
std::optional<std::vector<uint32_t>> readEntry(const std::filesystem::path& path, bool& corrupted) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::stringstream bytes;
    bytes << in.rdbuf();
    const std::string contents = bytes.str();
    corrupted = true;
    if (contents.size() <= kDigestHexSize + 1 || contents[kDigestHexSize] != '\n') return std::nullopt;
    const std::string_view body = std::string_view(contents).substr(kDigestHexSize + 1);
    if (body.size() % sizeof(uint32_t) != 0 || sha256Hex(body) != contents.substr(0, kDigestHexSize))
        return std::nullopt;
    std::vector<uint32_t> spirv(body.size() / sizeof(uint32_t));
    std::memcpy(spirv.data(), body.data(), body.size());
    if (spirv.size() < 5 || spirv[0] != kSpirvMagic) return std::nullopt;
    corrupted = false;
    return spirv;
}

} // namespace

std::optional<std::filesystem::path> defaultCacheDirectory() {
    const auto fromEnvironment = [](const char* name) -> std::optional<std::filesystem::path> {
        const char* value = std::getenv(name);
        if (!value || !*value) return std::nullopt;
        return std::filesystem::path(value);
    };
    if (auto dir = fromEnvironment("VOXC_CACHE_DIR")) return dir;
    if (auto dir = fromEnvironment("XDG_CACHE_HOME")) return *dir / "voxc";
    if (auto dir = fromEnvironment("HOME")) return *dir / ".cache" / "voxc";
    return std::nullopt;
}

void setCompileCacheDirectory(std::optional<std::filesystem::path> directory) {
    std::lock_guard lock(state().mutex);
    state().directory = std::move(directory);
}

std::optional<std::filesystem::path> compileCacheDirectory() {
    std::lock_guard lock(state().mutex);
    return state().directory;
}

CompileCacheCounts compileCacheCounts() {
    std::lock_guard lock(state().mutex);
    return state().counts;
}

SpirvMemo::SpirvMemo() = default;

SpirvMemo::~SpirvMemo() = default;

const std::vector<uint32_t>* SpirvMemo::find(std::string_view kernelName, const std::string& glsl) const {
    const auto it = spirv_.find(memoKey(kernelName, glsl));
    return it == spirv_.end() ? nullptr : &it->second;
}

void SpirvMemo::insert(std::string_view kernelName, const std::string& glsl, const std::vector<uint32_t>& spirv) {
    spirv_.emplace(memoKey(kernelName, glsl), spirv);
}

SpirvMemoScope::SpirvMemoScope(SpirvMemo& memo) : outer_(memoInScope) { memoInScope = &memo; }

SpirvMemoScope::~SpirvMemoScope() { memoInScope = outer_; }

namespace {

void count(const std::function<void(CompileCacheCounts&)>& update) {
    std::lock_guard lock(state().mutex);
    update(state().counts);
}

// cachedCompile without the memo.
std::vector<uint32_t> directoryCachedCompile(std::string_view kernelName, const std::string& glsl,
                                             const std::function<std::vector<uint32_t>()>& compile) {
    const std::optional<std::filesystem::path> directory = compileCacheDirectory();
    std::filesystem::path entry;
    bool corrupted = false;
    if (directory) {
        const auto start = std::chrono::steady_clock::now();
        entry = *directory / "spirv" / (keyOf(kernelName, glsl) + ".spv");
        std::optional<std::vector<uint32_t>> cached = readEntry(entry, corrupted);
        const double ms = millisecondsSince(start);
        if (cached) {
            count([&](CompileCacheCounts& c) { ++c.hits, c.cacheMs += ms; });
            return *cached;
        }
        count([&](CompileCacheCounts& c) { c.cacheMs += ms; });
    }
    const auto start = std::chrono::steady_clock::now();
    std::vector<uint32_t> spirv = compile();
    const double ms = millisecondsSince(start);
    count([&](CompileCacheCounts& c) { ++c.compiled, c.corrupted += corrupted, c.compileMs += ms; });
    if (directory) {
        const auto writeStart = std::chrono::steady_clock::now();
        // A cache that cannot be written (read-only home, full disk) costs speed, not the run.
        try {
            std::error_code ec;
            std::filesystem::create_directories(entry.parent_path(), ec);
            writeFileAtomically(entry.string(), sha256Hex(asBytes(spirv)) + "\n" + std::string(asBytes(spirv)));
        } catch (const std::exception&) {
        }
        const double writeMs = millisecondsSince(writeStart);
        count([&](CompileCacheCounts& c) { c.cacheMs += writeMs; });
    }
    return spirv;
}

} // namespace

std::vector<uint32_t> cachedCompile(std::string_view kernelName, const std::string& glsl,
                                    const std::function<std::vector<uint32_t>()>& compile) {
    SpirvMemo* memo = memoInScope;
    if (!memo) return directoryCachedCompile(kernelName, glsl, compile);
    if (const std::vector<uint32_t>* kept = memo->find(kernelName, glsl)) {
        count([](CompileCacheCounts& c) { ++c.remembered; });
        return *kept;
    }
    std::vector<uint32_t> spirv = directoryCachedCompile(kernelName, glsl, compile);
    memo->insert(kernelName, glsl, spirv);
    return spirv;
}

} // namespace voxc::codegen
