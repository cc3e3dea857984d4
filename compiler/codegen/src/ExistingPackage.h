#pragma once
// What a package directory holds before writePackage replaces it.
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace voxc::codegen {

// The files of the package at `dir` (relative path -> bytes; none for an empty directory),
// nullopt when `dir` does not exist. Read through one directory handle, so a concurrent compile
// swapping the directory yields one whole package, never a mix (the read is retried when the
// package being read is removed under it). UserError when `dir` is a symbolic link or not a
// directory, or holds anything voxc does not write (a package holds manifest.json with a voxc
// manifest, kernels/*.comp, *.spv, data/*.bin, sources/*.vox, *.rules, nothing else): replacing
// it would delete a user's file. The messages say "cannot VERB package 'DIR': ...". A file whose
// size on disk differs from the one manifest.json's "files" gives is never read: loading refuses
// the package, writing leaves the file out of the map (so the package is replaced).
enum class PackageVerb { Write, Load };
std::optional<std::map<std::string, std::string>> existingPackage(const std::filesystem::path& dir,
                                                                  PackageVerb verb = PackageVerb::Write);

} // namespace voxc::codegen
