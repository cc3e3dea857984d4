// `lsystem NAME { ... }` blocks (docs/language.md, "L-systems"): keys and nested blocks are read
// into the generators library's lsystem::Definition, which then checks itself
// (lsystem::checkDefinition, checkString, checkExpansionLimits); this file only turns each of
// its problems into a diagnostic at the right place, in the .vox file or the imported rule file.
#include "LsystemOrigins.h"
#include "Sections.h"
#include "Suggest.h"
#include "Values.h"

#include "voxc/core/InputFile.h"
#include "voxc/generators/lsystem/Evolve.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/generators/lsystem/RuleFile.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <limits>
#include <set>

namespace voxc::check {

namespace {

using namespace lsystem;

constexpr std::string_view kKeys[] = {"turtle",    "selection",  "axiom",       "expansions", "seed",
                                      "angle",     "step",       "angle_delta", "step_delta", "angle_deviation",
                                      "pitch_limit", "start",    "yaw",         "pitch",      "rules"};
constexpr std::string_view kNestedBlocks[] = {"production", "macro",   "target",      "balanced",
                                               "constrain",  "connect", "random_rules"};
constexpr std::string_view kTypes[] = {"none", "tunnel", "room"};
// Alternatives one `random_rules` block may add.
constexpr int64_t kMaxRandomAlternatives = 64;
// Numbers are range-checked by lsystem::checkDefinition; here they only have to be finite.
constexpr double kAnyNumber = std::numeric_limits<double>::max();

// The text of `key = "..."`, or E0010 when the value is not a string.
std::optional<std::string> readString(Context& context, const ast::Assignment& a) {
    const ast::Expr* expr = a.value.isList() ? nullptr : a.value.scalar.get();
    if (expr && expr->kind == ast::Expr::Kind::String) return expr->name;
    context.diagnostics.error("E0010", a.value.loc, fmt::format("'{}' expects a string in double quotes", a.key));
    return std::nullopt;
}

// One word of `choices` (`turtle = abop;`): its index, or E0011 naming the choices.
std::optional<size_t> readWord(Context& context, const ast::Assignment& a, std::span<const std::string_view> choices) {
    const ast::Expr* expr = a.value.isList() ? nullptr : a.value.scalar.get();
    if (expr && expr->kind == ast::Expr::Kind::Name)
        for (size_t i = 0; i < choices.size(); ++i)
            if (expr->name == choices[i]) return i;
    const std::string found = expr && expr->kind == ast::Expr::Kind::Name ? expr->name : std::string();
    context.diagnostics.error("E0011", a.value.loc,
                              fmt::format("'{}' must be one of {}{}", a.key, fmt::join(choices, ", "),
                                          found.empty() ? std::string() : didYouMean(found, choices)));
    return std::nullopt;
}

glm::dvec3 toVec(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

class LsystemReader {
public:
    LsystemReader(Context& context, const ast::Block& block, const std::string& sourcePath)
        : context_(context), block_(block), sourcePath_(sourcePath),
          where_(fmt::format("lsystem '{}'", block.label.value_or(""))) {
        origins_.fallback = {block.labelLoc, nullptr};
    }

    std::optional<CheckedLsystem> read() {
        const int errorsBefore = context_.diagnostics.errorCount();
        readKeys();
        readNestedBlocks();
        if (context_.diagnostics.errorCount() != errorsBefore) return std::nullopt;
        for (const DefinitionProblem& problem : checkDefinition(definition_)) origins_.report(context_, definition_, problem);
        if (context_.diagnostics.errorCount() != errorsBefore) return std::nullopt;
        try {
            checkExpansionLimits(definition_);
        } catch (const LimitError& e) {
            context_.diagnostics.error("E0012", block_.labelLoc, fmt::format("{}: {}", where_, e.what()));
            return std::nullopt;
        }
        return CheckedLsystem{*block_.label, block_.labelLoc, definition_, connect_, rulesPath_, rulesName_, rulesText_,
                              block_.loc, block_.end};
    }

private:
    void readKeys() {
        BlockKeys keys(context_, block_, where_, kKeys);
        TurtleParams& p = definition_.params;
        constexpr std::string_view turtles[] = {"thesis", "abop"};
        constexpr std::string_view selections[] = {"weighted", "thesis"};
        if (const auto* a = keys.find("turtle"))
            if (auto i = readWord(context_, *a, turtles)) definition_.turtle = *i == 0 ? TurtleKind::Thesis : TurtleKind::Abop;
        if (const auto* a = keys.find("selection"))
            if (auto i = readWord(context_, *a, selections))
                definition_.selection = *i == 0 ? Selection::Weighted : Selection::Thesis;
        if (const auto* a = keys.find("axiom")) {
            if (auto text = readString(context_, *a)) {
                definition_.axiom = *text;
                origins_.strings["axiom"] = {textStart(a->value.loc), nullptr};
            }
        }
        if (const auto* a = keys.find("expansions")) {
            if (auto v = readInteger(context_, *a, 0, std::numeric_limits<uint32_t>::max()))
                definition_.expansions = uint32_t(*v);
            origins_.places["expansions"] = {a->value.loc, nullptr};
        }
        if (const auto* a = keys.find("seed"))
            if (auto v = readInteger(context_, *a, 0, std::numeric_limits<uint32_t>::max())) definition_.seed = uint32_t(*v);
        number(keys, "angle", p.angle);
        number(keys, "step", p.step);
        number(keys, "angle_delta", p.angleDelta);
        number(keys, "step_delta", p.stepDelta);
        number(keys, "angle_deviation", p.angleDeviation);
        number(keys, "pitch_limit", p.pitchLimit);
        number(keys, "yaw", p.yaw);
        number(keys, "pitch", p.pitch);
        vector(keys, "start", "start", p.start);
        if (const auto* a = keys.find("rules")) readRuleFile(*a);
    }

    void number(const BlockKeys& keys, std::string_view key, double& out, std::string where = {}) {
        const auto* a = keys.find(key);
        if (!a) return;
        if (auto v = readNumber(context_, *a, -kAnyNumber, kAnyNumber)) out = *v;
        origins_.places[where.empty() ? std::string(key) : where] = {a->value.loc, nullptr};
    }

    void vector(const BlockKeys& keys, std::string_view key, const std::string& where, glm::dvec3& out) {
        const auto* a = keys.find(key);
        if (!a) return;
        if (auto v = readNumberVec3(context_, *a, -kAnyNumber, kAnyNumber)) out = toVec(*v);
        origins_.places[where] = {a->value.loc, nullptr};
    }

    static SourceLoc textStart(SourceLoc quoted) { return {quoted.line, quoted.column + 1, 1}; }

    void readNestedBlocks() {
        rejectUnexpectedMembers(context_, block_, where_, {.blocks = true});
        bool sawTarget = false, sawBalanced = false, sawConstrain = false, sawConnect = false, sawRandom = false;
        const ast::Block* randomRules = nullptr;
        for (const ast::Block& nested : block_.blocks) {
            if (nested.kind == "production" || nested.kind == "macro") {
                readAlternatives(nested, nested.kind == "macro");
            } else if (nested.kind == "target" && once(nested, sawTarget)) {
                readTarget(nested);
            } else if (nested.kind == "balanced" && once(nested, sawBalanced)) {
                checkLabel(context_, nested, false);
                rejectUnexpectedMembers(context_, nested, "'balanced' block", {});
                constexpr std::string_view keys[] = {"delta"};
                BlockKeys found(context_, nested, "'balanced' block", keys);
                definition_.balanced = BalancedMode{};
                number(found, "delta", definition_.balanced->delta, "balanced.delta");
            } else if (nested.kind == "constrain" && once(nested, sawConstrain)) {
                readConstrain(nested);
            } else if (nested.kind == "connect" && once(nested, sawConnect)) {
                readConnect(nested);
            } else if (nested.kind == "random_rules" && once(nested, sawRandom)) {
                randomRules = &nested;
            } else if (std::find(std::begin(kNestedBlocks), std::end(kNestedBlocks), nested.kind) ==
                       std::end(kNestedBlocks)) {
                context_.diagnostics.error("E0008", nested.loc,
                                           fmt::format("unknown block '{}' in {}{}", nested.kind, where_,
                                                       didYouMean(nested.kind, kNestedBlocks)));
            }
        }
        // After every macro is known (the block's and the rule file's).
        if (randomRules) readRandomRules(*randomRules);
    }

    // `random_rules { symbol = "Z"; count = 1; macros = [6, 6]; bracket_chance = 0.5;
    // weights { Q = 0.5; T = -1; } }` (§III-B.1): `count` random alternatives of the production
    // of `symbol`, drawn from the block's seed, appended after its written ones. Without
    // `weights` every macro weighs 1.
    void readRandomRules(const ast::Block& nested) {
        checkLabel(context_, nested, false);
        rejectUnexpectedMembers(context_, nested, "'random_rules' block", {.blocks = true});
        constexpr std::string_view keys[] = {"symbol", "count", "macros", "bracket_chance"};
        BlockKeys found(context_, nested, "'random_rules' block", keys);
        const int errorsBefore = context_.diagnostics.errorCount();
        char symbol = 'Z';
        if (const auto* a = found.find("symbol"))
            if (auto text = readString(context_, *a)) {
                if (text->size() == 1 && *text != "[" && *text != "]")
                    symbol = (*text)[0];
                else
                    context_.diagnostics.error("E0001", a->value.loc,
                                               fmt::format("'symbol' names one symbol, as in \"Z\", not \"{}\"", *text));
            }
        int64_t count = 1;
        if (const auto* a = found.find("count"))
            if (auto v = readInteger(context_, *a, 1, kMaxRandomAlternatives)) count = *v;
        RandomRuleParams params;
        params.selection = definition_.selection;
        if (const auto* a = found.find("macros"))
            if (auto v = readRange(context_, *a)) {
                // Whole counts; their range (2 <= min <= max <= 64) is randomProduction's check.
                if ((*v)[0] != std::floor((*v)[0]) || (*v)[1] != std::floor((*v)[1]) || (*v)[0] < 0 || (*v)[1] > 1e6)
                    context_.diagnostics.error("E0007", a->value.loc, "'macros' is a range of whole counts [min, max]");
                else
                    params.minMacros = uint32_t((*v)[0]), params.maxMacros = uint32_t((*v)[1]);
            }
        if (const auto* a = found.find("bracket_chance"))
            if (auto v = readNumber(context_, *a, 0, 1)) params.bracketChance = *v;
        for (const auto& [macro, substitutes] : definition_.macros) params.weights[macro] = 1.0;
        for (const ast::Block& weights : nested.blocks) {
            if (weights.kind != "weights") {
                context_.diagnostics.error("E0008", weights.loc,
                                           fmt::format("unknown block '{}' in 'random_rules'; it takes one "
                                                       "'weights {{ Q = 0.5; T = -1; }}' block",
                                                       weights.kind));
                continue;
            }
            checkLabel(context_, weights, false);
            rejectUnexpectedMembers(context_, weights, "'weights' block", {});
            for (const ast::Assignment& a : weights.assignments) {
                if (a.key.size() != 1 || !definition_.macros.contains(a.key[0])) {
                    context_.diagnostics.error("E0002", a.loc,
                                               fmt::format("'{}' is not a macro of {}; weights name macros", a.key,
                                                           where_));
                    continue;
                }
                if (auto v = readNumber(context_, a, -kAnyNumber, kAnyNumber)) params.weights[a.key[0]] = *v;
            }
        }
        if (context_.diagnostics.errorCount() != errorsBefore) return;
        if (params.weights.empty()) {
            context_.diagnostics.error("E0009", nested.loc,
                                       fmt::format("'random_rules' needs macros to choose from; {} declares none",
                                                   where_));
            return;
        }
        std::vector<Alternative>& alternatives = definition_.productions[symbol];
        try {
            for (int64_t k = 0; k < count; ++k)
                alternatives.emplace_back(randomProduction(params, definition_.seed, uint32_t(k)), SymbolType::None, 1.0,
                                          nested.loc);
        } catch (const UserError& e) {
            context_.diagnostics.error("E0007", nested.loc, e.what());
        }
    }

    // False (and E0003) for the second block of a kind that may appear once.
    bool once(const ast::Block& nested, bool& seen) {
        if (seen) {
            context_.diagnostics.error("E0003", nested.loc, fmt::format("a second '{}' block in {}", nested.kind, where_));
            return false;
        }
        seen = true;
        return true;
    }

    // `production Z { "FZ[RFZ]" 1; }` or `macro C { "FLFLFZ" tunnel 1; }`.
    void readAlternatives(const ast::Block& nested, bool macro) {
        const std::string what = macro ? "macro" : "production";
        if (!checkLabel(context_, nested, true)) return;
        if (nested.label->size() != 1) {
            context_.diagnostics.error("E0001", nested.labelLoc,
                                       fmt::format("a {} names one symbol, as in '{} {}', not '{}'", what, what,
                                                   macro ? "C" : "Z", *nested.label));
            return;
        }
        const char symbol = (*nested.label)[0];
        auto& table = macro ? definition_.macros : definition_.productions;
        if (!(macro ? declaredMacros_ : declaredProductions_).insert(symbol).second) {
            context_.diagnostics.error("E0003", nested.labelLoc,
                                       fmt::format("a second {} block for '{}'; list every alternative in one", what,
                                                   symbol));
            return;
        }
        const std::string where = fmt::format("{} {}", what, symbol);
        rejectUnexpectedMembers(context_, nested, fmt::format("{} '{}'", what, symbol), {.strings = true});
        for (const ast::Assignment& a : nested.assignments)
            context_.diagnostics.error("E0008", a.loc,
                                       fmt::format("unexpected key '{}' in {} '{}'; it lists strings as "
                                                   "'\"FZ\" tunnel 1;'",
                                                   a.key, what, symbol));
        origins_.places[where] = {nested.labelLoc, nullptr};
        std::vector<Alternative>& alternatives = table[symbol];
        for (const ast::WeightedString& entry : nested.strings) {
            Alternative alternative(entry.text, SymbolType::None, 1.0, textStart(entry.loc));
            if (entry.type) {
                if (auto type = parseSymbolType(*entry.type))
                    alternative.type = *type;
                else if (context_.constants.isDeclared(*entry.type))
                    // `"FZ" W;` reads W as the type: the grammar puts an optional type first.
                    context_.diagnostics.error("E0002", entry.typeLoc,
                                               fmt::format("'{0}' is a constant, not a type; a weight given by a "
                                                           "constant follows a type, as in '\"{1}\" none {0};'",
                                                           *entry.type, entry.text));
                else
                    context_.diagnostics.error("E0002", entry.typeLoc,
                                               fmt::format("unknown type '{}': expected none, tunnel or room{}",
                                                           *entry.type, didYouMean(*entry.type, kTypes)));
            }
            if (entry.weight)
                if (auto weight = context_.constants.evaluate(*entry.weight, "the weight of an alternative")) alternative.weight = *weight;
            const std::string key = fmt::format("{} #{}", where, alternatives.size() + 1);
            origins_.strings[key] = {alternative.loc, nullptr};
            origins_.places[key] = {entry.weight ? entry.weight->loc : entry.loc, nullptr};
            alternatives.push_back(std::move(alternative));
        }
    }

    void readTarget(const ast::Block& nested) {
        checkLabel(context_, nested, false);
        rejectUnexpectedMembers(context_, nested, "'target' block", {});
        constexpr std::string_view keys[] = {"point", "strength"};
        BlockKeys found(context_, nested, "'target' block", keys);
        definition_.target = TargetMode{};
        if (found.require("point")) vector(found, "point", "target.point", definition_.target->point);
        number(found, "strength", definition_.target->strength, "target.strength");
    }

    // A box (`min`, `max`) or a sphere (`center`, `radius`).
    void readConstrain(const ast::Block& nested) {
        checkLabel(context_, nested, false);
        rejectUnexpectedMembers(context_, nested, "'constrain' block", {});
        constexpr std::string_view keys[] = {"min", "max", "center", "radius"};
        BlockKeys found(context_, nested, "'constrain' block", keys);
        ConstrainedMode mode;
        const bool box = found.find("min") || found.find("max");
        const bool sphere = found.find("center") || found.find("radius");
        if (box == sphere) {
            context_.diagnostics.error("E0009", nested.loc,
                                       "'constrain' needs a box ('min' and 'max') or a sphere ('center' and "
                                       "'radius'), not both");
            return;
        }
        if (box) {
            mode.shape = ConstrainedMode::Shape::Box;
            if (found.require("min") && found.require("max")) {
                vector(found, "min", "constrain.min", mode.min);
                vector(found, "max", "constrain.max", mode.max);
            }
        } else {
            mode.shape = ConstrainedMode::Shape::Sphere;
            if (found.require("center") && found.require("radius")) {
                vector(found, "center", "constrain.center", mode.center);
                number(found, "radius", mode.radius, "constrain.radius");
            }
        }
        definition_.constrained = mode;
    }

    void readConnect(const ast::Block& nested) {
        checkLabel(context_, nested, false);
        rejectUnexpectedMembers(context_, nested, "'connect' block", {});
        constexpr std::string_view keys[] = {"chance", "max_distance", "frequency", "amplitude", "spacing"};
        BlockKeys found(context_, nested, "'connect' block", keys);
        number(found, "chance", connect_.chance);
        number(found, "max_distance", connect_.maxDistance);
        number(found, "frequency", connect_.frequency);
        number(found, "amplitude", connect_.amplitude);
        number(found, "spacing", connect_.spacing);
        try {
            checkConnectParams(connect_);
        } catch (const UserError& e) {
            context_.diagnostics.error("E0007", nested.loc, e.what());
        }
    }

    // `rules = "caves.rules";`: the paper's Symbol;SubstituteString;Type;Weight records, read
    // relative to the .vox file; their errors are located in the rule file.
    void readRuleFile(const ast::Assignment& a) {
        auto name = readString(context_, a);
        if (!name) return;
        if (definition_.turtle != TurtleKind::Thesis) {
            context_.diagnostics.error("E0010", a.value.loc, "rule files use the thesis alphabet; remove 'turtle = abop'");
            return;
        }
        const std::string path = (std::filesystem::path(sourcePath_).parent_path() / *name).string();
        Diagnostics fileDiagnostics;
        std::optional<SourceFile> source = openRuleFile(path, fileDiagnostics);
        if (source && reportIfNotText(*source, fileDiagnostics)) source.reset();
        if (!source) {
            for (const Diagnostic& d : fileDiagnostics.take())
                context_.diagnostics.error(d.code, a.value.loc, d.message);
            return;
        }
        rulesPath_ = path;
        rulesName_ = *name;
        rulesText_ = source->text();
        auto shared = std::make_shared<const SourceFile>(std::move(*source));
        std::optional<RuleSet> rules = parseRuleFile(*shared, fileDiagnostics, definition_.limits);
        for (Diagnostic& d : fileDiagnostics.take()) {
            d.file = shared;
            context_.diagnostics.report(std::move(d));
        }
        if (!rules) return;
        merge(rules->productions, definition_.productions, "production", shared);
        merge(rules->macros, definition_.macros, "macro", shared);
    }

    // The rule file from the disk, or from CheckOptions::readRuleFile when it is set.
    std::optional<SourceFile> openRuleFile(const std::string& path, Diagnostics& diagnostics) const {
        const size_t maxBytes = size_t(context_.limits.maxSourceBytes);
        if (!context_.readRuleFile) {
            // Only a regular file: the name is the document's, and a FIFO or /dev/stdin would
            // block the check (and, under `voxc lsp`, read the protocol stream).
            InputFileRead read = readInputFile(path, maxBytes);
            if (read.bytes) return SourceFile(path, std::move(*read.bytes));
            diagnostics.error(std::string(read.code()), {}, read.message);
            return std::nullopt;
        }
        std::optional<std::string> text = context_.readRuleFile(path);
        if (!text) {
            diagnostics.error("E0100", {}, fmt::format("cannot read file '{}': no such file", path));
            return std::nullopt;
        }
        if (text->size() > maxBytes) {
            diagnostics.error("E0012", {}, fmt::format("cannot read file '{}': it is larger than the limit of {} bytes ({} MiB)",
                                                       path, maxBytes, maxBytes >> 20));
            return std::nullopt;
        }
        return SourceFile(path, std::move(*text));
    }

    // Appends the file's alternatives after the block's own (the file is read before them, so
    // the block's production and macro blocks append after the file's).
    void merge(std::map<char, std::vector<Alternative>>& from, std::map<char, std::vector<Alternative>>& to,
               std::string_view what, const std::shared_ptr<const SourceFile>& file) {
        for (auto& [symbol, alternatives] : from) {
            std::vector<Alternative>& target = to[symbol];
            for (Alternative& alternative : alternatives) {
                const std::string key = fmt::format("{} {} #{}", what, symbol, target.size() + 1);
                origins_.strings[key] = {alternative.loc, file};
                origins_.places[key] = {alternative.loc, file};
                target.push_back(std::move(alternative));
            }
        }
    }

    Context& context_;
    const ast::Block& block_;
    const std::string& sourcePath_;
    std::string where_;
    Definition definition_;
    ConnectParams connect_;
    std::string rulesPath_, rulesName_, rulesText_;
    LsystemOrigins origins_;
    std::set<char> declaredProductions_, declaredMacros_; // blocks seen (a rule file may add to the same symbols)
};

} // namespace

std::vector<CheckedLsystem> checkLsystems(Context& context, const ast::File& file, const std::string& sourcePath) {
    std::vector<CheckedLsystem> checked;
    std::map<std::string, SourceLoc> names;
    for (const ast::Block& block : file.blocks) {
        if (block.kind != "lsystem" || !checkLabel(context, block, true)) continue;
        auto [it, inserted] = names.emplace(*block.label, block.labelLoc);
        if (!inserted) {
            context.diagnostics.error("E0003", block.labelLoc,
                                      fmt::format("an lsystem named '{}' already exists", *block.label),
                                      {{it->second, "first declared here"}});
            continue;
        }
        if (auto lsystem = LsystemReader(context, block, sourcePath).read()) checked.push_back(std::move(*lsystem));
    }
    return checked;
}

} // namespace voxc::check
