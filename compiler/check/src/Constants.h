#pragma once
// Named constants and constant folding. A constant may use only constants declared before
// it, so there are no cycles; a constant whose expression failed folds to nothing and is
// not reported again where it is used.
#include "voxc/syntax/Ast.h"
#include "voxc/syntax/Diagnostics.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>

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

    // Folds `expr`, reporting unknown names (E0002), strings (E0010), division by zero and
    // non-finite results (E0007). `subject` names what the value is for in those messages, e.g.
    // "'probability'" or "the weight of a production" (empty: nothing). Nothing after an error.
    std::optional<double> evaluate(const ast::Expr& expr, std::string_view subject = {}) const;

    bool isDeclared(const std::string& name) const { return entries_.count(name) != 0; }

private:
    struct Entry {
        SourceLoc loc;
        std::optional<double> value;
    };
    std::optional<double> fold(const ast::Expr& expr, std::string_view subject, bool& failed) const;

    Diagnostics& diagnostics_;
    const Overrides& overrides_;
    std::map<std::string, Entry, std::less<>> entries_;
};

} // namespace voxc::check
