// `voxc lsystem FILE NAME`: expands one lsystem block and prints its string, statistics and
// skeleton (docs/cli.md); `voxc lsystem cross A.vox:NAME B.vox:NAME --brackets I,J` prints the
// crossover of two production rules as lsystem blocks.
#include "Commands.h"
#include "Console.h"
#include "Common.h"
#include "LsystemInputs.h"
#include "OutputPaths.h"

#include "voxc/check/Check.h"
#include "voxc/core/AtomicWrite.h"
#include "voxc/generators/lsystem/Connect.h"
#include "voxc/generators/lsystem/Evolve.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/generators/lsystem/Export.h"

#include <cmath>
#include <fmt/format.h>
#include <iostream>

namespace voxc::driver {

namespace {

using namespace lsystem;

// Strings longer than this are shown as their head and tail.
constexpr size_t kShownSymbols = 2000;
constexpr size_t kShownTail = 200;
constexpr size_t kShownSegments = 50;

struct LsystemOptions {
    std::string file;
    std::string name;
    std::optional<uint32_t> expansions;
    std::optional<uint32_t> seed;
    std::string format = "text";
    std::string output;
};

struct CrossOptions {
    std::string first, second; // FILE:NAME
    std::vector<size_t> brackets;
};

// Six decimals; a rounding residue such as -1e-16 prints as 0, not -0.000000.
std::string point(glm::dvec3 p) {
    auto clean = [](double v) { return std::fabs(v) < 5e-7 ? 0.0 : v; };
    return fmt::format("({:.6f}, {:.6f}, {:.6f})", clean(p.x), clean(p.y), clean(p.z));
}

std::string shownString(const std::string& symbols) {
    if (symbols.size() <= kShownSymbols) return symbols;
    return fmt::format("{} ... [{} symbols left out] ... {}", symbols.substr(0, kShownSymbols - kShownTail),
                       symbols.size() - kShownSymbols, symbols.substr(symbols.size() - kShownTail));
}

std::string textReport(const CheckedLsystem& lsystem, const Definition& definition, const Expansion& expansion,
                       const Skeleton& skeleton) {
    std::string out = fmt::format("lsystem '{}': {} expansion{}, seed {}, turtle {}, selection {}\n", lsystem.name,
                                  definition.expansions, definition.expansions == 1 ? "" : "s", definition.seed,
                                  definition.turtle == TurtleKind::Thesis ? "thesis" : "abop",
                                  definition.selection == Selection::Weighted ? "weighted" : "thesis");
    // Productions as the expansion used them (a random_rules block's drawn alternatives included).
    for (const auto& [symbol, alternatives] : definition.productions) {
        std::vector<std::string> texts;
        for (const Alternative& a : alternatives) texts.push_back(fmt::format("\"{}\" {}", a.text, a.weight));
        out += fmt::format("production {}: {}\n", symbol, fmt::join(texts, " | "));
    }
    out += fmt::format("length after each expansion: {}\n", fmt::join(expansion.lengths, ", "));
    out += fmt::format("string ({} symbols): {}\n", expansion.symbols.size(), shownString(expansion.symbols));
    std::map<char, size_t> counts;
    for (char c : expansion.symbols) ++counts[c];
    std::string histogram;
    for (const auto& [symbol, count] : counts) histogram += fmt::format("{}{} {}", histogram.empty() ? "" : ", ", symbol, count);
    out += fmt::format("symbols: {}\n", histogram);
    size_t byType[3] = {};
    for (const Segment& s : skeleton.segments) ++byType[size_t(s.type)];
    size_t linePoints = 0;
    for (const Connection& c : skeleton.connections) linePoints += c.points.size();
    out += fmt::format("skeleton: {} segments (none {}, tunnel {}, room {}), {} branches, {} endpoints, "
                       "{} connections ({} points), final position {}{}\n",
                       skeleton.segments.size(), byType[0], byType[1], byType[2], skeleton.branches.size(),
                       skeleton.endpoints.size(), skeleton.connections.size(), linePoints,
                       point(skeleton.finalPosition), skeleton.startOutside ? ", start outside the volume" : "");
    for (size_t i = 0; i < skeleton.segments.size() && i < kShownSegments; ++i) {
        const Segment& s = skeleton.segments[i];
        out += fmt::format("  segment {} -> {} branch {} {}\n", point(s.from), point(s.to), s.branch,
                           symbolTypeName(s.type));
    }
    if (skeleton.segments.size() > kShownSegments)
        out += fmt::format("  ... {} more segments (--format json or obj writes them all)\n",
                           skeleton.segments.size() - kShownSegments);
    for (const Endpoint& e : skeleton.endpoints) out += fmt::format("  endpoint {} branch {}\n", point(e.position), e.branch);
    return out;
}

void runLsystem(const LsystemOptions& options) {
    if (!options.output.empty() && options.format == "json")
        requireExtension(options.output, {".json"}, "the skeleton (--format json)");
    if (!options.output.empty() && options.format == "obj")
        requireExtension(options.output, {".obj"}, "the skeleton (--format obj)");
    const CheckResult result = loadChecked(options.file);
    const CheckedLsystem& lsystem = findLsystem(result.lsystems, options.file, options.name);
    const std::vector<RolePath> inputs{{"the input", options.file}, {"the rule file", lsystem.rulesPath}};
    const std::vector<RolePath> outputs{{"-o", options.output}};
    refuseClashingPaths(inputs, outputs);

    Definition definition = lsystem.definition;
    if (options.expansions) definition.expansions = *options.expansions;
    if (options.seed) definition.seed = *options.seed;
    Expansion expansion;
    Skeleton skeleton;
    try {
        checkExpansionLimits(definition);
        expansion = expand(definition);
        skeleton = interpret(definition, expansion.symbols, expansion.types);
        connectBranches(skeleton, lsystem.connect, definition.seed, definition.limits);
    } catch (const LimitError& error) {
        reportLimit(result, lsystem, error);
    }
    // The skeleton formats are streamed: a skeleton within the limits is gigabytes as one string.
    const auto write = [&](std::ostream& out) {
        if (options.format == "json") writeSkeletonJson(out, skeleton);
        else if (options.format == "obj") writeSkeletonObj(out, skeleton);
        else out << textReport(lsystem, definition, expansion, skeleton);
    };
    if (options.output.empty()) {
        write(std::cout);
        return;
    }
    writeFileAtomically(options.output, write);
    reportWritten({options.output});
}

// The production the crossover works on: the first symbol's first alternative.
const Alternative& crossedProduction(const CheckedLsystem& lsystem) {
    if (lsystem.definition.productions.empty())
        throw UserError(fmt::format("lsystem '{}' has no production to cross", lsystem.name));
    return lsystem.definition.productions.begin()->second.front();
}

void runCross(const CrossOptions& options) {
    if (options.brackets.size() != 2)
        throw UserError("--brackets takes two bracket numbers I,J (1-based, counted by their '[')");
    const auto [pathA, nameA] = splitReference(options.first);
    const auto [pathB, nameB] = splitReference(options.second);
    const CheckResult resultA = loadChecked(pathA);
    const CheckResult resultB = loadChecked(pathB);
    const CheckedLsystem& a = findLsystem(resultA.lsystems, pathA, nameA);
    const CheckedLsystem& b = findLsystem(resultB.lsystems, pathB, nameB);
    const auto [childA, childB] =
        crossover(crossedProduction(a).text, options.brackets[0], crossedProduction(b).text, options.brackets[1]);
    // Each child keeps its parent's settings and gains the other parent's macros it lacks,
    // since the graft may use them.
    auto child = [](const CheckedLsystem& own, const CheckedLsystem& other, const std::string& text) {
        Definition definition = own.definition;
        std::vector<Alternative>& production = definition.productions.begin()->second;
        production.front().text = text;
        for (const auto& [symbol, substitutes] : other.definition.macros) definition.macros.emplace(symbol, substitutes);
        return definition;
    };
    std::cout << formatLsystemBlock(nameA + "_x_" + nameB, child(a, b, childA), a.connect) << "\n"
              << formatLsystemBlock(nameB + "_x_" + nameA, child(b, a, childB), b.connect);
}

} // namespace

void addLsystemCommand(CLI::App& app) {
    auto options = std::make_shared<LsystemOptions>();
    CLI::App* command = app.add_subcommand(
        "lsystem", "Expand an lsystem block: print its string, statistics and skeleton (or write the skeleton)");
    command->add_option("file", options->file, "The .vox file");
    command->add_option("name", options->name, "The lsystem block's name");
    command->add_option("--expansions", options->expansions, "Expand this many times instead of the block's 'expansions'");
    command->add_option("--seed", options->seed, "Use this seed instead of the block's 'seed'");
    command->add_option("--format", options->format,
                        "text: string, statistics and skeleton; json: the skeleton's segments, endpoints, branches "
                        "and connections; obj: the skeleton as OBJ polylines")
        ->check(CLI::IsMember({"text", "json", "obj"}));
    command->add_option("-o,--output", options->output, "Write to this file (atomically) instead of stdout");

    auto cross = std::make_shared<CrossOptions>();
    CLI::App* crossCommand = command->add_subcommand(
        "cross", "Cross two production rules by bracket (Mark & Berechet III-D) and print the children as lsystem blocks");
    crossCommand->add_option("first", cross->first, "The first lsystem as FILE:NAME")->required();
    crossCommand->add_option("second", cross->second, "The second lsystem as FILE:NAME")->required();
    crossCommand->add_option("--brackets", cross->brackets,
                             "I,J: exchange the contents of bracket I of the first and bracket J of the second "
                             "(numbered from 1 by their '[', any depth)")
        ->delimiter(',')
        ->check(CLI::Validator(
            [](const std::string& text) -> std::string {
                // Digits only: CLI11 would read "-1" into a size_t as 2^64 - 1.
                const bool digits = !text.empty() && text.size() <= 9 &&
                                    text.find_first_not_of("0123456789") == std::string::npos;
                return digits && std::stoul(text) >= 1 ? std::string()
                                                       : "a bracket number is a whole number from 1 (counted by '[')";
            },
            "BRACKET"))
        ->required();
    addConsoleFlags(*crossCommand);
    crossCommand->callback([cross] { runCross(*cross); });

    addConsoleFlags(*command);
    command->callback([options, crossCommand] {
        if (crossCommand->parsed()) return;
        if (options->file.empty() || options->name.empty())
            throw UserError("voxc lsystem needs a FILE and the NAME of an lsystem block in it (see --help)");
        runLsystem(*options);
    });
}

} // namespace voxc::driver
