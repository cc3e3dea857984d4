#pragma once
// The checker: source text -> voxc::Program, or located diagnostics saying why not.
// It reads the file (at most Limits::maxSourceBytes), parses it (syntax errors and nesting
// beyond Limits::maxNesting stop here), folds constants, validates every block and key,
// converts printed symbol/transform layouts into Program's cell order, builds the pipeline,
// checks the lsystem blocks, checks its work estimate against Limits::maxWork and finally runs the warning analyses
// (W0201-W0209).
#include "voxc/generators/lsystem/Connect.h"
#include "voxc/generators/lsystem/Definition.h"
#include "voxc/program/Program.h"
#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace voxc {

// An `lsystem NAME { ... }` block, checked: its definition can be expanded within its limits
// (docs/language.md, "L-systems"). `voxc lsystem` reads it; an lsystem_cave feature carves it.
struct CheckedLsystem {
    std::string name;
    SourceLoc loc; // the block's name
    lsystem::Definition definition;
    lsystem::ConnectParams connect;
    std::string rulesPath; // the imported rule file as opened (relative to the working directory), or empty
    // With rulesPath: the `rules` string as written (relative to the .vox's directory) and the
    // file's text, which a compiled package keeps a copy of.
    std::string rulesName, rulesText;
    // The whole block, from its `lsystem` word to its closing brace, so tools can rewrite it.
    SourceLoc blockStart, blockEnd;
};

// The text of an `lsystem NAME { ... }` block that checks back to `definition` and `connect`
// (every key written, productions and macros in symbol order), for `voxc lsystem cross`.
// Throws UserError when a symbol or string cannot be written in .vox syntax (a rule file may
// name a macro `$`; a block label must be a letter).
std::string formatLsystemBlock(const std::string& name, const lsystem::Definition& definition,
                               const lsystem::ConnectParams& connect);

struct CheckResult {
    std::optional<Program> program;       // present exactly when no error was reported
    std::vector<CheckedLsystem> lsystems; // with `program`: every lsystem block, declaration order
    std::vector<Diagnostic> diagnostics;  // errors and warnings in report order
    SourceFile source;                    // what was checked (empty text when it could not be read)

    bool hasErrors() const;
    // Every diagnostic rendered against `source` (see voxc/syntax/Diagnostics.h).
    std::string rendered() const;
};

struct CheckOptions {
    Limits limits;
    // Replaces the value of each named `const`, as if its declaration said `const NAME = value;`
    // (its own expression is still checked), so every use sees the new value: constants folded
    // from it, grammar cells, world and shape keys, field expressions. A name the file does not
    // declare is error E0002 without a location; a NaN or infinite value is E0007 at the
    // declaration. `voxc explore` sweeps a constant this way.
    std::map<std::string, double, std::less<>> constOverrides;
    // Replaces the world's seed before anything reads it (`--seed`), so the features, carves and
    // the solves of the run draw from it too, as if the file said `seed = S;`.
    std::optional<uint32_t> seed{};
    // `--region`: the box of the world (world voxels, min and max with max excluded) a run will
    // compute. The world may then exceed Limits::maxVoxels: what must fit is the box grown by the
    // pipeline's halo (voxc/stages/Region.h), clipped to the world (E0014 otherwise), and the work
    // estimate counts that grid.
    std::optional<std::pair<glm::ivec3, glm::ivec3>> region{};
    // Where the rule files lsystem blocks import come from (`rules = "x.rules"`, given the path
    // joined to the .vox's directory as the checker would open it): the text, or nothing for a
    // file it does not have (E0100). Null: the disk. A loaded package serves its own copies.
    std::function<std::optional<std::string>(const std::string& path)> readRuleFile{};
    // The same for the files heightmap and mesh blocks read (`file = "ridge.png"`): their bytes,
    // or nothing (E0100). Null: the disk (at most Limits::maxInputBytes).
    std::function<std::optional<std::string>(const std::string& path)> readInputFile{};
};

CheckResult checkSource(const SourceFile& source, const Limits& limits = {});
CheckResult checkSource(const SourceFile& source, const CheckOptions& options);
// Reads `path` (E0100 when it cannot, E0101 when it is not UTF-8 text) and checks it.
CheckResult checkFile(const std::string& path, const Limits& limits = {});
CheckResult checkFile(const std::string& path, const CheckOptions& options);

} // namespace voxc
