#!/usr/bin/env bash
# Usage: docs_tests.sh DOCS_DIR. A user learns the language from docs/language.md and the other
# pages, so none of them may send the reader to a C++ header for a rule of the language: the
# page names no header at all, and no page but architecture.md (the contributors' map) names the
# headers where the rules are implemented. Prints "N passed, N failed" last.
set -u
docs=$1
. "$(dirname "$0")/../support/expect.sh"

headers_in() { grep -nE '[A-Za-z_/]+\.h\b' "$1"; }
for page in language.md; do
    if found=$(headers_in "$docs/$page"); then
        fail "$page names a C++ header:"; echo "$found"
    else
        pass "$page names no C++ header"
    fi
done
rules='(Semantics|Shapes|Ops|Aggregates|Program|Symmetry|Functions)\.h\b'
for page in "$docs"/*.md; do
    name=$(basename "$page")
    [ "$name" = architecture.md ] && continue
    [ "$name" = functions.md ] && continue # the registry's page, for people adding a builtin
    if found=$(grep -nE "$rules" "$page"); then
        fail "$name sends the reader to a header for the language's rules:"; echo "$found"
    else
        pass "$name states the rules itself"
    fi
done
finish
