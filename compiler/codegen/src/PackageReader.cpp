// Loading a package trusts nothing it has not checked: the manifest's version and hashes first,
// then every file against what the sources compile to.
#include "voxc/codegen/PackageReader.h"

#include "ExistingPackage.h"
#include "PackagedSpirv.h"
#include "voxc/core/Errors.h"
#include "voxc/core/Sha256.h"

#include <cstring>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#ifndef VOXC_VERSION
#error "VOXC_VERSION must be defined by the build"
#endif

namespace voxc::codegen {

namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;

thread_local const PackageContents* packageInScope = nullptr;

struct Loading {
    const std::string& dir;

    [[noreturn]] void fail(const std::string& why) const {
        throw UserError(fmt::format("cannot load package '{}': {}", dir, why));
    }
    [[noreturn]] void recompile(const std::string& why) const {
        fail(why + "; compile it again with `voxc compile`");
    }

    // A file the manifest names, whose bytes hash to `sha256`.
    const std::string& verifiedFile(const PackageContents& contents, const std::string& path,
                                    const std::string& sha256) const {
        const auto file = contents.files.find(path);
        if (file == contents.files.end()) recompile(fmt::format("{} is missing", path));
        if (sha256Hex(file->second) != sha256)
            recompile(fmt::format("{} does not match its SHA-256 in manifest.json (the package is corrupt)", path));
        return file->second;
    }
};

std::vector<uint32_t> wordsOf(const std::string& bytes) {
    std::vector<uint32_t> words(bytes.size() / 4);
    for (size_t i = 0; i < words.size(); ++i)
        for (int b = 0; b < 4; ++b) words[i] |= uint32_t(uint8_t(bytes[4 * i + size_t(b)])) << (8 * b);
    return words;
}

} // namespace

PackageContents readPackage(const std::string& dir) {
    const Loading loading{dir};
    PackageContents contents;
    contents.directory = dir;
    std::optional<std::map<std::string, std::string>> files = existingPackage(dir, PackageVerb::Load);
    if (!files) loading.fail("no such directory");
    if (!files->contains("manifest.json")) loading.fail("it has no manifest.json");
    contents.files = std::move(*files);

    const nlohmann::json manifest = nlohmann::json::parse(contents.files.at("manifest.json"), nullptr, false);
    if (!manifest.is_object()) loading.recompile("manifest.json is not JSON (the package is corrupt)");
    try {
        const std::string version = manifest.at("voxc_version").get<std::string>();
        if (version != VOXC_VERSION)
            loading.recompile(fmt::format("it was written by voxc {} and this is voxc {}", version, VOXC_VERSION));
        // The loader checked every file it lists against these sizes before reading it.
        if (!manifest.contains("files") || !manifest.at("files").is_object())
            loading.recompile("manifest.json does not give the size of each file (written by an older voxc)");
        const nlohmann::json& sources = manifest.value("sources", nlohmann::json::array());
        if (sources.empty()) loading.recompile("it holds no copy of its sources (written before packages did)");
        for (size_t i = 0; i < sources.size(); ++i) {
            const nlohmann::json& entry = sources.at(i);
            const std::string& text =
                loading.verifiedFile(contents, entry.at("file").get<std::string>(), entry.at("sha256").get<std::string>());
            if (i == 0)
                contents.source = {entry.at("path").get<std::string>(), text, {}};
            else
                contents.source.imports.push_back({entry.at("path").get<std::string>(), text});
        }
        contents.seed = manifest.at("world").at("seed").get<uint32_t>();
        contents.chunkSize = manifest.at("world").at("chunk").get<int32_t>();
        for (const nlohmann::json& kernel : manifest.at("kernels")) {
            const std::string name = kernel.at("name").get<std::string>();
            const std::string& spv = loading.verifiedFile(contents, kernel.at("spv").get<std::string>(),
                                                          kernel.at("spv_sha256").get<std::string>());
            const auto glsl = contents.files.find(kernel.at("glsl").get<std::string>());
            if (glsl == contents.files.end()) loading.recompile(fmt::format("{} is missing", kernel.at("glsl").get<std::string>()));
            std::vector<uint32_t> spirv = wordsOf(spv);
            if (spv.size() % 4 != 0 || spirv.size() < 5 || spirv[0] != kSpirvMagic)
                loading.recompile(fmt::format("{} is not SPIR-V", kernel.at("spv").get<std::string>()));
            contents.kernels[name] = {glsl->second, std::move(spirv)};
        }
    } catch (const nlohmann::json::exception& e) {
        loading.recompile(fmt::format("manifest.json lacks what this voxc reads ({})", e.what()));
    }
    return contents;
}

void verifyRebuiltPackage(const KernelPackage& rebuilt, const PackageContents& contents) {
    const Loading loading{contents.directory};
    const std::map<std::string, std::string> expected = packageFiles(rebuilt, contents.source);
    for (const auto& [path, bytes] : expected) {
        const auto file = contents.files.find(path);
        if (file == contents.files.end()) loading.recompile(fmt::format("{} is missing", path));
        if (file->second != bytes)
            loading.recompile(fmt::format("{} differs from what its sources compile to (edited, or written by another "
                                          "build of voxc {})",
                                          path, VOXC_VERSION));
    }
    for (const auto& [path, bytes] : contents.files)
        if (!expected.contains(path))
            loading.recompile(fmt::format("{} is not part of what its sources compile to", path));
}

PackagedSpirvScope::PackagedSpirvScope(const PackageContents& contents) {
    VOXC_ASSERT(!packageInScope);
    packageInScope = &contents;
}

PackagedSpirvScope::~PackagedSpirvScope() { packageInScope = nullptr; }

std::optional<std::vector<uint32_t>> packagedSpirv(std::string_view kernelName, const std::string& glsl) {
    if (!packageInScope) return std::nullopt;
    const auto kernel = packageInScope->kernels.find(kernelName);
    if (kernel == packageInScope->kernels.end() || kernel->second.glsl != glsl)
        throw UserError(fmt::format("cannot load package '{}': its sources compile to a kernel {} {}; compile it "
                                    "again with `voxc compile`",
                                    packageInScope->directory, kernelName,
                                    kernel == packageInScope->kernels.end() ? "that it does not hold"
                                                                            : "whose GLSL differs from its copy"));
    return kernel->second.spirv;
}

} // namespace voxc::codegen
