#pragma once
// What the language server says about the words of the language, read from the registries that
// define them (compiler/builtins, the generators), so the editor's help cannot drift from what
// the checker accepts: builtin functions (signature and doc), symbol, transform and material
// operators, start shapes and Dey's generators with their keys (type, range, default).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace voxc::lsp {

// LSP CompletionItemKind values used here.
enum class WordKind { Function = 3, Variable = 6, Class = 7, Module = 9, Property = 10, Keyword = 14, Operator = 24 };

struct WordHelp {
    std::string name;
    WordKind kind;
    std::string detail;        // one line: a signature, "symbol operator", "start shape"
    std::string documentation; // markdown
};

// Every builtin word: functions, operators, shapes and generators.
const std::vector<WordHelp>& builtinWords();
// The word's help when it is a builtin (a name can be both, e.g. MAT in symbols and transforms).
std::optional<WordHelp> findBuiltin(std::string_view word);

// The keys of a block whose kind is a start shape (`box`, `sphere`, ...) or a generator (`arch`,
// ...); empty for other blocks, whose keys no registry describes.
std::vector<WordHelp> registryKeys(std::string_view blockKind);

} // namespace voxc::lsp
