#pragma once
// Typed reading of `key = value;` assignments and the key discipline every block follows:
// unknown keys (E0008, with a suggestion), duplicates (E0003), missing required keys (E0009),
// wrong shapes of value (E0010) and values out of range (E0007).
#include "Context.h"

#include "voxc/syntax/Ast.h"

#include <array>
#include <glm/vec3.hpp>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace voxc::check {

// The largest magnitude a coordinate key (an origin, a size, a height) takes.
constexpr double kMaxCoordinate = 1e7;

// Shortest text that reads back as `v`: 64, 0.5, -1e+30.
std::string formatNumber(double v);
// "[3, 3, 1]"
std::string formatVec(glm::ivec3 v);

// The assignments of one block, validated against the keys it accepts.
class BlockKeys {
public:
    // `where` names the block in messages, e.g. "'world' block" or "rule 'erode'".
    BlockKeys(Context& context, const ast::Block& block, std::string where, std::span<const std::string_view> known);

    // The assignment of `key`, or null when the block does not set it.
    const ast::Assignment* find(std::string_view key) const;
    // Like find, reporting E0009 at the block when the key is missing.
    const ast::Assignment* require(std::string_view key) const;

private:
    Context& context_;
    const ast::Block& block_;
    std::string where_;
    std::vector<const ast::Assignment*> assignments_; // first of each known key
};

// What a block may hold besides assignments; anything else is reported (E0008).
struct Allowed {
    bool blocks = false;
    bool rows = false;
    bool names = false;
    bool strings = false; // `"FZ" tunnel 1;` (L-system productions and macros)
};
void rejectUnexpectedMembers(Context& context, const ast::Block& block, const std::string& where, Allowed allowed);

// Reports E0001 when the block has a label it should not have, or lacks one it needs.
bool checkLabel(Context& context, const ast::Block& block, bool needsLabel);

// Takes a labelled block's name for a pipeline stage (curves, terrain): E0003 and false when an
// earlier block in `names`, another stage (`usedNames`) or the start state already has it.
bool claimStageName(Context& context, const ast::Block& block, std::map<std::string, SourceLoc>& names,
                    const std::vector<std::string>& usedNames);

// Value readers: each reports its own errors against `key` and returns nothing on failure.
std::optional<double> readNumber(Context& context, const ast::Assignment& a, double min, double max);
std::optional<int64_t> readInteger(Context& context, const ast::Assignment& a, int64_t min, int64_t max);
std::optional<std::array<double, 3>> readNumberVec3(Context& context, const ast::Assignment& a, double min,
                                                    double max);
std::optional<glm::ivec3> readIntegerVec3(Context& context, const ast::Assignment& a, int64_t min, int64_t max);
// A key of voxc/check/KeyRanges.h's blockKeys(block) within its range: an integer when the range
// says so (readInteger's errors), else a number (readNumber's).
std::optional<double> readKey(Context& context, const ast::Assignment& a, std::string_view block);
// One element of a's list value as an integer in [min, max] (E0010, E0007 at the element).
std::optional<int64_t> readIntegerElement(Context& context, const ast::Assignment& a, const ast::Value& element,
                                          int64_t min, int64_t max);
// `[lo, hi]` of numbers with lo <= hi, each within the float range.
std::optional<std::array<double, 2>> readRange(Context& context, const ast::Assignment& a);
// `[[x, y, z], [x, y, z]]` of integers.
std::optional<std::array<glm::ivec3, 2>> readBox(Context& context, const ast::Assignment& a);
// `x`, `y` or `z` as 0, 1, 2.
std::optional<int> readAxis(Context& context, const ast::Assignment& a);

// A scalar expression folded to a number that is finite as a float (used for operator values).
std::optional<float> readFloat(Context& context, const ast::Expr& expr);

} // namespace voxc::check
