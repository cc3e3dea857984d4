#pragma once
// Writes a KernelPackage as a package directory: dir/manifest.json, dir/kernels/<name>.comp
// (GLSL), dir/kernels/<name>.spv (SPIR-V words, little endian), dir/data/<buffer>.bin (the
// words of the buffers the compiler fills, little endian) and dir/sources/ (the .vox and its
// rule files). The directory is replaced as
// a whole, so a reader sees the old package or the new one, never a mix.
#include "voxc/codegen/KernelPackage.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace voxc::codegen {

// manifest.json's "format": how voxc recognises a directory it may replace.
inline constexpr const char* kPackageFormat = "voxc-package";

// A file the .vox imports: a rule file or a heightmap's or mesh's file, its path as written (the
// `rules = "..."` or `file = "..."` string, relative to the .vox's directory) and its bytes.
struct ImportedFile {
    std::string path;
    std::string text;
};

// What the package records about the program's source: the file name without its directory (so
// the manifest does not depend on where or how the command was typed), the text, and the rule
// files it imports. The package holds copies of them all (sources/), hashed in the manifest, so
// a loader can rebuild the plan the manifest describes (PackageReader.h).
struct PackageSource {
    std::string fileName;
    std::string text;
    std::vector<ImportedFile> imports{};
};

// The manifest text writePackage writes (JSON, keys in a fixed order, trailing newline).
std::string packageManifest(const KernelPackage& package, const PackageSource& source = {});

// The package files of the source copies: sources/0.vox for the .vox, sources/N.rules for
// imports[N-1], or sources/N.png (.npy, .tif, .tiff, .glb, .gltf, .obj, .ply) when `importPath`
// ends so (numbered, and the extension from that list, so no user's path decides a file name).
std::string packageSourcePath(size_t index, std::string_view importPath = {});
// The extensions a copied heightmap or mesh file keeps (packageSourcePath; a package reader
// accepts sources/ files with these, .vox and .rules).
inline constexpr std::string_view kPackageInputExtensions[] = {"png", "npy", "tif", "tiff", "glb", "gltf", "obj", "ply"};

// A kernel's files, relative to the package directory.
std::string packageGlslPath(const Kernel& kernel);
std::string packageSpirvPath(const Kernel& kernel);

// A storage buffer whose words the compiler computes, and the package file that holds them.
struct PackageData {
    uint32_t binding = 0;
    std::string path; // relative to the package directory, under data/
    std::vector<int32_t> words;
};
// The package's buffers with known contents: point sets (binding 10), solve tables (binding 12).
std::vector<PackageData> packageData(const KernelPackage& package);
std::string littleEndianWords(const std::vector<int32_t>& words);
std::string littleEndianWords(const std::vector<uint32_t>& words); // a .spv file's bytes

// Every file of the package: path relative to the package directory -> bytes.
std::map<std::string, std::string> packageFiles(const KernelPackage& package, const PackageSource& source = {});

enum class PackageWrite {
    Created,   // `dir` did not exist
    Replaced,  // `dir` held another voxc package, now gone
    Unchanged, // `dir` already held these exact bytes; nothing was touched
};

// Builds the package in a new sibling directory and swaps it in (Linux renameat2
// RENAME_EXCHANGE over an existing package, then removes the old one). UserError, with `dir` as
// it was, when it cannot be written (e.g. a full disk), or when `dir` is not a directory or is a
// non-empty directory that is not a voxc package (voxc never deletes files it did not write).
PackageWrite writePackage(const KernelPackage& package, const std::string& dir, const PackageSource& source = {});

} // namespace voxc::codegen
