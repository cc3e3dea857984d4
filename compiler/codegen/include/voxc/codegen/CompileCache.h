#pragma once
// Kernels compiled by earlier runs, kept on disk so an unchanged file's second run skips glslang
// and the validator (issue "Speed", part 1). Content-addressed: an entry's name is the SHA-256 of
// the GLSL text and of what else decides the SPIR-V (voxc's version, glslang's version, the
// target environment), so a stale entry is never found rather than invalidated. An entry holds
// the SPIR-V and its own SHA-256; one that does not match (truncated, corrupted, edited) is
// compiled again and rewritten, never trusted. Entries are written to a temp file and renamed,
// so concurrent runs sharing a cache see whole entries or none.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace voxc::codegen {

// $VOXC_CACHE_DIR, else $XDG_CACHE_HOME/voxc, else $HOME/.cache/voxc; nothing when none is set.
std::optional<std::filesystem::path> defaultCacheDirectory();

// The directory compileComputeShader keeps SPIR-V in (its spirv/ subdirectory); nothing (the
// default) turns the cache off. A process-wide setting, made once by the driver.
void setCompileCacheDirectory(std::optional<std::filesystem::path> directory);
std::optional<std::filesystem::path> compileCacheDirectory();

// What compileComputeShader did since the process started, for `voxc run --timings`.
struct CompileCacheCounts {
    uint64_t hits = 0;
    uint64_t compiled = 0;   // no entry, or the cache is off
    uint64_t corrupted = 0;  // an entry that failed its check, compiled again (also in `compiled`)
    uint64_t remembered = 0; // taken from a SpirvMemo in scope (neither a hit nor compiled)
    double compileMs = 0.0;  // time in glslang and the validator
    double cacheMs = 0.0;    // time reading and writing entries
};
CompileCacheCounts compileCacheCounts();

// Kernels' SPIR-V kept in memory by their owner, by kernel name and GLSL: libvoxc keeps one per
// program, whose regions of one size compile to the same GLSL, so a later region runs neither
// glslang nor the validator even with the cache directory off (an engine's process has none).
class SpirvMemo {
public:
    // Out of line, so libvoxc (which exports only its C API) instantiates none of the map's code.
    SpirvMemo();
    ~SpirvMemo();
    const std::vector<uint32_t>* find(std::string_view kernelName, const std::string& glsl) const;
    void insert(std::string_view kernelName, const std::string& glsl, const std::vector<uint32_t>& spirv);

private:
    std::unordered_map<std::string, std::vector<uint32_t>> spirv_; // by name, a newline, the GLSL
};

// While one lives on a thread, compileComputeShader on that thread takes a kernel's SPIR-V from
// `memo` when it holds it and adds what it compiles or reads from the cache directory.
class SpirvMemoScope {
public:
    explicit SpirvMemoScope(SpirvMemo& memo);
    ~SpirvMemoScope();
    SpirvMemoScope(const SpirvMemoScope&) = delete;
    SpirvMemoScope& operator=(const SpirvMemoScope&) = delete;

private:
    SpirvMemo* outer_;
};

} // namespace voxc::codegen
