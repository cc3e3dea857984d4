// `voxc evolve FILE NAME [--with FILE:NAME]... -o DIR`: the next generation of an lsystem block by
// crossover and mutation (docs/architecture.md, "Evolution"): one .vox file per variant (the input
// with the block rewritten), a preview picture of each skeleton, a contact sheet and a JSON
// summary. A person picks variants and runs evolve on them again.
#include "Commands.h"
#include "Console.h"
#include "Common.h"
#include "LsystemInputs.h"
#include "OutputPaths.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/explore/Png.h"
#include "voxc/explore/SkeletonPreview.h"
#include "voxc/generators/lsystem/Connect.h"
#include "voxc/generators/lsystem/Evolve.h"
#include "voxc/generators/lsystem/Expand.h"

#include <filesystem>
#include <fmt/format.h>
#include <iostream>
#include <nlohmann/json.hpp>

namespace voxc::driver {

namespace {

using namespace lsystem;
using Json = nlohmann::ordered_json;

constexpr uint32_t kMaxPopulation = 64;
// A generation is written as one set: a .vox and a .png per variant, the contact sheet and the summary.
static_assert(2 * kMaxPopulation + 2 <= OutputFiles::kMaxFiles, "a full generation must fit one set of outputs");
constexpr int kSheetColumns = 4;

struct EvolveOptions {
    std::string file;
    std::string name;
    std::vector<std::string> with; // more picks, FILE:NAME
    uint32_t population = 8;
    std::optional<uint32_t> seed;
    uint32_t generation = 1;
    std::string outputDir;
};

// Byte offset of a 1-based (line, column) location; columns count characters (UTF-8 code points).
size_t offsetOf(const SourceFile& source, SourceLoc loc) {
    const std::string_view line = source.line(loc.line);
    size_t at = size_t(line.data() - source.text().data());
    for (uint32_t column = 1; column < loc.column; ++column) {
        ++at;
        while (at < source.text().size() && (uint8_t(source.text()[at]) & 0xC0) == 0x80) ++at;
    }
    return at;
}

// The input's text with the block replaced by `block`.
std::string withBlock(const SourceFile& source, const CheckedLsystem& lsystem, const std::string& block) {
    if (lsystem.blockEnd.line == 0) throw InternalError("a checked lsystem block without its closing brace");
    const size_t begin = offsetOf(source, lsystem.blockStart), end = offsetOf(source, lsystem.blockEnd) + 1;
    std::string text = source.text();
    std::string replacement = block;
    if (!replacement.empty() && replacement.back() == '\n') replacement.pop_back();
    return text.replace(begin, end - begin, replacement);
}

struct Variant {
    std::string name;     // "variant_3"
    std::string source;   // the .vox text
    Skeleton skeleton;
    size_t symbols = 0;
    std::string overLimit; // why the variant cannot be expanded, or empty
};

Variant makeVariant(const std::string& name, const SourceFile& source, const CheckedLsystem& parent,
                    const Definition& child) {
    Variant variant;
    variant.name = name;
    variant.source = withBlock(source, parent, formatLsystemBlock(parent.name, child, parent.connect));
    try {
        checkExpansionLimits(child);
        const Expansion expansion = expand(child);
        variant.symbols = expansion.symbols.size();
        variant.skeleton = interpret(child, expansion.symbols, expansion.types);
        connectBranches(variant.skeleton, parent.connect, child.seed, child.limits);
    } catch (const LimitError& error) {
        variant.overLimit = error.what();
        return variant;
    }
    // The rewritten file must check as the child: a failure here is voxc's, not the user's.
    const CheckResult checked = checkSource(SourceFile(source.path(), variant.source));
    if (checked.hasErrors())
        throw InternalError(fmt::format("the rewritten lsystem block of {} does not check: {}", name,
                                        checked.diagnostics.front().message));
    return variant;
}

std::string caption(const Variant& variant) {
    if (!variant.overLimit.empty()) return "over the limits";
    // Short enough for the preview's width (about 40 characters of the bitmap font).
    return fmt::format("{} sym, {} seg, {} ends, {} links", variant.symbols, variant.skeleton.segments.size(),
                       variant.skeleton.endpoints.size(), variant.skeleton.connections.size());
}

void runEvolve(const EvolveOptions& options) {
    if (options.population < 1 || options.population > kMaxPopulation)
        throw UserError(fmt::format("--population must be 1..{}", kMaxPopulation));
    std::vector<std::string> inputPaths{options.file};
    std::vector<std::string> inputNames{options.name};
    for (const std::string& reference : options.with) {
        const auto [path, name] = splitReference(reference);
        inputPaths.push_back(path);
        inputNames.push_back(name);
    }
    std::vector<RolePath> inputs;
    for (const std::string& path : inputPaths) inputs.push_back({"an input", path});
    const RolePath outputs[] = {{"-o", options.outputDir, true}};
    refuseInputsInside({"-o", options.outputDir}, inputs);
    refuseClashingPaths(inputs, outputs);
    // Created now (removed again if evolve fails, when it was evolve's): a file, a dangling link
    // or an unwritable place is refused before any work.
    OutputDirectory directory(options.outputDir);

    std::vector<CheckResult> results;
    for (const std::string& path : inputPaths) results.push_back(loadChecked(path));
    std::vector<Definition> picks;
    Json parents = Json::array();
    for (size_t i = 0; i < results.size(); ++i) {
        picks.push_back(findLsystem(results[i].lsystems, inputPaths[i], inputNames[i]).definition);
        parents.push_back(inputPaths[i] + ":" + inputNames[i]);
    }
    const CheckedLsystem& first = findLsystem(results[0].lsystems, inputPaths[0], inputNames[0]);
    const uint32_t seed = options.seed.value_or(first.definition.seed);
    const std::vector<Definition> children = nextGeneration(picks, options.population, seed, options.generation);

    const std::filesystem::path dir(options.outputDir);
    OutputFiles files;
    std::vector<explore::Image> previews;
    std::vector<std::string> labels;
    Json variants = Json::array();
    for (size_t k = 0; k < children.size(); ++k) {
        const Variant variant =
            makeVariant(fmt::format("variant_{}", k + 1), results[0].source, first, children[k]);
        const std::string vox = (dir / (variant.name + ".vox")).string();
        const std::string png = (dir / (variant.name + ".png")).string();
        files.add(vox, variant.source);
        previews.push_back(explore::renderSkeletonPreview(variant.skeleton, caption(variant)));
        labels.push_back(variant.name);
        files.add(png, explore::encodePng(previews.back()));
        Json entry{{"file", variant.name + ".vox"},
                   {"preview", variant.name + ".png"},
                   {"seed", children[k].seed},
                   {"symbols", variant.symbols},
                   {"segments", variant.skeleton.segments.size()},
                   {"endpoints", variant.skeleton.endpoints.size()},
                   {"connections", variant.skeleton.connections.size()}};
        if (!variant.overLimit.empty()) entry["over_limit"] = variant.overLimit;
        variants.push_back(entry);
    }
    files.add((dir / "contact_sheet.png").string(),
              explore::encodePng(explore::contactSheet(previews, labels, kSheetColumns)));
    const Json summary{{"lsystem", first.name}, {"parents", parents}, {"seed", seed},
                       {"generation", options.generation}, {"variants", variants}};
    files.add((dir / "generation.json").string(), summary.dump(2) + "\n");
    files.commit();
    directory.keep();
    status() << fmt::format("wrote {} variants of lsystem '{}' (generation {}, seed {}) to {}: see "
                             "contact_sheet.png, then evolve the ones you like: voxc evolve {}/variant_N.vox {} "
                             "[--with {}/variant_M.vox:{}] --generation {} -o NEXT_DIR\n",
                             children.size(), first.name, options.generation, seed, options.outputDir,
                             options.outputDir, first.name, options.outputDir, first.name, options.generation + 1);
}

} // namespace

void addEvolveCommand(CLI::App& app) {
    auto options = std::make_shared<EvolveOptions>();
    CLI::App* command = app.add_subcommand(
        "evolve", "Breed variants of an lsystem block by crossover and mutation, with a preview picture of each");
    command->add_option("file", options->file, "The .vox file")->required();
    command->add_option("name", options->name, "The lsystem block's name")->required();
    command->add_option("--with", options->with, "More picks to cross with, as FILE:NAME (repeatable)");
    command->add_option("--population", options->population, "Variants to write (1..64, default 8)");
    command->add_option("--seed", options->seed, "Seed of the crossover and mutation draws (default: the block's seed)");
    command->add_option("--generation", options->generation, "Generation number, part of every draw (default 1)");
    command->add_option("-o,--output", options->outputDir, "Directory for the variants and pictures")->required();
    addConsoleFlags(*command);
    command->callback([options] { runEvolve(*options); });
}

} // namespace voxc::driver
