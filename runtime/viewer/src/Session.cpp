#include "voxc/viewer/Session.h"

#include "voxc/check/Check.h"
#include "voxc/check/FeatureOverrides.h"
#include "voxc/check/KeyRanges.h"
#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/core/Stopped.h"
#include "voxc/core/Suggest.h"
#include "voxc/generators/dey/Generators.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Solve.h"
#include "voxc/syntax/Parser.h"
#include "voxc/vulkan/Executor.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <stop_token>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <thread>
#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <functional>
#include <map>

namespace voxc::viewer {

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// A value written as a plain number (or its negation): the only kind a slider can stand in for;
// a value computed from other constants follows them instead.
std::optional<double> literalNumber(const ast::Expr* expr) {
    if (expr == nullptr) return std::nullopt;
    if (expr->kind == ast::Expr::Kind::Number) return expr->number;
    if (expr->kind == ast::Expr::Kind::Negate && expr->lhs && expr->lhs->kind == ast::Expr::Kind::Number)
        return -expr->lhs->number;
    return std::nullopt;
}

// The slider: the whole range when it is short, else a part of it around the value (priority
// spans all of int32).
void setSliderSpan(Parameter& p) {
    p.sliderMin = p.min;
    p.sliderMax = p.max;
    constexpr double kLongest = 1000.0;
    if (p.max - p.min <= kLongest) return;
    const double reach = std::max(10.0, 2.0 * std::abs(p.value));
    p.sliderMin = std::max(p.min, std::min(0.0, p.value - reach));
    p.sliderMax = std::min(p.max, std::max(p.value + reach, p.sliderMin + 10.0));
}

// The range a key gives a constant written as its value, for every key with a declared range.
struct ConstantUse {
    double min, max;
    bool integer;
};

void collectConstantUses(const ast::Block& block, std::string_view blockKind,
                         const std::function<std::optional<KeyRange>(std::string_view, std::string_view)>& rangeOf,
                         std::map<std::string, ConstantUse>& uses) {
    for (const ast::Assignment& a : block.assignments) {
        const ast::Expr* value = a.value.scalar.get();
        if (value == nullptr || value->kind != ast::Expr::Kind::Name) continue;
        const std::optional<KeyRange> range = rangeOf(blockKind, a.key);
        if (!range) continue;
        auto [it, fresh] = uses.try_emplace(value->name, ConstantUse{range->min, range->max, range->integer});
        if (!fresh) {
            it->second.min = std::max(it->second.min, range->min);
            it->second.max = std::min(it->second.max, range->max);
            it->second.integer = it->second.integer || range->integer;
        }
    }
    for (const ast::Block& inner : block.blocks) collectConstantUses(inner, inner.kind, rangeOf, uses);
}

// A constant's range: those of the keys it is the value of; without one, 0 to twice the file's
// value (-1..1 for 0), integers when the file wrote an integer.
Parameter constantParameter(const std::string& name, double written, const std::optional<ConstantUse>& use) {
    Parameter p{Parameter::Kind::Constant, name, written, std::min(0.0, 2 * written), std::max(0.0, 2 * written)};
    if (written == 0.0) p.min = -1.0, p.max = 1.0;
    p.integer = written == std::floor(written) && std::abs(written) >= 1.0;
    if (use && use->min <= use->max) {
        p.min = use->min;
        p.max = use->max;
        p.integer = use->integer;
    }
    setSliderSpan(p);
    return p;
}

// Sliders for the number keys of curves, terrain and lsystem blocks and of the blocks nested in them
// (voxc/check/KeyRanges.h's blockKeys), named as findKeyTarget reads them: a nested block by its
// label, by its kind when it is the only unlabelled one of that kind, else as KIND[I].
void addBlockKeys(const ast::File& file, const ast::Block& block, const std::string& name,
                  const std::map<std::string, double>& overrides, std::vector<Parameter>& parameters) {
    for (const BlockKey& k : blockKeys(block.kind)) {
        const ast::Assignment* a = findAssignment(block, k.key);
        const std::optional<double> written = a ? literalNumber(a->value.scalar.get()) : k.range.absent;
        if (!written) continue;
        Parameter p{Parameter::Kind::BlockKey, fmt::format("{}.{}", name, k.key), *written, k.range.min, k.range.max,
                    k.range.integer};
        // Only a name that leads back to this block (a name two blocks share is offered for neither).
        const std::optional<KeyTarget> target = findKeyTarget(file, p.name);
        if (!target || target->block != &block) continue;
        if (auto it = overrides.find(p.name); it != overrides.end()) p.value = it->second, p.overridden = true;
        setSliderSpan(p);
        parameters.push_back(p);
    }
    std::map<std::string, size_t> seen, unlabelled;
    for (const ast::Block& member : block.blocks)
        if (!member.label) ++unlabelled[member.kind];
    for (const ast::Block& member : block.blocks) {
        const size_t index = seen[member.kind]++;
        const std::string segment = member.label                   ? *member.label
                                    : unlabelled[member.kind] == 1 ? member.kind
                                                                   : fmt::format("{}[{}]", member.kind, index);
        addBlockKeys(file, member, fmt::format("{}.{}", name, segment), overrides, parameters);
    }
}

} // namespace

struct Session::Loaded {
    Program program;
    // The grid as generated, before the edits: apart from the world's grid only while the world
    // has edits (a world without any holds it, uncopied).
    std::optional<ChunkedGrid> base;
    std::optional<EditableWorld> world;
};

Session::Session(VulkanContext& context, SessionOptions options) : context_(context), options_(std::move(options)) {
    seedOverride_ = options_.seed;
    reload();
}

Session::~Session() = default;

bool Session::hasWorld() const { return loaded_ && loaded_->world; }
const EditableWorld& Session::world() const { return *loaded_->world; }
const Program& Session::program() const { return loaded_->program; }

bool Session::fileChanged() const {
    std::error_code error;
    const auto time = std::filesystem::last_write_time(options_.path, error);
    if (error) return false; // mid-save (renamed away): look again on the next poll
    const auto size = std::filesystem::file_size(options_.path, error);
    return !error && (time != loadedTime_ || size != loadedText_.size());
}

std::string Session::textWithOverrides(const std::string& text, const ast::File& file) const {
    return overrideFeatureKeys(text, file, keyOverrides_);
}

void Session::listParameters(const ast::File& file) {
    std::vector<Parameter> parameters;
    Parameter seed{Parameter::Kind::Seed, "seed", double(loaded_->program.world.seed), 0.0, 1000.0, true,
                   seedOverride_.has_value()};
    seed.max = std::max(seed.max, seed.value);
    setSliderSpan(seed);
    parameters.push_back(seed);
    // The declared range of a key a constant is the value of: a grammar's, a rule's or a feature's.
    const auto rangeOf = [&](std::string_view blockKind, std::string_view key) -> std::optional<KeyRange> {
        if (std::optional<KeyRange> range = grammarKeyRange(blockKind, key)) return range;
        if (std::optional<KeyRange> range = blockKeyRange(blockKind, key)) return range;
        if (const dey::GeneratorInfo* info = dey::findGenerator(blockKind))
            for (const dey::GeneratorKey& k : info->keys)
                if (k.name == key && k.type != dey::GeneratorKeyType::Vec3)
                    return KeyRange{k.min, k.max, k.type == dey::GeneratorKeyType::Integer};
        return std::nullopt;
    };
    std::map<std::string, ConstantUse> uses;
    for (const ast::Block& block : file.blocks) collectConstantUses(block, block.kind, rangeOf, uses);
    for (const ast::FeatureDecl& decl : file.features) collectConstantUses(decl.body, decl.body.kind, rangeOf, uses);
    for (const ast::ConstDecl& decl : file.constants) {
        const std::optional<double> written = literalNumber(decl.value.get());
        if (!written) continue;
        const auto use = uses.find(decl.name);
        Parameter p = constantParameter(decl.name, *written,
                                        use == uses.end() ? std::nullopt : std::optional(use->second));
        if (auto it = constOverrides_.find(decl.name); it != constOverrides_.end()) p.value = it->second, p.overridden = true;
        parameters.push_back(p);
    }
    for (const ast::FeatureDecl& decl : file.features) {
        const dey::GeneratorInfo* info = dey::findGenerator(decl.body.kind);
        if (info == nullptr) continue;
        for (const dey::GeneratorKey& key : info->keys) {
            if (key.type == dey::GeneratorKeyType::Vec3 || key.override) continue;
            const ast::Assignment* a = findAssignment(decl.body, key.name);
            const std::optional<double> written = a ? literalNumber(a->value.scalar.get()) : std::optional(key.value[0]);
            if (!written) continue;
            Parameter p{Parameter::Kind::FeatureKey, fmt::format("{}.{}", decl.name, key.name), *written, key.min, key.max,
                        key.type == dey::GeneratorKeyType::Integer};
            if (auto it = keyOverrides_.find(p.name); it != keyOverrides_.end()) p.value = it->second, p.overridden = true;
            setSliderSpan(p);
            parameters.push_back(p);
        }
    }
    // Grammar and rule keys: written as a plain number, or absent (the language's default).
    const auto addKey = [&](const ast::Block& block, std::string_view blockKind, std::string_view key, double fallback,
                            const std::string& name) {
        const std::optional<KeyRange> range = grammarKeyRange(blockKind, key);
        const ast::Assignment* a = findAssignment(block, key);
        const std::optional<double> written = a ? literalNumber(a->value.scalar.get()) : std::optional(fallback);
        if (!range || !written) return;
        Parameter p{Parameter::Kind::GrammarKey, name, *written, range->min, range->max, range->integer};
        if (auto it = keyOverrides_.find(p.name); it != keyOverrides_.end()) p.value = it->second, p.overridden = true;
        setSliderSpan(p);
        parameters.push_back(p);
    };
    for (const ast::Block& grammar : file.blocks) {
        if (grammar.kind != "grammar" || !grammar.label) continue;
        addKey(grammar, "grammar", "iterations", 1.0, fmt::format("{}.iterations", *grammar.label));
        for (const ast::Block& rule : grammar.blocks) {
            if (rule.kind != "rule" || !rule.label) continue;
            const std::string prefix = fmt::format("{}.{}.", *grammar.label, *rule.label);
            addKey(rule, "rule", "probability", 1.0, prefix + "probability");
            addKey(rule, "rule", "priority", 0.0, prefix + "priority");
            addKey(rule, "rule", "weight", 1.0, prefix + "weight");
        }
    }
    for (const ast::Block& block : file.blocks)
        if (block.label && !blockKeys(block.kind).empty())
            addBlockKeys(file, block, *block.label, keyOverrides_, parameters);
    parameters_ = std::move(parameters);
}

// Solves programs in the background, one at a time, newest first: a request made while one is
// solving replaces any request still waiting, and only the newest ticket's outcome is kept, so a
// newer slider move supersedes an older refine; a solve already running is asked to stop, and
// stops at its next V-cycle, pass or batch of erosion steps, leaving nothing in the solve cache,
// so the newer preview and solve have both cores. Unless the newer request solves the same blocks
// (the same solve keys: a file saved with the values the sliders had): then the running solve
// goes on, its tables reach the solve cache, and the newer request reads them there.
class Session::Refiner {
    static constexpr int kRefineNice = 10;

public:
    struct Outcome {
        uint64_t ticket = 0;
        std::optional<Program> program; // solved; nothing when the solve failed
        std::string error;
        double ms = 0.0;
    };

    explicit Refiner(std::function<void()> starting) : starting_(std::move(starting)), thread_([this] { work(); }) {}
    ~Refiner() {
        {
            const std::lock_guard lock(mutex_);
            stop_ = true;
        }
        wake_.notify_one();
        thread_.join(); // waits for a solve in progress: the thread reads nothing the session owns
    }

    void submit(uint64_t ticket, Program program, std::vector<std::string> keys) {
        {
            const std::lock_guard lock(mutex_);
            latest_ = ticket;
            pending_.emplace(Request{ticket, std::move(program), std::move(keys)});
            done_.reset();
        }
        wake_.notify_one();
    }
    // Drops what is waiting and whatever the running solve will give: `ticket` is newer. `next`:
    // the solve keys of the request `ticket` will submit (none when it submits none).
    void supersede(uint64_t ticket, const std::vector<std::string>& next) {
        const std::lock_guard lock(mutex_);
        latest_ = ticket;
        pending_.reset();
        done_.reset();
        if (running_ && (next.empty() || next != runningKeys_)) running_->request_stop();
    }
    uint64_t stopped() const {
        const std::lock_guard lock(mutex_);
        return stopped_;
    }
    std::optional<Outcome> take() {
        const std::lock_guard lock(mutex_);
        std::optional<Outcome> out = std::move(done_);
        done_.reset();
        return out;
    }

private:
    void work() {
        // Below the window's thread (Linux nice values are per thread and inherited by the threads
        // the solve starts), so a superseded solve still running slows a new preview less.
        setpriority(PRIO_PROCESS, pid_t(syscall(SYS_gettid)), kRefineNice);
        std::unique_lock lock(mutex_);
        while (true) {
            wake_.wait(lock, [&] { return stop_ || pending_.has_value(); });
            if (stop_) return;
            auto [ticket, program, keys] = std::move(*pending_);
            pending_.reset();
            runningKeys_ = std::move(keys);
            running_.emplace();
            const std::stop_token stop = running_->get_token();
            lock.unlock();
            Outcome outcome;
            outcome.ticket = ticket;
            const auto start = std::chrono::steady_clock::now();
            bool stopped = false;
            try {
                if (starting_) starting_();
                // What compileProgram would solve: the same tables.
                stages::solveBlocks(program, stages::SolveOptions{.stop = stop});
                outcome.program = std::move(program);
            } catch (const Stopped&) {
                stopped = true;
            } catch (const std::exception& e) {
                outcome.error = e.what();
            }
            outcome.ms = millisecondsSince(start);
            lock.lock();
            running_.reset();
            stopped_ += stopped;
            if (ticket == latest_ && !stopped) done_ = std::move(outcome);
        }
    }

    const std::function<void()> starting_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<std::stop_source> running_; // the solve in progress's
    std::vector<std::string> runningKeys_;    // and its blocks' solve keys
    uint64_t stopped_ = 0;
    bool stop_ = false;
    uint64_t latest_ = 0;
    struct Request {
        uint64_t ticket;
        Program program;
        std::vector<std::string> keys;
    };
    std::optional<Request> pending_;
    std::optional<Outcome> done_;
    std::thread thread_; // last: started once the rest is built
};

bool Session::reload() {
    Diagnostics readErrors;
    std::optional<SourceFile> source = loadSourceFile(options_.path, readErrors);
    std::error_code ignored;
    loadedTime_ = std::filesystem::last_write_time(options_.path, ignored);
    if (!source) {
        loadedText_.clear();
        error_ = renderAll(readErrors.all(), SourceFile(options_.path, ""));
        return false;
    }
    loadedText_ = source->text();
    // The file as written, for the slider splices and the parameter list; the checker reports its errors.
    Diagnostics parseErrors;
    const ast::File file = parse(*source, parseErrors);
    try {
        auto start = std::chrono::steady_clock::now();
        CheckOptions checkOptions;
        checkOptions.constOverrides.insert(constOverrides_.begin(), constOverrides_.end());
        checkOptions.seed = seedOverride_;
        CheckResult checked = checkSource(SourceFile(options_.path, textWithOverrides(loadedText_, file)), checkOptions);
        if (checked.hasErrors() || !checked.program) {
            error_ = checked.rendered();
            return false;
        }
        warnings_ = checked.rendered();
        WorldStats stats;
        stats.checkMs = millisecondsSince(start);
        Program program = std::move(*checked.program);
        if (options_.chunk) {
            const int32_t c = *options_.chunk;
            if (c < 8 || c > 64 || (c & (c - 1)) != 0)
                throw UserError(fmt::format("--chunk {}: the chunk size must be a power of two from 8 to 64", c));
            program.world.chunkSize = c;
        }
        start = std::chrono::steady_clock::now();
        std::optional<Program> preview;
        if (needsPreview(program, options_.preview)) {
            try {
                preview = previewProgram(program, options_.preview);
            } catch (const std::exception&) {
                // A coarse box the solve refuses (too thin, say): no preview, the full solve below.
            }
        }
        if (preview) {
            stats.preview = true;
            stats.solveMs = millisecondsSince(start);
            std::vector<std::string> keys = solveKeys(program);
            supersedeRefine(keys);
            show(std::move(*preview), stats);
            if (!refiner_) refiner_ = std::make_unique<Refiner>(options_.fullSolveStarting);
            refiner_->submit(ticket_, std::move(program), std::move(keys));
            refining_ = true;
        } else {
            stages::solveBlocks(program); // on the host, through the solve cache, as compileProgram would
            stats.solveMs = millisecondsSince(start);
            supersedeRefine({});
            show(std::move(program), stats);
        }
    } catch (const UserError& e) {
        if (readingEdits_) throw; // the edits file is not watched: waiting for a save cannot mend it
        error_ = fmt::format("{}: {}\n", options_.path, e.what());
        return false;
    }
    listParameters(file);
    error_.clear();
    return true;
}

// A new world replaces the one on screen: a refine of the older one must not replace it in turn.
// (A reload that fails keeps the last world and lets its refine finish.)
void Session::supersedeRefine(const std::vector<std::string>& next) {
    ++ticket_;
    refining_ = false;
    if (refiner_) refiner_->supersede(ticket_, next);
}

void Session::show(Program program, WorldStats stats) {
    auto start = std::chrono::steady_clock::now();
    // Constants are folded into the kernels' text, so a changed constant is a changed kernel;
    // unchanged kernels come from the SPIR-V cache (docs/architecture.md, "voxc_viewer").
    const KernelPackage package = compileProgram(program, {});
    stats.compileMs = millisecondsSince(start);
    start = std::chrono::steady_clock::now();
    VulkanExecutor executor(context_, package);
    RunResult result = executor.run();
    stats.runMs = millisecondsSince(start);
    stats.dispatches = result.dispatches;
    const ChunkLayout& layout = result.grid.layout();
    stats.size = layout.gridSize;
    stats.chunkSize = layout.chunkSize;
    stats.chunkCount = layout.chunkCount;
    if (options_.readEdits) {
        readingEdits_ = true;
        edits_ = options_.readEdits(program);
        readingEdits_ = false;
        options_.readEdits = nullptr;
    }
    loaded_ = std::make_unique<Loaded>(Loaded{std::move(program), std::move(result.grid), std::nullopt});
    start = std::chrono::steady_clock::now();
    rebuildWorld();
    stats.meshMs = millisecondsSince(start);
    stats.triangles = loaded_->world->mesh().triangles.size() / 3;
    stats_ = stats;
    ++generation_;
}

uint64_t Session::stoppedSolves() const { return refiner_ ? refiner_->stopped() : 0; }

std::optional<bool> Session::poll() {
    if (!refining_ || !refiner_) return std::nullopt;
    std::optional<Refiner::Outcome> outcome = refiner_->take();
    if (!outcome || outcome->ticket != ticket_) return std::nullopt;
    refining_ = false;
    if (!outcome->program) {
        error_ = fmt::format("{}: {}\n", options_.path, outcome->error);
        return false;
    }
    WorldStats stats = stats_;
    stats.preview = false;
    stats.solveMs = outcome->ms;
    try {
        show(std::move(*outcome->program), stats);
    } catch (const UserError& e) {
        error_ = fmt::format("{}: {}\n", options_.path, e.what());
        return false;
    }
    error_.clear();
    return true;
}

void Session::rebuildWorld() {
    ChunkedGrid grid = edits_.empty() ? std::move(*loaded_->base) : *loaded_->base;
    if (edits_.empty()) loaded_->base.reset();
    for (const Brush& brush : edits_) applyBrush(grid, brush);
    loaded_->world.emplace(std::move(grid), MeshOptions{.iso = options_.iso});
}

void Session::keepBase() {
    if (!loaded_->base) loaded_->base = loaded_->world->grid();
}

bool Session::setParameter(const std::string& name, double value) {
    const auto it = std::find_if(parameters_.begin(), parameters_.end(), [&](const Parameter& p) { return p.name == name; });
    if (it == parameters_.end()) {
        std::vector<std::string_view> names;
        std::string list;
        for (const Parameter& p : parameters_) {
            names.push_back(p.name);
            list += fmt::format("{}{}", list.empty() ? "" : ", ", p.name);
        }
        throw UserError(fmt::format("no parameter named '{}' (the parameters are: {}){}", name, list,
                                    didYouMean(name, names)));
    }
    if (!(value >= it->min && value <= it->max) && it->kind != Parameter::Kind::Seed)
        throw UserError(fmt::format("{} = {}: outside its range [{}, {}]", name, value, it->min, it->max));
    if (it->integer) value = std::round(value);
    switch (it->kind) {
    case Parameter::Kind::Seed:
        if (!(value >= 0 && value <= double(UINT32_MAX))) throw UserError(fmt::format("seed {}: expected 0 to {}", value, UINT32_MAX));
        seedOverride_ = uint32_t(value);
        break;
    case Parameter::Kind::Constant: constOverrides_[name] = value; break;
    case Parameter::Kind::FeatureKey:
    case Parameter::Kind::GrammarKey:
    case Parameter::Kind::BlockKey: keyOverrides_[name] = value; break;
    }
    return reload();
}

bool Session::resetParameters() {
    constOverrides_.clear();
    keyOverrides_.clear();
    seedOverride_ = options_.seed;
    return reload();
}

EditStats Session::edit(const Brush& brush) {
    VOXC_ASSERT(hasWorld());
    const auto start = std::chrono::steady_clock::now();
    keepBase();
    const EditResult result = loaded_->world->edit(brush);
    EditStats stats{result.chunksRemeshed.size(), 0, millisecondsSince(start)};
    if (result.changed) {
        const glm::ivec3 extent = result.changed->last - result.changed->first + 1;
        stats.voxelsInBox = size_t(extent.x) * extent.y * extent.z;
        edits_.push_back(brush); // only edits that changed something, so every undo shows
        redo_.clear();
    }
    return stats;
}

bool Session::undo() {
    if (edits_.empty() || !hasWorld()) return false;
    redo_.push_back(edits_.back());
    edits_.pop_back();
    // A brush cannot be inverted (min and max forget), so the world is replayed from the base.
    rebuildWorld();
    return true;
}

bool Session::redo() {
    if (redo_.empty() || !hasWorld()) return false;
    const Brush brush = redo_.back();
    redo_.pop_back();
    keepBase();
    loaded_->world->edit(brush);
    edits_.push_back(brush);
    return true;
}

void Session::saveEdits(const std::filesystem::path& path) const {
    writeFileAtomically(path.string(), formatEdits(edits_, loaded_ ? loaded_->program.materials : std::vector<Material>{}));
}

double sliderValue(float shown) { return std::strtod(fmt::format("{}", shown).c_str(), nullptr); }

std::string formatEdits(const std::vector<Brush>& edits, const std::vector<Material>& materials) {
    std::string out = "[";
    for (size_t i = 0; i < edits.size(); ++i) {
        const Brush& b = edits[i];
        out += fmt::format("{}\n  {{\"op\": \"{}\", \"center\": [{}, {}, {}], \"radius\": {}, \"softness\": {}", i ? "," : "",
                           b.op == Brush::Op::Carve ? "carve" : "add", b.center.x, b.center.y, b.center.z, b.radius,
                           b.softness);
        if (b.op == Brush::Op::Add && b.material != 0)
            for (const Material& m : materials)
                if (m.id == b.material) out += fmt::format(", \"material\": \"{}\"", m.name);
        out += "}";
    }
    out += edits.empty() ? "]\n" : "\n]\n";
    return out;
}

} // namespace voxc::viewer
