#!/usr/bin/env bash
# Usage: adversarial_tests.sh VOXC SOURCE_DIR. Inputs an adversarial user would try: files a .vox
# names that are not regular files, bounds at their limit and one past it, damaged or unwritable
# outputs. Each must end at once with exit 1 and one clear line (never a hang, exit 2 or a
# partial output). Commands that would hang run under `timeout`, so a hang fails (exit 124).
# Prints "N passed, N failed" last.
set -u
voxc=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export VOXC_CACHE_DIR="$work/cache" # never the user's cache
. "$(dirname "$0")/../support/expect.sh"

# --- files a .vox names: only regular files, at most 4 MiB (docs/language.md, "Limits") ---
lsystem_naming() { printf 'world { size = [16, 16, 16]; }\nlsystem net {\n  rules = "%s";\n}\n' "$1"; }
mkfifo "$work/fifo.rules"
lsystem_naming fifo.rules > "$work/fifo.vox"
expect rules_fifo_refused 1 "fifo\.vox:3:11: error E0100: cannot read file '.*fifo\.rules': it is a FIFO \(named pipe\), not a regular file" \
    -- timeout 30 "$voxc" check "$work/fifo.vox"
lsystem_naming /dev/stdin > "$work/stdin.vox"
# stdin a pipe that stays open (as under `voxc lsp`), a terminal-like device, and /dev/null
expect rules_stdin_pipe_refused 1 "stdin\.vox:3:11: error E0100: .*'/dev/stdin': it is a FIFO" \
    -- bash -c 'timeout 30 "$0" check "$1" < <(exec sleep 40 2>/dev/null)' "$voxc" "$work/stdin.vox"
expect rules_stdin_device_refused 1 "stdin\.vox:3:11: error E0100: .*'/dev/stdin': it is a character device" \
    -- bash -c 'timeout 30 "$0" check "$1" < /dev/null' "$voxc" "$work/stdin.vox"
lsystem_naming /dev/zero > "$work/zero.vox"
expect rules_device_refused 1 "zero\.vox:3:11: error E0100: .*it is a character device" -- timeout 30 "$voxc" check "$work/zero.vox"
# heightmap and mesh blocks read their files the same way
mkfifo "$work/fifo.png" "$work/fifo.glb"
printf 'world { size = [16, 16, 16]; }\nheightmap hills {\n  file = "fifo.png";\n  size = [16, 16];\n  height = [0, 8];\n}\nfield g = clamp(hills(wx, wz) - wy, 0, 1);\npipeline { start; set g; }\n' > "$work/fifo_heightmap.vox"
expect heightmap_fifo_refused 1 "fifo_heightmap\.vox:3:10: error E0100: .*fifo\.png': it is a FIFO" -- timeout 30 "$voxc" check "$work/fifo_heightmap.vox"
printf 'world { size = [16, 16, 16]; }\nmesh rock {\n  file = "fifo.glb";\n}\nfield g = clamp(-rock(wp), 0, 1);\npipeline { start; set g; }\n' > "$work/fifo_mesh.vox"
expect mesh_fifo_refused 1 "fifo_mesh\.vox:3:10: error E0100: .*fifo\.glb': it is a FIFO" -- timeout 30 "$voxc" check "$work/fifo_mesh.vox"
lsystem_naming . > "$work/dir.vox"
expect rules_directory_refused 1 "dir\.vox:3:11: error E0100: .*it is a directory" -- timeout 30 "$voxc" check "$work/dir.vox"
# the size cap: exactly 4 MiB of comments is read, one byte more is E0012 with the number
{ printf 'I;FFZ;tunnel;1\n'; head -c $((4 * 1024 * 1024 - 15 - 1)) /dev/zero | tr '\0' '#'; printf '\n'; } > "$work/cap.rules"
lsystem_naming cap.rules > "$work/cap.vox"
expect rules_at_cap 0 "ok" -- timeout 60 "$voxc" check "$work/cap.vox"
printf '#' >> "$work/cap.rules"
expect rules_past_cap 1 "cap\.vox:3:11: error E0012: cannot read file '.*cap\.rules': it is larger than the limit of 4194304 bytes" \
    -- timeout 60 "$voxc" check "$work/cap.vox"
# the .vox itself, named on the command line, may be a pipe: the user chose it
expect source_from_pipe 0 "ok" -- bash -c 'cat "$1" | "$0" check /dev/stdin' "$voxc" "$src/examples/overhang.vox"
# a binary .vox: located like every other diagnostic, its line not printed
printf 'world\0{}\n' > "$work/binary.vox"
expect binary_located 1 "^binary\.vox:1:6: error E0101: not a text file: a NUL byte$" \
    -- bash -c 'set -o pipefail; cd "$1" && "$0" check binary.vox 2>&1 | sed -n 1p' "$voxc" "$work"

# --- outputs: exit 1 with one line, never exit 2, never a partial output ---
macros=$src/examples/lsystem_macros.vox
# a full population (2 x 64 + 2 files written as one set), and one past the bound
expect evolve_population_64 0 "wrote 64 variants" -- timeout 300 "$voxc" evolve "$macros" macros --population 64 -o "$work/gen64"
expect evolve_population_64_files 0 "^130$" -- bash -c 'ls "$0" | wc -l' "$work/gen64"
expect evolve_population_65 1 "--population must be 1\.\.64" -- "$voxc" evolve "$macros" macros --population 65 -o "$work/gen65"
expect_no_file evolve_population_65_no_folder "$work/gen65"
: > "$work/a_file"
expect evolve_into_file 1 "cannot write into '.*a_file': it exists and is not a directory" -- "$voxc" evolve "$macros" macros -o "$work/a_file"
ln -s "$work/nowhere" "$work/dangling"
expect evolve_into_dangling_link 1 "cannot write into '.*dangling': it is a link to '.*nowhere', which does not exist" \
    -- "$voxc" evolve "$macros" macros -o "$work/dangling"
expect_no_file evolve_dangling_nothing_made "$work/nowhere"
expect evolve_unwritable 1 "^voxc: error: cannot write into '/proc/self/x'" -- "$voxc" evolve "$macros" macros -o /proc/self/x
expect evolve_unwritable_existing 1 "cannot write" -- "$voxc" evolve "$macros" macros -o /proc/self
# a failed evolve removes the folders it made (here: the input fails its check), and only those
printf 'world { size = [8, 8, 8]; }\nlsystem bad {\n  rules = "nope.rules";\n}\n' > "$work/bad_lsystem.vox"
expect evolve_fails 1 "" -- "$voxc" evolve "$work/bad_lsystem.vox" bad -o "$work/made/deeper"
expect_no_file evolve_failed_no_folder "$work/made"
mkdir "$work/mine"
expect evolve_fails_in_existing 1 "" -- "$voxc" evolve "$work/bad_lsystem.vox" bad -o "$work/mine"
expect evolve_failed_keeps_existing 0 "" -- test -d "$work/mine"

world=$work/world.vox
printf 'world { size = [16, 16, 16]; }\nfield ground = clamp(8 - y, 0, 1);\npipeline { start; set ground; }\n' > "$world"
expect world_into_file 1 "cannot write into '.*a_file': it exists and is not a directory" -- "$voxc" world "$world" --interpreter -o "$work/a_file"
expect world_into_dangling_link 1 "cannot write into '.*dangling': it is a link" -- "$voxc" world "$world" --interpreter -o "$work/dangling"
expect world_unwritable 1 "^voxc: error: cannot write into '/proc/self/x'" -- "$voxc" world "$world" --interpreter -o /proc/self/x
expect world_writes 0 "wrote 1 of 1 tiles" -- "$voxc" world "$world" --interpreter --tile 16 -o "$work/w"
cp "$work/w/index.json" "$work/index.good"
# a damaged index: each tile entry without one of its keys, or with a wrong type, is computed again
for damage in 'del t["file"]' 'del t["sha256"]' 'del t["tile"]' 't["tile"] = "0,0,0"' 't["tile"] = [0, 0]' \
              't["sha256"] = 7' 't["file"] = "../../escape.vdb"' 't["mesh"] = 3' 't["mesh"] = {"file": 1}'; do
    python3 - "$work/index.good" "$work/w/index.json" "$damage" <<'PY'
import json, sys
index = json.load(open(sys.argv[1]))
t = index["tiles"][0]
exec(sys.argv[3])
json.dump(index, open(sys.argv[2], "w"))
PY
    expect "world_damaged_index_$(tr -c 'a-z0-9' '_' <<<"$damage")" 0 "wrote 1 of 1 tiles .*\(0 up to date\)" \
        -- "$voxc" world "$world" --interpreter --tile 16 -o "$work/w"
done
expect world_repaired_index 0 "" -- cmp "$work/index.good" "$work/w/index.json"
for damage in '[]' '{"format": "voxc-world"}' '{"format": "voxc-world", "tiles": 3}' 'not json'; do
    printf '%s' "$damage" > "$work/w/index.json"
    expect "world_index_not_an_index_$(tr -c 'a-z0-9' '_' <<<"$damage")" 1 "is not a voxc world index" \
        -- "$voxc" world "$world" --interpreter --tile 16 -o "$work/w"
done
rm "$work/w/index.json"; mkfifo "$work/w/index.json"
expect world_index_fifo 1 "index\.json': it is a FIFO" -- timeout 30 "$voxc" world "$world" --interpreter --tile 16 -o "$work/w"

# --- flags and edits files: bounds at their limit and one past ---
expect max_work_infinite 1 "--max-work: expects a number from 1 to 1e\+18" -- "$voxc" check --max-work 1e400 "$world"
expect max_work_inf 1 "--max-work: expects a number from 1 to 1e\+18" -- "$voxc" check --max-work inf "$world"
expect max_work_at_bound 0 "ok" -- "$voxc" check --max-work 1e18 "$world"
expect max_work_past_bound 1 "expects a number from 1" -- "$voxc" check --max-work 1.0001e18 "$world"
printf '[{"op": "carve", "center": [1, 2, 3],\n  "radius": 1e400}]\n' > "$work/huge.json"
expect edits_radius_overflow 1 "huge\.json:2:13: error E0007: the number 1e400 is beyond the range of a double" \
    -- "$voxc" interp "$world" --edits "$work/huge.json"
# 100,000 edits (the most a file may hold) are located and replayed in seconds; one more is E0012
python3 -c '
import sys
n = int(sys.argv[2])
with open(sys.argv[1], "w") as f:
    f.write("[\n" + ",\n".join("{\"op\": \"carve\", \"center\": [%d, 8, %d], \"radius\": 1}" % (i % 16, i // 16 % 16) for i in range(n)) + "\n]\n")
' "$work/many.json" 100000
expect edits_at_count_limit 0 "edits: 100000 applied" -- timeout 120 "$voxc" interp "$world" --edits "$work/many.json"
sed -i 's/^]$/,{"op": "add", "center": [1, 1, 1], "radius": 1}]/' "$work/many.json"
expect edits_past_count_limit 1 "many\.json:100002:2: error E0012: 100001 edits: at most 100000 per file" \
    -- timeout 120 "$voxc" interp "$world" --edits "$work/many.json"
# brushes bigger than the grid: the voxels they visit, clipped to the grid, are bounded (10^9)
python3 -c '
import sys
with open(sys.argv[1], "w") as f:
    f.write("[" + ",\n".join("{\"op\": \"add\", \"center\": [8, 8, 8], \"radius\": 4096}" for i in range(50000)) + "]\n")
' "$work/huge_brushes.json"
printf 'world { size = [128, 128, 128]; }\nfield ground = clamp(8 - y, 0, 1);\npipeline { start; set ground; }\n' > "$work/world128.vox"
# 128^3 = 2,097,152 voxels per brush: the 477th brush passes 10^9 (476 x 2,097,152 = 998,244,352)
expect edits_past_voxel_limit 1 "huge_brushes\.json:477:1: error E0012: edit 477: the edits so far visit 1000341504 voxels of the grid, more than the limit of 1000000000" \
    -- timeout 60 "$voxc" interp "$work/world128.vox" --edits "$work/huge_brushes.json"
# a curve of 4096 control points (the limit) checks in seconds (its spline's knots built once);
# 4097 is refused
curve_of() {
    python3 -c '
import sys
n = int(sys.argv[1])
points = ", ".join("[%.6f, 8, %.6f]" % (4 + 24.0 * i / (n - 1), 16 + (i % 2) * 0.01) for i in range(n))
print("world { size = [32, 16, 32]; }\ncurves ledge {\n  box = [[0, 0, 0], [31, 15, 31]];\n"
      "  curve c { points = [%s]; constraint { t = 0; } constraint { t = 1; } }\n}\npipeline { start; set ledge; }" % points)
' "$1"
}
curve_of 4096 > "$work/curve4096.vox"
expect curve_points_at_limit 0 "ok" -- timeout 120 "$voxc" check "$work/curve4096.vox"
curve_of 4097 > "$work/curve4097.vox"
expect curve_points_past_limit 1 "curve4097\.vox:4:22: error E0007: 'points' expects a list of 4 to 4096 control points" \
    -- timeout 120 "$voxc" check "$work/curve4097.vox"
# `voxc lsystem --format json` streams the skeleton: 516,033 segments (63 F, two tips per rewrite,
# 13 expansions) in far less memory than a JSON tree of them (about 1.3 kB a segment)
printf 'world { size = [8, 8, 8]; }\nlsystem many {\n  expansions = 13;\n  production Z { "%sZZ"; }\n}\n' "$(printf 'F%.0s' $(seq 63))" > "$work/wide.vox"
peak_kib() { python3 -c '
import resource, subprocess, sys
code = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=300).returncode
print(code, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
' "$@"; }
read -r code peak < <(peak_kib "$voxc" lsystem "$work/wide.vox" many --format json -o "$work/wide.json")
[[ $code == 0 && $peak -lt 300000 ]] && pass "lsystem_json_streams (peak ${peak} KiB)" || fail "lsystem_json_streams: exit $code, peak ${peak} KiB"
expect lsystem_json_complete 0 "^516033$" -- python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['segments']))" "$work/wide.json"
read -r code peak < <(peak_kib "$voxc" lsystem "$work/wide.vox" many --format obj)
[[ $code == 0 && $peak -lt 300000 ]] && pass "lsystem_obj_streams (peak ${peak} KiB)" || fail "lsystem_obj_streams: exit $code, peak ${peak} KiB"
# a package file of 4 GiB (sparse) is never read: one the manifest lists with another size is
# replaced by compile at once; one it does not list is refused from its size (the 256 MiB cap)
expect package_compile 0 "" -- "$voxc" compile "$world" -o "$work/pkg"
spv=$(ls "$work/pkg/kernels/"*.spv | head -1)
size=$(stat -c %s "$spv")
truncate -s 4G "$spv"
expect package_tampered_kernel_replaced 0 "" -- timeout 30 "$voxc" compile "$world" -o "$work/pkg"
expect package_tampered_kernel_restored 0 "^$size\$" -- stat -c %s "$spv"
truncate -s 4G "$work/pkg/kernels/unlisted.spv"
expect package_huge_kernel_refused 1 "cannot write package '.*pkg': kernels/unlisted\.spv is 4294967296 bytes, more than a package file may hold \(268435456 bytes\)" \
    -- timeout 30 "$voxc" compile "$world" -o "$work/pkg"
rm -rf "$work/pkg"
expect cross_negative_bracket 1 "--brackets: a bracket number is a whole number from 1" \
    -- "$voxc" lsystem cross "$macros:macros" "$macros:macros" --brackets -1,1

finish
