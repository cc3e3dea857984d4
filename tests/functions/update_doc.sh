#!/bin/sh
# Regenerates the registry table in docs/functions.md from voxc::functions().
# Usage: tests/functions/update_doc.sh [build dir]   (default: build)
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
cmake --build "$build" --target voxc_functions_doc
doc=$root/docs/functions.md
table=$(mktemp)
"$build/tests/functions/voxc_functions_doc" > "$table"
python3 - "$doc" "$table" <<'PY'
import sys
doc, table = sys.argv[1], open(sys.argv[2]).read()
text = open(doc).read()
begin = text.index("<!-- registry table:")
end = text.index("<!-- end of registry table -->\n") + len("<!-- end of registry table -->\n")
tmp = doc + ".tmp"
open(tmp, "w").write(text[:begin] + table + text[end:])
import os
os.replace(tmp, doc)
PY
rm -f "$table"
echo "updated $doc"
