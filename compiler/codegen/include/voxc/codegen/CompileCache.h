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
    double compileMs = 0.0;  // time in glslang and the validator
    double cacheMs = 0.0;    // time reading and writing entries
};
CompileCacheCounts compileCacheCounts();

} // namespace voxc::codegen
