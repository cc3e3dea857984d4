#pragma once
// Where each part of an L-system definition was written, so that the problems
// lsystem::checkDefinition names by a `where` string ("angle", "production Z #2", "macro Q")
// become located diagnostics, in the .vox file or in an imported rule file.
#include "Context.h"

#include "voxc/generators/lsystem/Definition.h"
#include "voxc/syntax/SourceFile.h"

#include <map>
#include <memory>
#include <string>

namespace voxc::check {

struct LsystemOrigin {
    SourceLoc loc;
    std::shared_ptr<const SourceFile> file; // null: the checked .vox file
};

struct LsystemOrigins {
    // "axiom", "production Z #2": where the string's first character is (problems inside a
    // string are located at their character).
    std::map<std::string, LsystemOrigin> strings;
    // Keys, blocks and weights by their `where` name ("angle", "target.point", "macro Q").
    std::map<std::string, LsystemOrigin> places;
    LsystemOrigin fallback; // the block's name, for problems of the whole definition

    void report(Context& context, const lsystem::Definition& definition, const lsystem::DefinitionProblem& problem) const;
};

} // namespace voxc::check
