#pragma once
// Named constants and constant folding. A constant may use only constants declared before
// it, so there are no cycles; a constant whose expression failed folds to nothing and is
// not reported again where it is used.
#include "voxc/syntax/Ast.h"
#include "voxc/syntax/Diagnostics.h"

#include <map>
#include <optional>
#include <string>

namespace voxc::check {

class Constants {
public:
    using Overrides = std::map<std::string, double, std::less<>>;

    Constants(Diagnostics& diagnostics, const Overrides& overrides) : diagnostics_(diagnostics), overrides_(overrides) {}

    // Folds the declaration's expression and records it (E0003 for a second declaration);
    // an override of the name replaces the folded value.
    void declare(const ast::ConstDecl& decl);

    // E0002 for every override whose name no declaration used; call after every declare().
    void reportUnknownOverrides() const;

    // Folds `expr`, reporting unknown names (E0002), division by zero and non-finite
    // results (E0007). Returns nothing after an error.
    std::optional<double> evaluate(const ast::Expr& expr) const;

    bool isDeclared(const std::string& name) const { return entries_.count(name) != 0; }

private:
    struct Entry {
        SourceLoc loc;
        std::optional<double> value;
    };
    std::optional<double> fold(const ast::Expr& expr, bool& failed) const;

    Diagnostics& diagnostics_;
    const Overrides& overrides_;
    std::map<std::string, Entry, std::less<>> entries_;
};

} // namespace voxc::check
