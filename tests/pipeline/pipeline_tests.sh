#!/usr/bin/env bash
# Usage: pipeline_tests.sh VOXC SOURCE_DIR. The flags build systems and tools use (docs/cli.md,
# "Build pipelines"): the depfile of `compile -MD`, JSON diagnostics, quiet and verbose modes.
# Prints "N passed, N failed" last.
set -u
voxc=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/../support/expect.sh"

cp -r "$src/tests/pipeline/project" "$work/proj"
vox=$work/proj/world.vox
rules=$work/proj/tunnels.rules

# The depfile names the .vox and the rule file it imports, under the target -MT gives.
expect depfile_compile 0 "wrote $work/deps.d \(2 inputs\)" -- "$voxc" compile "$vox" -o "$work/pkg" -MD -MF "$work/deps.d" -MT "$work/stamp"
expect depfile_lists_every_input 0 "" -- python3 - "$work/deps.d" "$work/stamp" "$vox" "$rules" <<'PY'
import sys
text = open(sys.argv[1]).read()
target, _, rest = text.partition(":")
assert target == sys.argv[2], (target, sys.argv[2])
inputs = rest.replace("\\\n", " ").split()
assert inputs == sys.argv[3:], (inputs, sys.argv[3:])
PY
expect depfile_default_path 0 "wrote $work/pkg2.d" -- "$voxc" compile "$vox" -o "$work/pkg2/" -MD
expect depfile_default_target 0 "" -- grep -q "^$work/pkg2/manifest.json:" "$work/pkg2.d"
expect depfile_unchanged_package 0 "is up to date" -- "$voxc" compile "$vox" -o "$work/pkg2" --MD
expect depfile_inside_package 1 "inside the package directory" -- "$voxc" compile "$vox" -o "$work/pkg" -MF "$work/pkg/deps.d"
expect depfile_is_input 1 "voxc never writes over a file it reads" -- "$voxc" compile "$vox" -o "$work/pkg3" -MF "$vox"
mkdir -p "$work/with space"
cp "$vox" "$rules" "$work/with space/"
expect depfile_space 0 "" -- "$voxc" compile "$work/with space/world.vox" -o "$work/pkg4" -MF "$work/spaced.d"
expect depfile_space_escaped 0 "" -- grep -qF 'with\ space/tunnels.rules' "$work/spaced.d"
# Heightmap and mesh files are inputs too: the depfile names them, so a changed image or mesh
# rebuilds the package.
cp "$src/examples/imported_ridge.vox" "$src/examples/imported_ridge.png" "$src/examples/boulders.vox" \
    "$src/examples/boulder.glb" "$work/proj/"
expect depfile_heightmap 0 "\(3 inputs\)" -- "$voxc" compile "$work/proj/imported_ridge.vox" -o "$work/ridge" -MF "$work/ridge.d"
expect depfile_heightmap_named 0 "" -- grep -qF "$work/proj/imported_ridge.png" "$work/ridge.d"
expect depfile_heightmap_scene_mesh_named 0 "" -- grep -qF "$work/proj/boulder.glb" "$work/ridge.d"
expect depfile_mesh 0 "\(2 inputs\)" -- "$voxc" compile "$work/proj/boulders.vox" -o "$work/boulders" -MF "$work/boulders.d"
expect depfile_mesh_named 0 "" -- grep -qF "$work/proj/boulder.glb" "$work/boulders.d"
# A build tool that reads the depfile (ninja, as CMake's generated rules do) rebuilds the package
# when the heightmap or the mesh changes, and not when nothing did.
mkdir "$work/ninja"
cat > "$work/ninja/build.ninja" <<EOF
rule voxc
  command = "$voxc" compile \$in -o "$work/ninja/pkg" -q -MF \$out.d -MT \$out && touch \$out
  depfile = \$out.d
  deps = gcc
build ridge.stamp: voxc $work/proj/imported_ridge.vox
EOF
expect ninja_builds 0 "\[1/1\]" -- ninja -C "$work/ninja"
expect ninja_up_to_date 0 "no work to do" -- ninja -C "$work/ninja"
sleep 1 # past the stamp's time, at a file system's coarsest resolution
touch "$work/proj/imported_ridge.png"
expect ninja_rebuilds_on_heightmap 0 "\[1/1\]" -- ninja -C "$work/ninja"
expect ninja_up_to_date_again 0 "no work to do" -- ninja -C "$work/ninja"
sleep 1
touch "$work/proj/boulder.glb"
expect ninja_rebuilds_on_mesh 0 "\[1/1\]" -- ninja -C "$work/ninja"
# A damaged input is a located error at its block's file value, and the compile leaves no
# package: a truncated heightmap, then a truncated mesh.
mkdir "$work/damaged"
cp "$work/proj/imported_ridge.vox" "$work/proj/boulder.glb" "$work/damaged/"
head -c 3000 "$work/proj/imported_ridge.png" > "$work/damaged/imported_ridge.png"
expect damaged_heightmap 1 "imported_ridge.vox:25:10: error E0102: heightmap 'ridge': .*truncated" -- \
    "$voxc" compile "$work/damaged/imported_ridge.vox" -o "$work/damaged/pkg" -MD
expect_no_file damaged_heightmap_no_package "$work/damaged/pkg"
cp "$work/proj/imported_ridge.png" "$work/damaged/"
head -c 2000 "$work/proj/boulder.glb" > "$work/damaged/boulder.glb"
expect damaged_mesh 1 "imported_ridge.vox:33:10: error E0102: mesh 'boulder': " -- \
    "$voxc" compile "$work/damaged/imported_ridge.vox" -o "$work/damaged/pkg" -MD
expect_no_file damaged_mesh_no_package "$work/damaged/pkg"
printf 'world { size = [8, 8, 8]; }\npipeline { start; nope; }\n' > "$work/broken.vox"
expect depfile_not_on_error 1 "E0002" -- "$voxc" compile "$work/broken.vox" -o "$work/pkg5" -MD -MF "$work/broken.d"
expect depfile_not_on_error_absent 1 "" -- test -e "$work/broken.d"

# JSON diagnostics carry what the text form says: code, file, line, column (for an error in the
# .vox file and one in its rule file), on check, compile and run alike.
printf 'world {\n  size = [16, 16, 16];\n}\nlsystem net {\n  rules = "bad.rules";\n}\ngrammar g { rule r { size = [1,1,1]; symbol { [PRES 3] } } }\npipeline { start; missing; }\n' > "$work/bad.vox"
printf 'I;FFZ;tunnel;1\nC;FXZ;tunnel;1\n' > "$work/bad.rules"
"$voxc" check "$work/bad.vox" > /dev/null 2> "$work/text.err"
for verb in check compile run; do
    extra=()
    [ "$verb" = compile ] && extra=(-o "$work/badpkg")
    [ "$verb" = run ] && extra=(-o "$work/bad.ply")
    "$voxc" "$verb" "$work/bad.vox" "${extra[@]}" --diagnostics-format json > /dev/null 2> "$work/$verb.json"
    expect "json_matches_text_$verb" 0 "" -- python3 - "$work/text.err" "$work/$verb.json" "$work/bad.vox" <<'PY'
import json, re, sys
text = open(sys.argv[1]).read()
located = re.findall(r"^(\S+?):(\d+):(\d+): (error|warning) (E\d{4}|W\d{4}): (.*)$", text, re.M)
assert len(located) >= 3, text
objects = [json.loads(line) for line in open(sys.argv[2])]
diagnostics = [o for o in objects if "summary" not in o]
got = [(o["file"], str(o["range"]["start"]["line"]), str(o["range"]["start"]["column"]), o["severity"], o["code"], o["message"])
       for o in diagnostics]
assert got == [tuple(d) for d in located], (got, located)
for o in diagnostics:
    assert o["range"]["end"]["line"] == o["range"]["start"]["line"] and o["range"]["end"]["column"] > o["range"]["start"]["column"]
    assert isinstance(o["notes"], list)
assert any(o["file"].endswith("bad.rules") for o in diagnostics)
# the closing summary is a record of its own, not one more error
errors = sum(o["severity"] == "error" for o in diagnostics)
warnings = sum(o["severity"] == "warning" for o in diagnostics)
assert objects[-1] == {"summary": {"file": sys.argv[3], "errors": errors, "warnings": warnings}}, objects[-1]
assert all("fixits" in o for o in diagnostics)
PY
done
expect json_missing_file 1 '^\{"code":"E0100","severity":"error","file":"[^"]*nope.vox","range":null' -- "$voxc" check "$work/nope.vox" --diagnostics-format json
expect json_bad_format 1 "diagnostics-format" -- "$voxc" check "$vox" --diagnostics-format xml

# -q prints only warnings and errors; -v adds the inputs read and the time taken.
expect quiet_check_silent 0 "^$" -- "$voxc" check -q "$vox"
expect quiet_compile_silent 0 "^$" -- "$voxc" compile --quiet "$vox" -o "$work/pkg6" -MD
expect quiet_still_errors 1 "E0002" -- "$voxc" check -q "$work/broken.vox"
expect verbose_check 0 "checked .*world.vox \([0-9]+ bytes\) in [0-9.]+ ms: 0 errors, 0 warnings" -- "$voxc" check -v "$vox"
expect verbose_rule_file 0 "lsystem net imports the rule file .*tunnels.rules" -- "$voxc" compile -v "$vox" -o "$work/pkg7"
expect verbose_compile_time 0 "compiled [0-9]+ kernels in [0-9.]+ ms" -- "$voxc" compile -v "$vox" -o "$work/pkg7"
expect quiet_and_verbose 1 "excludes" -- "$voxc" check -q -v "$vox"
# -v names each heightmap and mesh file with its size, and marks one outside the .vox's folder
# (through .. or absolute), which a package built from it still copies.
mkdir "$work/sub"
sed -e 's#"imported_ridge.png"#"../proj/imported_ridge.png"#' -e "s#\"boulder.glb\"#\"$work/proj/boulder.glb\"#" \
    "$work/proj/imported_ridge.vox" > "$work/sub/ridge.vox"
expect verbose_input_inside 0 "heightmap ridge reads .*/proj/imported_ridge.png \([0-9]+ bytes\)$" -- "$voxc" check -v "$work/proj/imported_ridge.vox"
expect verbose_input_outside_relative 0 "heightmap ridge reads .*/sub/../proj/imported_ridge.png \([0-9]+ bytes\), outside the .vox's folder" -- \
    "$voxc" check -v "$work/sub/ridge.vox"
expect verbose_input_outside_absolute 0 "mesh boulder reads $work/proj/boulder.glb \([0-9]+ bytes\), outside the .vox's folder" -- \
    "$voxc" check -v "$work/sub/ridge.vox"

finish
