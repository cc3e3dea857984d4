// The differential fuzzer (docs/fuzzing.md): random valid programs (ProgramGenerator.h) run by the
// interpreter and by Vulkan (lavapipe), compared bit for bit, densities and materials, as
// docs/architecture.md ("Determinism") promises for every record the generator uses.
//
//   voxc_diff_fuzz [--seed S] [--programs N] [--seconds T] [--out DIR] [--verbose] [FILE.vox ...]
//
// Program i of a run is generated from seed S + i. Files given on the command line are compared
// instead of generated programs; a file whose text holds `voxc_diff_fuzz tolerance: T` (in a
// comment) is compared within T, the documented tolerance of the records it calls, instead of bit
// for bit (NaN must still meet NaN). A program that differs, or that the checker accepted but voxc
// then failed on, is written to DIR (default diff-findings/) and makes the exit status 1; so does
// a run where the checker rejected more than half the generated programs (the generator would be
// testing nothing). Programs the checker rejects are counted, not compared.
//
// Each compared pair then gets the same random sphere brushes (what an edits file or the viewer's
// brush replays, docs/cli.md "Edits files"), applied to the interpreter's dense grid and to the
// device's chunked grid by their own loops, and is compared again.
#include "ProgramGenerator.h"
#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/core/Errors.h"
#include "voxc/edit/Brush.h"
#include "voxc/grid/Grid.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

struct Options {
    uint64_t seed = 1;
    std::optional<uint64_t> programs;
    std::optional<double> seconds;
    std::filesystem::path out = "diff-findings";
    bool verbose = false;
    std::vector<std::string> files;
};

struct Tally {
    uint64_t compared = 0, rejected = 0, findings = 0, voxels = 0, solidVoxels = 0, brushes = 0;
};

bool sameDensity(float a, float b, float tolerance) {
    if (tolerance == 0.0f || std::isnan(a) || std::isnan(b)) return std::memcmp(&a, &b, sizeof a) == 0;
    return std::fabs(a - b) <= tolerance;
}

// The first few voxels where the two grids differ, or nothing when they agree.
std::optional<std::string> differences(const voxc::DenseGrid& expected, const voxc::DenseGrid& actual, float tolerance) {
    if (expected.size() != actual.size()) return "grid sizes differ";
    std::string report;
    size_t count = 0;
    const glm::ivec3 size = expected.size();
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const float a = expected.at({x, y, z}), b = actual.at({x, y, z});
                const int ma = expected.materialAt({x, y, z}), mb = actual.materialAt({x, y, z});
                if (sameDensity(a, b, tolerance) && ma == mb) continue;
                if (count++ < 5)
                    report += fmt::format("  voxel ({},{},{}): interpreter {} (material {}), vulkan {} (material {})\n", x,
                                          y, z, a, ma, b, mb);
            }
    if (count == 0) return std::nullopt;
    return fmt::format("{} voxels differ\n{}", count, report);
}

voxc::VulkanContext& lavapipe() {
    static voxc::VulkanContext context(voxc::ContextOptions{.device = "lavapipe"});
    return context;
}

// `voxc_diff_fuzz tolerance: T` in the text, or 0 (bit for bit).
float declaredTolerance(const std::string& text) {
    constexpr std::string_view kKey = "voxc_diff_fuzz tolerance:";
    const size_t at = text.find(kKey);
    return at == std::string::npos ? 0.0f : std::stof(text.substr(at + kKey.size()));
}

// 1 to 6 brushes from the program's text: carves and adds (some painting a material), centres
// within or just outside the grid, radii from under a voxel to a third of it, hard to soft ramps.
std::vector<voxc::Brush> randomBrushes(const std::string& text, const voxc::World& world) {
    uint64_t state = 1469598103934665603ull; // FNV-1a of the text, then splitmix64 draws
    for (unsigned char c : text) state = (state ^ c) * 1099511628211ull;
    const auto next = [&] {
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    };
    const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * float(next() >> 40) / float(1 << 24); };
    std::vector<voxc::Brush> brushes(1 + next() % 6);
    const glm::vec3 low = glm::vec3(world.origin) - 4.0f, high = glm::vec3(world.origin + world.size) + 4.0f;
    for (voxc::Brush& brush : brushes) {
        brush.op = next() % 2 ? voxc::Brush::Op::Carve : voxc::Brush::Op::Add;
        brush.center = {uniform(low.x, high.x), uniform(low.y, high.y), uniform(low.z, high.z)};
        brush.radius = uniform(0.3f, float(std::max({world.size.x, world.size.y, world.size.z})) / 3.0f);
        brush.softness = uniform(0.1f, 6.0f);
        brush.material = brush.op == voxc::Brush::Op::Add && next() % 2 ? uint8_t(1 + next() % 4) : 0;
    }
    return brushes;
}

// Checks, runs and compares one program; returns what went wrong, if anything.
std::optional<std::string> compare(const std::string& name, const std::string& text, const Options& options, Tally& tally) {
    const voxc::CheckResult checked = voxc::checkSource(voxc::SourceFile(name, text));
    if (!checked.program) {
        ++tally.rejected;
        if (options.verbose) fmt::print("{}: rejected by the checker\n{}", name, checked.rendered());
        return std::nullopt;
    }
    try {
        const voxc::DenseGrid expected = voxc::interpret(*checked.program);
        voxc::VulkanExecutor executor(lavapipe(), voxc::compileProgram(*checked.program));
        voxc::ChunkedGrid device = executor.run().grid;
        ++tally.compared;
        tally.voxels += expected.data().size();
        for (float density : expected.data()) tally.solidVoxels += density >= 0.5f;
        const float tolerance = declaredTolerance(text);
        if (auto found = differences(expected, device.toDense(), tolerance)) return found;
        voxc::DenseGrid edited = expected;
        const std::vector<voxc::Brush> brushes = randomBrushes(text, checked.program->world);
        for (const voxc::Brush& brush : brushes) {
            voxc::applyBrush(edited, checked.program->world.origin, brush);
            voxc::applyBrush(device, brush);
        }
        tally.brushes += brushes.size();
        if (auto found = differences(edited, device.toDense(), tolerance))
            return fmt::format("after {} brushes (interpreter's dense grid vs the device's chunked grid):\n{}",
                               brushes.size(), *found);
        return std::nullopt;
    } catch (const voxc::UserError& error) {
        // A limit of the run (a work budget, a device limit) rather than a disagreement.
        ++tally.rejected;
        if (options.verbose) fmt::print("{}: {}\n", name, error.what());
        return std::nullopt;
    } catch (const std::exception& error) {
        return fmt::format("checked, then failed: {}", error.what());
    }
}

Options parseOptions(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw voxc::UserError(fmt::format("{} needs a value", arg));
            return argv[++i];
        };
        if (arg == "--seed") options.seed = std::stoull(value());
        else if (arg == "--programs") options.programs = std::stoull(value());
        else if (arg == "--seconds") options.seconds = std::stod(value());
        else if (arg == "--out") options.out = value();
        else if (arg == "--verbose") options.verbose = true;
        else if (arg.starts_with("--")) throw voxc::UserError(fmt::format("unknown option {}", arg));
        else options.files.push_back(arg);
    }
    if (!options.programs && !options.seconds) options.programs = 20;
    return options;
}

void recordFinding(const Options& options, const std::string& name, const std::string& text, const std::string& what,
                   Tally& tally) {
    ++tally.findings;
    std::filesystem::create_directories(options.out);
    const std::filesystem::path path = options.out / std::filesystem::path(name).filename();
    std::ofstream(path) << "// voxc_diff_fuzz finding: " << what.substr(0, what.find('\n')) << "\n" << text;
    fmt::print("FINDING {}: {}  program written to {}\n", name, what, path.string());
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
    try {
        const Options options = parseOptions(argc, argv);
        Tally tally;
        if (!options.files.empty()) {
            for (const std::string& file : options.files) {
                std::stringstream text;
                text << std::ifstream(file).rdbuf();
                if (const auto what = compare(file, text.str(), options, tally)) recordFinding(options, file, text.str(), *what, tally);
            }
            fmt::print("diff: {} files compared, {} rejected, {} findings\n", tally.compared, tally.rejected, tally.findings);
            return tally.findings ? 1 : 0;
        }
        const auto begin = std::chrono::steady_clock::now();
        uint64_t generated = 0;
        for (; !options.programs || generated < *options.programs; ++generated) {
            const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
            if (options.seconds && elapsed >= *options.seconds) break;
            const uint64_t seed = options.seed + generated;
            const std::string name = fmt::format("diff_{}.vox", seed);
            const std::string text = voxc::fuzz::generateProgram(seed);
            if (options.verbose) fmt::print("--- {}\n{}", name, text);
            if (const auto what = compare(name, text, options, tally)) recordFinding(options, name, text, *what, tally);
        }
        fmt::print("diff: {} programs from seed {}: {} compared bit for bit ({} voxels, {} of them solid; then again "
                   "after {} brushes), {} rejected, {} findings\n",
                   generated, options.seed, tally.compared, tally.voxels, tally.solidVoxels, tally.brushes, tally.rejected,
                   tally.findings);
        if (tally.rejected * 2 > generated) {
            fmt::print("diff: the checker rejected more than half the generated programs (--verbose shows why)\n");
            return 1;
        }
        return tally.findings ? 1 : 0;
    } catch (const std::exception& error) {
        fmt::print(stderr, "voxc_diff_fuzz: {}\n", error.what());
        return 2;
    }
}
