#pragma once
// What `voxc view` shows, without the window: a .vox file checked and run on a Vulkan device, its
// grid as an EditableWorld with the user's brush edits (undo, redo, saved as the JSON that
// `voxc run --edits` replays), the file's parameters as slider values, and hot reload that keeps
// the last good world when the file (or a slider) no longer checks. docs/viewer.md.
//
// Parameters: every `const` written as a plain number, the world's seed, every number or integer
// key of a feature (Dey's generators), each grammar's `iterations` and each rule's `probability`,
// `priority` and `weight`, and the number keys of curves, terrain and lsystem blocks (constraint
// points' amplitude and roughness, a terrain spline's radius and rain, an lsystem's expansions,
// ...: voxc/check/KeyRanges.h's blockKeys), each within the range the language declares for its key
// (a constant: the ranges of the keys it is the value of, or without one, 0 to twice its value).
// A constant is overridden through CheckOptions::constOverrides; a key by rewriting its value in
// the text given to the checker (the file on disk is never written), so both are checked exactly
// as if the file said so.
#include "voxc/edit/EditableWorld.h"
#include "voxc/program/Program.h"
#include "voxc/viewer/Preview.h"
#include "voxc/vulkan/Context.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace voxc::ast {
struct File;
}

namespace voxc::viewer {

struct Parameter {
    enum class Kind : uint8_t { Constant, FeatureKey, GrammarKey, BlockKey, Seed };
    Kind kind = Kind::Constant;
    // The constant's name, "feature.key", "grammar.key" (iterations), "grammar.rule.key"
    // (probability, priority, weight), a curves, terrain or lsystem block's key as findKeyTarget
    // (voxc/check/FeatureOverrides.h) reads it ("cliffs.face.constraint[1].amplitude",
    // "valley.river.rain", "net.expansions"), or "seed".
    std::string name = {};
    double value = 0.0;
    double min = 0.0, max = 1.0; // what `set` accepts: the key's declared range
    bool integer = false;
    bool overridden = false; // a slider replaced the file's value
    double sliderMin = 0.0, sliderMax = 1.0; // the slider's span: the range, or a part of it around the value
};

struct SessionOptions {
    std::string path = {};             // the .vox file
    std::optional<uint32_t> seed = {}; // --seed
    std::optional<int32_t> chunk = {}; // --chunk
    float iso = 0.5f;
    // Reads the edits replayed on the world (--edits) once the file first checks, since they name
    // its materials (and its grid bounds their work); a UserError it throws leaves reload() (the
    // edits file is not watched).
    std::function<std::vector<Brush>(const Program&)> readEdits = {};
    // Which curves and terrain blocks are shown coarse first while their full solve runs in the
    // background (Preview.h; docs/viewer.md, "Progressive preview").
    PreviewOptions preview = {};
    // Called on the background thread as each full solve starts, before its first pass (tests
    // hold a solve there until a newer reload has superseded it).
    std::function<void()> fullSolveStarting = {};
};

// What the last successful run made, for the panel's statistics.
struct WorldStats {
    glm::ivec3 size{0};
    int32_t chunkSize = 0;
    glm::ivec3 chunkCount{0};
    uint64_t dispatches = 0;
    size_t triangles = 0;
    // solveMs: the curves and terrain solves (a preview's coarse ones; after a refine, the
    // background's full ones); compileMs is then lowering and kernels only.
    double checkMs = 0.0, solveMs = 0.0, compileMs = 0.0, runMs = 0.0, meshMs = 0.0;
    bool preview = false; // the world is a coarse preview; the full solve is running
};

struct EditStats {
    size_t chunksRemeshed = 0; // whose share of the mesh the edit can change (EditResult::chunksRemeshed)
    size_t voxelsInBox = 0; // of the changed box; 0 for a no-op
    double ms = 0.0;        // brush and re-mesh
};

class Session {
public:
    // Loads the file (reload()); a file that does not check leaves the session without a world
    // and the diagnostics in lastError(). `context` must outlive the session.
    Session(VulkanContext& context, SessionOptions options);
    ~Session();

    // Re-reads, re-checks and re-runs the file with the current parameters, then replays the
    // edits. On errors (diagnostics, or a run the device refuses) keeps the last good world and
    // returns false; lastError() holds the rendered diagnostics. When a large curves or terrain
    // block must be solved (SessionOptions::preview), the world is a coarse preview and the full
    // solve runs in the background (refining()); a later reload that makes a world supersedes it
    // (one that fails keeps the preview and lets its refine finish).
    bool reload();
    // Whether a background solve will replace the preview on screen.
    bool refining() const { return refining_; }
    // Background solves a newer reload stopped while they ran (at a V-cycle, a pass or a batch of
    // erosion steps: stages::SolveOptions::stop).
    uint64_t stoppedSolves() const;
    // Shows the background solve's world once it is done: nothing while it runs (or when there is
    // none), true when the world was replaced (the one a reload without a preview makes), false
    // when the solve or the run failed (lastError(); the preview stays). Call it from the thread
    // that drives the session, as often as convenient.
    std::optional<bool> poll();
    // True when the file's modification time, size or text differ from what was last loaded.
    bool fileChanged() const;

    bool hasWorld() const;
    const EditableWorld& world() const; // requires hasWorld()
    const Program& program() const;     // the last good program
    const std::string& lastError() const { return error_; }
    const std::string& warnings() const { return warnings_; }
    const WorldStats& stats() const { return stats_; }
    const std::string& path() const { return options_.path; }
    float iso() const { return options_.iso; }
    // Counts reload() calls that made a new world (for scripts waiting on a reload).
    uint64_t generation() const { return generation_; }

    const std::vector<Parameter>& parameters() const { return parameters_; }
    // Sets a parameter by name (Parameter::name) and reloads. UserError for an
    // unknown name or a value outside the parameter's range; false when the reload failed.
    bool setParameter(const std::string& name, double value);
    // Drops every slider override and reloads.
    bool resetParameters();

    // Applies the brush to the world (re-meshing only the chunks it can change) and records it.
    EditStats edit(const Brush& brush);
    bool undo(); // false when there is nothing to undo
    bool redo();
    const std::vector<Brush>& edits() const { return edits_; }
    size_t redoCount() const { return redo_.size(); }
    // Writes the edits as `voxc run --edits` reads them (temp file, then renamed).
    void saveEdits(const std::filesystem::path& path) const;

private:
    struct Loaded;
    class Refiner;
    // Compiles and runs a solved (or previewed) program, replays the edits and makes it the world.
    void show(Program program, WorldStats stats);
    // `next`: the solve keys of the full solve this reload submits (none when it submits none).
    void supersedeRefine(const std::vector<std::string>& next);
    std::string textWithOverrides(const std::string& text, const ast::File& file) const;
    void rebuildWorld();
    // Copies the world's grid aside as the base before its first edit (the base of an unedited world is its grid).
    void keepBase();
    void listParameters(const ast::File& file);

    VulkanContext& context_;
    SessionOptions options_;
    std::map<std::string, double> constOverrides_;
    std::map<std::string, double> keyOverrides_; // a key's name (Parameter::name) -> value
    std::optional<uint32_t> seedOverride_;
    std::vector<Parameter> parameters_;
    std::vector<Brush> edits_, redo_;
    std::unique_ptr<Loaded> loaded_;
    std::string error_, warnings_;
    WorldStats stats_;
    uint64_t generation_ = 0;
    // What the file looked like when last read, for fileChanged().
    std::filesystem::file_time_type loadedTime_{};
    std::string loadedText_;
    bool readingEdits_ = false;
    uint64_t ticket_ = 0;     // counts the worlds reload() made: a refine of an older one is dropped
    bool refining_ = false;
    std::unique_ptr<Refiner> refiner_; // started by the first preview
};

// The value a float slider standing at `shown` gives its parameter: the shortest decimal that reads
// back as `shown` (what the panel shows and a file would say: 2.7f gives 2.7, not the float's
// 2.700000047683716), so a file that then says the value checks to the same numbers, and its
// curves and terrain blocks to the same solve keys: it reads the slider's solves from the cache.
double sliderValue(float shown);

// The edits as the JSON array `voxc run --edits` reads (docs/cli.md, "Edits files"): floats are
// written in their shortest exact form, so a replay gives the same bits; an add's material by name.
std::string formatEdits(const std::vector<Brush>& edits, const std::vector<Material>& materials);

} // namespace voxc::viewer
