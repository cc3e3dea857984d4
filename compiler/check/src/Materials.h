#pragma once
// Material names: their own namespace, filled from the `material NAME { ... }` blocks before
// anything else is checked, and read wherever a material is named: the operand of MAT/NMAT,
// a `material = NAME;` key (start shapes, features) and a pipeline stage's `material NAME`.
// `none` is the builtin material 0; it can be named but not declared.
#include "voxc/program/Program.h"
#include "voxc/syntax/Ast.h"
#include "voxc/syntax/Diagnostics.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace voxc::check {

// The key that names a block's material.
constexpr std::string_view kMaterialKey = "material";

struct Context;

class MaterialNames {
public:
    // Names every declared material (so a use is never "unknown" because the declaration has
    // another error); the first declaration of a name wins.
    void declare(const std::string& name, uint8_t id);

    // The id of `name` (0 for `none`), or E0002 with a suggestion.
    std::optional<uint8_t> resolve(Diagnostics& diagnostics, std::string_view name, SourceLoc loc) const;
    // The operand of MAT/NMAT or a `material = NAME;` value: a bare name (E0010 for a number
    // or any other expression).
    std::optional<uint8_t> resolve(Diagnostics& diagnostics, const ast::Expr& expr, std::string_view what) const;

private:
    std::vector<std::pair<std::string, uint8_t>> names_; // declaration order
};

// Every `material NAME { id = N; color = [r, g, b]; }` block, in declaration order, with ids
// resolved (default 1 + index among the material blocks). Also declares the names in
// context.materials.
std::vector<Material> checkMaterials(Context& context, const ast::File& file);

// `material = NAME;` in a shape or feature block: the key's value resolved as a material.
std::optional<uint8_t> readMaterialKey(Context& context, const ast::Assignment& a);

} // namespace voxc::check
