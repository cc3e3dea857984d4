// The viewer's session on lavapipe, without a window: parameters and their ranges, sliders that
// re-run, a broken file that keeps the last world, edits with undo and redo, the saved edits format.
#include "voxc/viewer/Session.h"

#include "voxc/check/Check.h"
#include "voxc/check/FeatureOverrides.h"
#include "voxc/codegen/CompileCache.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/stages/SolveCache.h"
#include "voxc/syntax/Parser.h"

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <thread>

namespace voxc::viewer {
namespace {

constexpr const char* kProgram = R"(const FLOOR = 12;
const HALF = FLOOR / 2;
world { size = [40, 32, 40]; chunk = 16; seed = 3; }
material rock { id = 1; color = [0.5, 0.5, 0.5]; }
start { box { min = [0, 0, 0]; max = [40, FLOOR, 40]; } }
feature bridge = arch {
  start = [8, 10, 20];
  end = [32, 10, 20];
  radius = 3;
  peak = 6;
}
pipeline { start; union bridge; }
)";

// A compile and solve cache of the test's own until destroyed, so what a test solves does not
// depend on earlier runs.
class OwnCache {
public:
    explicit OwnCache(const std::filesystem::path& directory) : previous_(codegen::compileCacheDirectory()) {
        codegen::setCompileCacheDirectory(directory);
    }
    ~OwnCache() { codegen::setCompileCacheDirectory(previous_); }
    OwnCache(const OwnCache&) = delete;
    OwnCache& operator=(const OwnCache&) = delete;

private:
    std::optional<std::filesystem::path> previous_;
};

class SessionTest : public ::testing::Test {
protected:
    void SetUp() override {
        directory_ = std::filesystem::temp_directory_path() /
                     ("voxc_session_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::create_directories(directory_);
        write(kProgram);
    }
    void TearDown() override { std::filesystem::remove_all(directory_); }
    void write(const std::string& text) {
        std::ofstream(path()) << text;
        // A later write in the same clock tick must still look changed.
        std::filesystem::last_write_time(path(), std::filesystem::file_time_type::clock::now() + std::chrono::seconds(++writes_));
    }
    std::string path() const { return (directory_ / "scene.vox").string(); }
    static VulkanContext& context() {
        static VulkanContext context(ContextOptions{.device = "lavapipe"});
        return context;
    }
    // `session`'s world is the world of a file that says `text` (written over the session's file
    // and opened without a preview).
    void expectWorldOfFile(const Session& session, const std::string& text) {
        write(text);
        Session written(context(), {.path = path(), .preview = {.curvesCells = 0}});
        ASSERT_TRUE(written.hasWorld()) << written.lastError();
        EXPECT_TRUE(written.world().mesh().positions == session.world().mesh().positions);
    }
    const Parameter& parameter(const Session& session, const std::string& name) {
        const auto& all = session.parameters();
        const auto it = std::find_if(all.begin(), all.end(), [&](const Parameter& p) { return p.name == name; });
        static const Parameter missing{};
        EXPECT_NE(it, all.end()) << name;
        return it == all.end() ? missing : *it;
    }

    std::filesystem::path directory_;
    int writes_ = 0;
};

TEST_F(SessionTest, ListsLiteralConstantsFeatureKeysAndSeedWithTheirRanges) {
    Session session(context(), {path()});
    ASSERT_TRUE(session.hasWorld()) << session.lastError();
    const Parameter& floor = parameter(session, "FLOOR");
    EXPECT_EQ(floor.value, 12);
    EXPECT_EQ(floor.min, 0);
    EXPECT_EQ(floor.max, 24);
    EXPECT_TRUE(floor.integer);
    // HALF follows FLOOR: no slider of its own.
    for (const Parameter& p : session.parameters()) EXPECT_NE(p.name, "HALF");
    const Parameter& peak = parameter(session, "bridge.peak");
    EXPECT_EQ(peak.value, 6);
    EXPECT_EQ(peak.min, 0);
    EXPECT_EQ(peak.max, 10); // the arch generator's declared range
    const Parameter& exponent = parameter(session, "bridge.taper_exponent"); // not written: its default
    EXPECT_EQ(exponent.value, 1);
    EXPECT_EQ(parameter(session, "bridge.iterations").integer, true);
    EXPECT_EQ(parameter(session, "seed").value, 3);
}

TEST_F(SessionTest, SlidersRerunAsIfTheFileSaidSo) {
    Session session(context(), {path()});
    ASSERT_TRUE(session.hasWorld());
    const Mesh before = session.world().mesh();
    ASSERT_TRUE(session.setParameter("bridge.peak", 2));
    EXPECT_TRUE(session.world().mesh().positions != before.positions);
    EXPECT_TRUE(parameter(session, "bridge.peak").overridden);
    // The same world as a file that writes the value.
    std::string text = kProgram;
    text.replace(text.find("peak = 6;"), 9, "peak = 2;");
    write(text);
    Session written(context(), {path()});
    EXPECT_TRUE(written.world().mesh().positions == session.world().mesh().positions);

    // A key the file leaves at its default is written into the checked text.
    ASSERT_TRUE(session.setParameter("bridge.taper_exponent", 3));
    EXPECT_EQ(parameter(session, "bridge.taper_exponent").value, 3);
    ASSERT_TRUE(session.setParameter("FLOOR", 4));
    EXPECT_EQ(session.stats().size, glm::ivec3(40, 32, 40));
    EXPECT_THROW(session.setParameter("bridge.peak", 11), UserError);
    EXPECT_THROW(session.setParameter("HALF", 1), UserError);
    ASSERT_TRUE(session.resetParameters()); // back to the file, which now says peak = 2
    EXPECT_TRUE(session.world().mesh().positions == written.world().mesh().positions);
}

constexpr const char* kGrammarProgram = R"(const CHIP = 0.35;
world { size = [16, 16, 16]; chunk = 16; seed = 1; }
start { box { min = [0, 0, 0]; max = [16, 8, 16]; } }
grammar weather {
  iterations = 2;
  rule chip { size = [1, 2, 1]; probability = CHIP; priority = 1; symbol { [LT 0.5] [GEQ 0.5] } transform { [NOP] [SET 0] } }
}
pipeline { start; weather; }
)";

TEST_F(SessionTest, GrammarKeysAreParametersWithTheLanguagesRanges) {
    write(kGrammarProgram);
    Session session(context(), {path()});
    ASSERT_TRUE(session.hasWorld()) << session.lastError();
    // A constant that is a rule's probability ranges over the probability's [0, 1], not to twice its value.
    const Parameter& chip = parameter(session, "CHIP");
    EXPECT_EQ(chip.min, 0);
    EXPECT_EQ(chip.max, 1);
    EXPECT_FALSE(chip.integer);
    const Parameter& iterations = parameter(session, "weather.iterations");
    EXPECT_EQ(iterations.value, 2);
    EXPECT_EQ(iterations.min, 1);
    EXPECT_EQ(iterations.max, Limits{}.maxIterations);
    EXPECT_TRUE(iterations.integer);
    EXPECT_LE(iterations.sliderMax - iterations.sliderMin, 1000); // a usable part of it on the slider
    EXPECT_EQ(parameter(session, "weather.chip.priority").value, 1);
    const Parameter& weight = parameter(session, "weather.chip.weight"); // not written: the default
    EXPECT_EQ(weight.value, 1);
    EXPECT_EQ(weight.max, 1000);
    // A probability written as a constant follows the constant: no slider of its own.
    for (const Parameter& p : session.parameters()) EXPECT_NE(p.name, "weather.chip.probability");

    ASSERT_TRUE(session.setParameter("CHIP", 0.9)) << session.lastError();
    ASSERT_TRUE(session.setParameter("weather.iterations", 4)) << session.lastError();
    EXPECT_TRUE(parameter(session, "weather.iterations").overridden);
    EXPECT_THROW(session.setParameter("CHIP", 1.5), UserError);
    EXPECT_THROW(session.setParameter("weather.iterations", 0), UserError);
    // The same world as a file that writes both values.
    std::string text = kGrammarProgram;
    text.replace(text.find("CHIP = 0.35"), 11, "CHIP = 0.9");
    text.replace(text.find("iterations = 2"), 14, "iterations = 4");
    expectWorldOfFile(session, text);

    try {
        session.setParameter("weather.iteratons", 3);
        ADD_FAILURE() << "an unknown name was accepted";
    } catch (const UserError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("no parameter named 'weather.iteratons' (the parameters are: seed, CHIP, "
                               "weather.iterations, weather.chip.priority, weather.chip.weight)"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("did you mean 'weather.iterations'?"), std::string::npos) << message;
    }
}

TEST_F(SessionTest, ABrokenFileKeepsTheLastWorldAndSaysWhy) {
    Session session(context(), {path()});
    ASSERT_TRUE(session.hasWorld());
    const Mesh before = session.world().mesh();
    const uint64_t generation = session.generation();
    std::string text = kProgram;
    text.replace(text.find("peak = 6;"), 9, "peak = 6");
    write(text);
    EXPECT_TRUE(session.fileChanged());
    EXPECT_FALSE(session.reload());
    EXPECT_FALSE(session.fileChanged()); // not reloaded again until the next save
    EXPECT_NE(session.lastError().find("scene.vox:10:"), std::string::npos) << session.lastError();
    EXPECT_NE(session.lastError().find("error E0001"), std::string::npos) << session.lastError();
    EXPECT_EQ(session.generation(), generation);
    EXPECT_TRUE(session.world().mesh().positions == before.positions);
    write(kProgram);
    EXPECT_TRUE(session.reload());
    EXPECT_TRUE(session.lastError().empty());
}

TEST_F(SessionTest, EditsUndoAndRedoGiveTheMeshOfTheGrid) {
    Session session(context(), {path()});
    ASSERT_TRUE(session.hasWorld());
    const Mesh original = session.world().mesh();
    const Brush carve{Brush::Op::Carve, {20.0f, 12.0f, 20.0f}, 4.0f, 2.0f};
    const EditStats stats = session.edit(carve);
    EXPECT_GT(stats.chunksRemeshed, 0u);
    const Mesh carved = session.world().mesh();
    EXPECT_TRUE(carved.positions != original.positions);
    EXPECT_TRUE(carved.positions == meshMarchingCubes(session.world().grid(), MeshOptions{}).positions);
    // A carve in the air changes nothing and is not recorded.
    session.edit({Brush::Op::Carve, {20.0f, 30.0f, 2.0f}, 1.0f, 1.0f});
    EXPECT_EQ(session.edits().size(), 1u);
    ASSERT_TRUE(session.undo());
    EXPECT_TRUE(session.world().mesh().positions == original.positions);
    EXPECT_FALSE(session.undo());
    ASSERT_TRUE(session.redo());
    EXPECT_TRUE(session.world().mesh().positions == carved.positions);
    // Edits survive a reload: replayed on the new world.
    ASSERT_TRUE(session.reload());
    EXPECT_TRUE(session.world().mesh().positions == carved.positions);
}

TEST_F(SessionTest, StartingEditsAreReadOnceTheFileFirstChecksWithItsMaterials) {
    std::string broken = kProgram;
    broken.replace(broken.find("peak = 6;"), 9, "peak = 6");
    write(broken);
    int reads = 0;
    const Brush carve{Brush::Op::Carve, {20.0f, 12.0f, 20.0f}, 4.0f, 2.0f};
    SessionOptions options{path()};
    options.readEdits = [&](const Program& program) {
        ++reads;
        EXPECT_EQ(program.materials.size(), 1u);
        return std::vector<Brush>{carve};
    };
    Session session(context(), options);
    EXPECT_FALSE(session.hasWorld());
    EXPECT_EQ(reads, 0); // the materials are not known yet
    write(kProgram);
    ASSERT_TRUE(session.reload());
    ASSERT_TRUE(session.reload());
    EXPECT_EQ(reads, 1);
    Session unedited(context(), {path()});
    unedited.edit(carve);
    EXPECT_TRUE(session.world().mesh().positions == unedited.world().mesh().positions);
    ASSERT_EQ(session.edits().size(), 1u);
}

TEST_F(SessionTest, AnUnreadableEditsFileEndsTheSession) {
    SessionOptions options{path()};
    options.readEdits = [](const Program&) -> std::vector<Brush> { throw UserError("edits.json:1:1: bad"); };
    EXPECT_THROW(Session(context(), options), UserError);
}

TEST_F(SessionTest, SavedEditsAreTheRunEditsFormatWithShortestExactFloats) {
    Session session(context(), {path()});
    session.edit({Brush::Op::Carve, {20.1f, 12.0f, 20.0f}, 4.5f, 2.0f});
    session.edit({Brush::Op::Add, {10.0f, 12.0f, 30.0f}, 3.0f, 1.0f, 1});
    EXPECT_EQ(formatEdits(session.edits(), session.program().materials),
              "[\n"
              "  {\"op\": \"carve\", \"center\": [20.1, 12, 20], \"radius\": 4.5, \"softness\": 2},\n"
              "  {\"op\": \"add\", \"center\": [10, 12, 30], \"radius\": 3, \"softness\": 1, \"material\": \"rock\"}\n"
              "]\n");
    EXPECT_EQ(formatEdits({}, {}), "[]\n");
}

// A terrain, a curves block and an lsystem carved by a feature, small enough to solve in a moment.
constexpr const char* kBlocksProgram = R"(world { size = [32, 24, 32]; chunk = 16; seed = 2; }
material sand { id = 1; color = [0.8, 0.7, 0.5]; }
material rock { id = 2; color = [0.5, 0.5, 0.5]; }
start { fill { value = 0; } }
terrain valley {
  size = 32;  levels = [2, 5];  max_height = 10;  preset = mountain_river;  steps_scale = 0.05;  material = rock;
  noise { amplitude = 2; }
  spline river { points = [[0, 4, 16], [10, 4, 20], [22, 4, 12], [32, 4, 16]]; radius = 2; rain = 0.5; }
}
curves cliffs {
  box = [[0, 0, 0], [31, 23, 15]];
  curve face {
    points = [[-2, 12, 8], [10, 12, 8], [21, 12, 8], [33, 12, 8]];
    constraint { t = 0; material = sand; amplitude = 1; }
    constraint { t = 1; material = sand; }
  }
  curve {
    points = [[-2, 20, 2], [10, 20, 2], [21, 20, 2], [33, 20, 2]];
    constraint { t = 0; }
    constraint { t = 1; roughness = 0.25; }
  }
}
lsystem net { expansions = 2; start = [4, 12, 24]; production Z { "FZ[RFZ]"; } }
feature tunnels = lsystem_cave { lsystem = net; radius = 2; }
pipeline { start; set valley; union cliffs; subtract tunnels; }
)";

TEST_F(SessionTest, CurvesTerrainAndLsystemKeysAreParametersWithTheCheckersRanges) {
    write(kBlocksProgram);
    Session session(context(), {path()});
    ASSERT_TRUE(session.hasWorld()) << session.lastError();
    struct Expected {
        const char* name;
        double value, min, max;
        bool integer;
    };
    // Written values, and the language's defaults where the file leaves a key out.
    const Expected expected[] = {
        {"cliffs.face.constraint[0].amplitude", 1, 0, 16, false},
        {"cliffs.face.constraint[1].amplitude", 0, 0, 16, false},
        {"cliffs.face.constraint[0].roughness", 0.5, 0, 1, false},
        {"cliffs.curve.constraint[1].roughness", 0.25, 0, 1, false},
        {"cliffs.noise_frequency", 0.0625, 0, 16, false},
        {"cliffs.smoothing", 1, 0, 64, true},
        {"valley.river.rain", 0.5, 0, 1000, false},
        {"valley.river.radius", 2, 0, 1e6, false},
        {"valley.noise.amplitude", 2, 0, 1e6, false},
        {"valley.steps_scale", 0.05, 0, 100, false},
        {"valley.max_height", 10, 1, 1e6, false},
        {"net.expansions", 2, 0, 16, true},
        {"net.seed", 0, 0, 4294967295.0, true},
        {"net.angle", 45, 0, 180, false},
    };
    for (const Expected& e : expected) {
        const Parameter& p = parameter(session, e.name);
        EXPECT_EQ(p.kind, Parameter::Kind::BlockKey) << e.name;
        EXPECT_EQ(p.value, e.value) << e.name;
        EXPECT_EQ(p.min, e.min) << e.name;
        EXPECT_EQ(p.max, e.max) << e.name;
        EXPECT_EQ(p.integer, e.integer) << e.name;
        EXPECT_LE(p.sliderMax - p.sliderMin, 1e6) << e.name;
    }
    // Every block key's range is the checker's: both ends pass its range checks (E0007; a bound on
    // work, E0012, depends on the whole file: 16 expansions of this net carve too many points), a
    // step past either is an error.
    Diagnostics parseErrors;
    const SourceFile source(path(), kBlocksProgram);
    const ast::File file = parse(source, parseErrors);
    ASSERT_FALSE(parseErrors.hasErrors());
    size_t blockKeys = 0;
    for (const Parameter& p : session.parameters()) {
        if (p.kind != Parameter::Kind::BlockKey) continue;
        ++blockKeys;
        const auto checkWith = [&](double value) {
            return checkSource(SourceFile(path(), overrideFeatureKeys(kBlocksProgram, file, {{p.name, value}})));
        };
        for (const double inside : {p.min, p.max}) {
            const CheckResult checked = checkWith(inside);
            for (const Diagnostic& d : checked.diagnostics)
                EXPECT_TRUE(d.severity != Severity::Error || d.code == "E0012")
                    << p.name << " = " << inside << "\n" << checked.rendered();
        }
        const double step = p.integer ? 1.0 : std::max(1e-3, 1e-3 * (p.max - p.min));
        for (const double outside : {p.min - step, p.max + step}) {
            const CheckResult checked = checkWith(outside);
            EXPECT_TRUE(checked.hasErrors()) << p.name << " = " << outside;
        }
    }
    EXPECT_GE(blockKeys, 30u);
}

TEST_F(SessionTest, CurvesTerrainAndLsystemSlidersRerunAsIfTheFileSaidSo) {
    const OwnCache cache(directory_ / "cache");
    write(kBlocksProgram);
    Session session(context(), {path()});
    ASSERT_TRUE(session.hasWorld()) << session.lastError();
    const std::vector<glm::vec3> before = session.world().mesh().positions;
    // As the window's float slider gives it: the decimal the panel shows, not the float's expansion.
    EXPECT_EQ(sliderValue(2.7f), 2.7);
    ASSERT_TRUE(session.setParameter("cliffs.face.constraint[1].amplitude", sliderValue(2.7f))) << session.lastError();
    EXPECT_TRUE(session.world().mesh().positions != before);
    // A terrain key solves the terrain again; the curves block, unchanged, comes from the cache.
    const stages::SolveCacheCounts counts = stages::solveCacheCounts();
    ASSERT_TRUE(session.setParameter("valley.river.rain", 2)) << session.lastError();
    EXPECT_EQ(stages::solveCacheCounts().solved - counts.solved, 1u);
    EXPECT_EQ(stages::solveCacheCounts().hits - counts.hits, 1u);
    ASSERT_TRUE(session.setParameter("net.expansions", 3)) << session.lastError();
    EXPECT_TRUE(parameter(session, "net.expansions").overridden);
    EXPECT_THROW(session.setParameter("cliffs.face.constraint[0].roughness", 1.5), UserError);
    EXPECT_THROW(session.setParameter("net.expansions", 17), UserError);
    // The same world as a file that writes the three values (one of them a key the file left out).
    std::string text = kBlocksProgram;
    const std::string secondPoint = "constraint { t = 1; material = sand; }";
    text.replace(text.find(secondPoint), secondPoint.size(), "constraint { t = 1; material = sand; amplitude = 2.7; }");
    text.replace(text.find("rain = 0.5"), 10, "rain = 2");
    text.replace(text.find("expansions = 2"), 14, "expansions = 3");
    // The file has the sliders' solve keys: opened afresh, and reloaded without the sliders, it
    // reads both solves from the cache and solves nothing.
    const stages::SolveCacheCounts beforeFile = stages::solveCacheCounts();
    expectWorldOfFile(session, text);
    ASSERT_TRUE(session.resetParameters()) << session.lastError();
    EXPECT_EQ(stages::solveCacheCounts().solved - beforeFile.solved, 0u);
    EXPECT_EQ(stages::solveCacheCounts().hits - beforeFile.hits, 4u);

    try {
        session.setParameter("cliffs.face.constraint[3].amplitude", 1);
        ADD_FAILURE() << "an unknown name was accepted";
    } catch (const UserError& error) {
        const std::string message = error.what();
        for (const char* listed : {"cliffs.face.constraint[1].amplitude", "valley.river.rain", "net.expansions", "seed"})
            EXPECT_NE(message.find(listed), std::string::npos) << listed << " in " << message;
    }
}

// Waits for the background solve to replace the preview.
std::optional<bool> waitForRefine(Session& session) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < until) {
        if (std::optional<bool> refined = session.poll()) return refined;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return std::nullopt;
}

TEST_F(SessionTest, ALargeSolveIsPreviewedCoarseThenRefinedToThePlainRunsWorld) {
    const OwnCache cache(directory_ / "cache");
    write(kBlocksProgram);
    // Sizes that make this small file's curves box (32x24x16) and terrain (level 5) previewed:
    // the curves on a 16x12x8 box, the terrain to level 4.
    const PreviewOptions preview{.curvesCells = 2048, .terrainLevel = 4};
    Session session(context(), {.path = path(), .preview = preview});
    ASSERT_TRUE(session.hasWorld()) << session.lastError();
    EXPECT_TRUE(session.refining());
    EXPECT_TRUE(session.stats().preview);
    const std::vector<glm::vec3> coarse = session.world().mesh().positions;
    const ChunkedGrid coarseGrid = session.world().grid();
    const uint64_t shown = session.generation();
    ASSERT_EQ(waitForRefine(session), std::optional<bool>(true)) << session.lastError();
    EXPECT_FALSE(session.refining());
    EXPECT_FALSE(session.stats().preview);
    EXPECT_EQ(session.generation(), shown + 1);
    EXPECT_TRUE(session.world().mesh().positions != coarse);
    EXPECT_EQ(session.poll(), std::nullopt); // nothing more to show
    // A preview of the same world: solid and air agree in all but a few percent of the voxels.
    size_t cells = 0, differing = 0;
    const glm::ivec3 size = session.stats().size;
    for (int32_t z = 0; z < size.z; ++z)
        for (int32_t y = 0; y < size.y; ++y)
            for (int32_t x = 0; x < size.x; ++x, ++cells)
                differing += (coarseGrid.at({x, y, z}) >= 0.5f) != (session.world().grid().at({x, y, z}) >= 0.5f);
    EXPECT_GT(differing, 0u);
    EXPECT_LT(differing, cells / 20) << differing << " of " << cells;

    // The refined world is the one a session without previews and without the cache solves.
    codegen::setCompileCacheDirectory(std::nullopt);
    Session plain(context(), {.path = path(), .preview = {.curvesCells = 0}});
    codegen::setCompileCacheDirectory(directory_ / "cache");
    ASSERT_TRUE(plain.hasWorld()) << plain.lastError();
    EXPECT_FALSE(plain.refining());
    EXPECT_TRUE(plain.world().mesh().positions == session.world().mesh().positions);
    // Both blocks are cached now, so the same file with previews on shows its full world at once.
    Session again(context(), {.path = path(), .preview = preview});
    EXPECT_FALSE(again.refining());
    EXPECT_TRUE(again.world().mesh().positions == session.world().mesh().positions);

    // Two slider moves in a row: the first one's refine is superseded, never shown.
    ASSERT_TRUE(session.setParameter("cliffs.face.constraint[1].amplitude", 2)) << session.lastError();
    EXPECT_TRUE(session.refining());
    ASSERT_TRUE(session.setParameter("cliffs.face.constraint[1].amplitude", 4)) << session.lastError();
    EXPECT_TRUE(session.refining());
    const uint64_t second = session.generation();
    ASSERT_EQ(waitForRefine(session), std::optional<bool>(true)) << session.lastError();
    EXPECT_EQ(session.generation(), second + 1);
    std::string text = kBlocksProgram;
    const std::string secondPoint = "constraint { t = 1; material = sand; }";
    text.replace(text.find(secondPoint), secondPoint.size(), "constraint { t = 1; material = sand; amplitude = 4; }");
    expectWorldOfFile(session, text);

    // A file that stops checking while a preview is on screen keeps it, and its refine still
    // comes: the last good world, solved fully.
    ASSERT_TRUE(session.setParameter("cliffs.face.constraint[1].amplitude", 5)) << session.lastError();
    ASSERT_TRUE(session.refining());
    write(std::string(kBlocksProgram) + "oops");
    EXPECT_FALSE(session.reload());
    EXPECT_TRUE(session.refining());
    ASSERT_EQ(waitForRefine(session), std::optional<bool>(true)) << session.lastError();
    text.replace(text.find("amplitude = 4; }"), 16, "amplitude = 5; }");
    write(text);
    Session five(context(), {.path = path(), .preview = {.curvesCells = 0}});
    ASSERT_TRUE(five.hasWorld()) << five.lastError();
    EXPECT_TRUE(five.world().mesh().positions == session.world().mesh().positions);
}

// A reload that solves the same blocks as the running full solve (the same solve keys: the file
// saved again unchanged, or with the values the sliders had) lets it finish into the solve cache
// and reads its tables there, rather than stopping it and solving again.
// Holds the full solve that starts as number `held` (1 for the opening's) until release(); the
// other solves pass through. A Releaser made after the session releases it on every way out of a
// test, before the session's destructor waits for the solve.
class SolveGate {
public:
    explicit SolveGate(int held) : held_(held) {}

    std::function<void()> hook() {
        return [this] {
            std::unique_lock lock(mutex_);
            ++started_;
            changed_.notify_all();
            if (started_ == held_) changed_.wait(lock, [&] { return released_; });
        };
    }
    bool waitForStarts(int count) {
        std::unique_lock lock(mutex_);
        return changed_.wait_for(lock, std::chrono::seconds(60), [&] { return started_ == count; });
    }
    void release() {
        const std::lock_guard lock(mutex_);
        released_ = true;
        changed_.notify_all();
    }
    int started() {
        const std::lock_guard lock(mutex_);
        return started_;
    }

    struct Releaser {
        SolveGate& gate;
        ~Releaser() { gate.release(); }
    };

private:
    std::mutex mutex_;
    std::condition_variable changed_;
    int started_ = 0;
    const int held_;
    bool released_ = false;
};

TEST_F(SessionTest, AReloadWithTheSameSolveKeysLetsTheRunningSolveFinish) {
    const OwnCache cache(directory_ / "cache");
    write(kBlocksProgram);
    SolveGate gate(1); // holds the opening's full solve until the reload is made
    SessionOptions options{.path = path(), .preview = {.curvesCells = 2048, .terrainLevel = 4}};
    options.fullSolveStarting = gate.hook();
    const stages::SolveCacheCounts before = stages::solveCacheCounts();
    Session session(context(), options);
    const SolveGate::Releaser releaseOnExit{gate};
    ASSERT_TRUE(session.refining()) << session.lastError();
    ASSERT_TRUE(gate.waitForStarts(1));
    ASSERT_TRUE(session.reload()) << session.lastError();
    ASSERT_TRUE(session.refining());
    gate.release();
    ASSERT_EQ(waitForRefine(session), std::optional<bool>(true)) << session.lastError();
    EXPECT_EQ(session.stoppedSolves(), 0u);
    // The held solve solved the curves and the terrain; the reload's read both from the cache.
    EXPECT_EQ(stages::solveCacheCounts().solved - before.solved, 2u);
    EXPECT_EQ(stages::solveCacheCounts().hits - before.hits, 2u);
    EXPECT_EQ(gate.started(), 2);
}

TEST_F(SessionTest, ASupersededRunningSolveStops) {
    const OwnCache cache(directory_ / "cache");
    write(kBlocksProgram);
    // The full solve of the first slider move is held as it starts, until the second move has
    // superseded it: then it runs with its stop asked for, as a solve that was running would.
    SolveGate gate(2);
    const PreviewOptions preview{.curvesCells = 2048, .terrainLevel = 4};
    SessionOptions options{.path = path(), .preview = preview};
    options.fullSolveStarting = gate.hook();
    Session session(context(), options);
    const SolveGate::Releaser releaseOnExit{gate};
    ASSERT_TRUE(session.refining()) << session.lastError();
    ASSERT_EQ(waitForRefine(session), std::optional<bool>(true)) << session.lastError();

    ASSERT_TRUE(session.setParameter("cliffs.face.constraint[1].amplitude", 2)) << session.lastError();
    ASSERT_TRUE(gate.waitForStarts(2));
    ASSERT_TRUE(session.setParameter("cliffs.face.constraint[1].amplitude", 4)) << session.lastError();
    gate.release();
    ASSERT_EQ(waitForRefine(session), std::optional<bool>(true)) << session.lastError();
    EXPECT_EQ(session.stoppedSolves(), 1u);
    EXPECT_EQ(gate.started(), 3); // the opening's, the stopped one and the second move's
    std::string text = kBlocksProgram;
    const std::string secondPoint = "constraint { t = 1; material = sand; }";
    text.replace(text.find(secondPoint), secondPoint.size(), "constraint { t = 1; material = sand; amplitude = 4; }");
    expectWorldOfFile(session, text);
}

} // namespace
} // namespace voxc::viewer
