#!/usr/bin/env bash
# Usage: cli_tests.sh VOXC SOURCE_DIR. Runs voxc as a user would and checks exit codes, messages
# and output files. Prints "N passed, N failed" last.
set -u
voxc=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export VOXC_CACHE_DIR="$work/cache" # never the user's cache
. "$(dirname "$0")/../support/expect.sh"

# --help on every verb
for verb in check compile run interp explore; do
    expect "help_$verb" 0 "Usage" -- "$voxc" "$verb" --help
done
expect no_verb 1 "" -- "$voxc"
expect unknown_flag 1 "" -- "$voxc" check --frobnicate "$src/examples/overhang.vox"

# bad input: located errors, exit 1
printf 'world {\n  size = [8, 8, 8]\n}\ngrammar g { rule r { size = [1,1,1]; symbol { [PRES 3] } } }\n' > "$work/bad.vox"
expect bad_syntax 1 "bad\.vox:[0-9]+:[0-9]+: error E[0-9]{4}" -- "$voxc" check "$work/bad.vox"
expect caret 1 "\^" -- "$voxc" check "$work/bad.vox"
head -c 300 /dev/urandom > "$work/garbage.vox"; printf '\0\1\2' >> "$work/garbage.vox"
expect binary 1 "garbage\.vox.*E0101" -- "$voxc" check "$work/garbage.vox"
printf '%%$#@ not a vox file ((((\n' > "$work/junk.vox"
expect garbage_text 1 "junk\.vox:1:[0-9]+: error E0001" -- "$voxc" check "$work/junk.vox"
: > "$work/empty.vox"
expect empty 1 "empty\.vox.*error E0009" -- "$voxc" check "$work/empty.vox"
expect missing 1 "nope\.vox.*E0100" -- "$voxc" check "$work/nope.vox"
expect missing_run 1 "E0100" -- "$voxc" run "$work/nope.vox" -o "$work/nope.ply"
expect_no_file no_partial_mesh "$work/nope.ply"
# limits: an endless device stops at the source cap; a pipeline past the work budget fails at the
# stage, and --max-work raises the budget (docs/language.md, "Limits")
expect dev_zero 1 "E0012.*larger than the limit" -- "$voxc" check /dev/zero
{
    printf 'world { size = [16, 16, 16]; }\ngrammar g {\n  iterations = 100000;\n'
    printf '  rule r { size = [1, 1, 1]; symbol { [GEQ 0.5] } transform { [SET 1] } }\n}\npipeline {\n  start;\n'
    for _ in $(seq 300); do printf '  g;\n'; done
    printf '}\n'
} > "$work/busy.vox"
expect over_budget 1 "busy\.vox:[0-9]+:3: error E0012.*--max-work" -- "$voxc" check "$work/busy.vox"
expect max_work_raises 0 "ok" -- "$voxc" check --max-work 1e14 "$work/busy.vox"
expect max_work_lowers 1 "E0012" -- "$voxc" interp --max-work 1000 "$src/examples/overhang.vox"
# a grid larger than the device binds as one buffer is refused before any work, pointing to --region
printf 'world { size = [512, 160, 512]; }\nfield ground = clamp(40 - y, 0, 1);\npipeline { start; set ground; }\n' > "$work/huge.vox"
expect grid_over_device_buffer 1 "--region.*voxc world" -- "$voxc" run "$work/huge.vox" --device lavapipe -o "$work/huge.ply"
expect_no_file no_partial_huge_mesh "$work/huge.ply"
expect bad_chunk 1 "power of two" -- "$voxc" run "$src/examples/overhang.vox" --chunk 12 -o "$work/x.ply"
expect bad_mesh_ext 1 "must end in" -- "$voxc" run "$src/examples/overhang.vox" -o "$work/x.stl"
expect bad_slice 1 "slice" -- "$voxc" interp "$src/examples/overhang.vox" --slice q=3
expect bad_device 1 "device" -- "$voxc" run "$src/examples/overhang.vox" --device 99 -o "$work/x.ply"
expect unwritable 1 "cannot write" -- "$voxc" run "$src/examples/overhang.vox" -o /nonexistent-dir/x.ply

# every example checks and compiles (each one's runs, meshes and readers: example_NAME)
for example in "$src"/examples/*.vox; do
    name=$(basename "$example" .vox)
    expect "check_$name" 0 "ok" -- "$voxc" check "$example"
    expect "compile_$name" 0 "kernels" -- "$voxc" compile "$example" -o "$work/pkg_$name"
done

# compile is byte-identical on every run
"$voxc" compile "$src/examples/overhang.vox" -o "$work/pkg_again" >/dev/null 2>&1
if diff -r "$work/pkg_overhang" "$work/pkg_again" >/dev/null; then
    echo "ok   compile_deterministic"; passed=$((passed + 1))
else
    echo "FAIL compile_deterministic"; failed=$((failed + 1))
fi
# every emitted SPIR-V passes spirv-val
for spv in "$work"/pkg_*/kernels/*.spv; do
    expect "spirv_val_$(basename "$(dirname "$(dirname "$spv")")")_$(basename "$spv")" 0 "" -- spirv-val --target-env vulkan1.1 "$spv"
done

# the Khronos validation layer reports nothing on a full run
expect validation_layer 0 "validation layer: 0 messages" -- "$voxc" run "$src/examples/overhang.vox" \
    --device lavapipe --validate -o "$work/validated.obj"

# interp trace and slice
expect trace 0 "iter 0 sweep [0-9]+ phase [0-9]+ anchor" -- "$voxc" interp "$src/examples/overhang.vox" --trace --trace-limit 5
expect slice 0 "#" -- "$voxc" interp "$src/examples/overhang.vox" --slice y=12

# explore: a cheap sweep writes both CSVs and a PNG; an unknown const is a clear error
expect explore 0 "pairwise IoU" -- "$voxc" explore "$src/examples/terrain.vox" --param ROCK --range 0.3:0.7:0.2 \
    --runs 2 --size 32,32,32 --csv "$work/explore.csv" --summary "$work/explore_summary.csv" --png "$work/explore.png"
expect explore_csv 0 "^ROCK,0.7,1,2025," -- cat "$work/explore.csv"
expect explore_summary 0 "^ROCK,0.5,2," -- cat "$work/explore_summary.csv"
expect explore_png 0 "PNG" -- head -c 4 "$work/explore.png"
expect explore_unknown_param 1 "E0002.*no such constant; did you mean 'ROCK'" -- "$voxc" explore \
    "$src/examples/terrain.vox" --param ROK --range 0:1:0.5 --png "$work/explore_bad.png"
expect_no_file explore_no_png_after_error "$work/explore_bad.png"
expect explore_bad_range 1 "STEP must be greater than 0" -- "$voxc" explore "$src/examples/terrain.vox" \
    --param ROCK --range 0:1:0

# materials: per-material counts, the uint8 .npy, PLY colours, OBJ groups with a .mtl beside it
cat > "$work/mat.vox" <<'EOF'
material rock { id = 1; color = [0.42, 0.40, 0.38]; }
material sand { color = [0.86, 0.78, 0.55]; }
world { size = [24, 24, 24]; chunk = 8; }
start {
  fill { value = 0; }
  box { min = [2, 2, 2]; max = [20, 12, 20]; material = rock; }
  sphere { center = [12, 14, 12]; radius = 5; material = sand; }
}
EOF
expect mat_run 0 "solid voxels by material: rock [0-9]+, sand [0-9]+" -- "$voxc" run "$work/mat.vox" --device lavapipe \
    -o "$work/mat.obj" --materials "$work/mat_run.npy"
expect mat_skipped_chunks 0 "skipped [1-9][0-9]* of 64 chunks with no surface" -- "$voxc" run "$work/mat.vox" \
    --device lavapipe -o "$work/mat.ply"
expect mat_npy 0 "'descr': '\|u1'.*'shape': \(24, 24, 24\)" -- \
    bash -c 'head -c 128 "$1" | tr -d "\\000"' _ "$work/mat_run.npy"
expect mat_obj_mtllib 0 "^mtllib mat\.mtl$" -- cat "$work/mat.obj"
expect mat_obj_usemtl 0 "^usemtl sand$" -- cat "$work/mat.obj"
expect mat_mtl 0 "^newmtl rock$" -- cat "$work/mat.mtl"
expect mat_ply_header 0 "property uchar material" -- sed '/^end_header$/q' "$work/mat.ply"
expect mat_interp 0 "solid voxels by material: rock" -- "$voxc" interp "$work/mat.vox" --materials "$work/mat_interp.npy"
if cmp -s "$work/mat_run.npy" "$work/mat_interp.npy"; then
    echo "ok   same_materials"; passed=$((passed + 1))
else
    echo "FAIL same_materials: run and interp materials differ"; failed=$((failed + 1))
fi
expect mat_bad_ext 1 "must end in \.npy" -- "$voxc" interp "$work/mat.vox" --materials "$work/mat.txt"
expect mat_unwritable_npy 1 "cannot write" -- "$voxc" run "$work/mat.vox" --device lavapipe \
    --materials "$work/no-dir/m.npy"
expect_no_file mat_no_partial_npy "$work/no-dir"
mkdir "$work/taken.obj"
expect mat_unwritable_obj 1 "is a directory" -- "$voxc" run "$work/mat.vox" --device lavapipe -o "$work/taken.obj"
expect_no_file mat_no_partial_mtl "$work/taken.mtl"

# file safety: no output over the input or over another output, refused before any work
cp "$work/mat.vox" "$work/self.ply"
expect out_is_input 1 "-o '.*self\.ply' is the input '.*self\.ply'" -- "$voxc" run "$work/self.ply" -o "$work/self.ply"
expect_same out_is_input_untouched "$work/mat.vox" "$work/self.ply"
ln -s mat.vox "$work/symlink.ply"
expect out_is_symlink_to_input 1 "is the input" -- "$voxc" run "$work/mat.vox" --device lavapipe -o "$work/symlink.ply"
ln "$work/mat.vox" "$work/hardlink.obj"
expect out_is_hard_link_to_input 1 "is the input" -- "$voxc" run "$work/mat.vox" --device lavapipe -o "$work/hardlink.obj"
expect_same hard_link_untouched "$work/mat.vox" "$work/hardlink.obj"
expect voxels_are_materials 1 "are the same file" -- "$voxc" run "$work/mat.vox" --device lavapipe \
    --voxels "$work/same.npy" --materials "$work/../$(basename "$work")/same.npy"
expect_no_file voxels_are_materials_nothing_written "$work/same.npy"
expect interp_outputs_clash 1 "are the same file" -- "$voxc" interp "$work/mat.vox" \
    --voxels "$work/same.npy" --materials "$work/./same.npy"
expect explore_outputs_clash 1 "--csv '.*' and --summary '.*' are the same file" -- "$voxc" explore \
    "$src/examples/terrain.vox" --param ROCK --range 0.3:0.5:0.2 --csv "$work/same.csv" --summary "$work/same.csv"
# a rule written once with `symmetry` runs as named variants, and the trace names them
expect trace_names_variants 0 "rule notch@(mirror_x|mirror_z|rot180y)" -- "$voxc" interp "$src/tests/e2e/cases/symmetry.vox" \
    --trace --trace-limit 50
mkdir -p "$work/adir.ply" "$work/adir.npy"
expect output_is_directory 1 "-o '.*adir\.ply' is a directory: give a file name" -- "$voxc" run "$work/mat.vox" \
    --device lavapipe -o "$work/adir.ply"
expect voxels_output_is_directory 1 "--voxels '.*' is a directory" -- "$voxc" interp "$work/mat.vox" --voxels "$work/adir.npy"
expect compile_over_input_dir 1 "contains the input" -- "$voxc" compile "$work/mat.vox" -o "$work"

# a failed OBJ export keeps the user's .mtl beside it; a failed output keeps the other outputs' old files
printf 'newmtl the_users_own\nKd 1 0 0\n' > "$work/kept.mtl"
cp "$work/kept.mtl" "$work/kept.mtl.orig"
expect obj_failure 1 "cannot write" -- "$voxc" run "$work/mat.vox" --device lavapipe -o "$work/kept.obj" \
    --materials "$work/no-dir/m.npy"
expect_same obj_failure_keeps_mtl "$work/kept.mtl.orig" "$work/kept.mtl"
printf 'the user'"'"'s voxels' > "$work/kept.npy"
cp "$work/kept.npy" "$work/kept.npy.orig"
expect set_failure 1 "cannot write" -- "$voxc" run "$work/mat.vox" --device lavapipe \
    --voxels "$work/kept.npy" --materials "$work/no-dir/m.npy"
expect_same set_failure_keeps_voxels "$work/kept.npy.orig" "$work/kept.npy"
if compgen -G "$work/*.tmp-*" >/dev/null; then
    echo "FAIL no_temp_files_left: $(compgen -G "$work/*.tmp-*" | head -3)"; failed=$((failed + 1))
else
    echo "ok   no_temp_files_left"; passed=$((passed + 1))
fi

# the compile cache: a second run reads every kernel back; --no-cache neither reads nor writes it
expect cache_first_run 0 "spirv .* 0 from the cache, [1-9][0-9]* compiled" -- env VOXC_CACHE_DIR="$work/fresh-cache" "$voxc" run "$work/mat.vox" \
    --device lavapipe -o "$work/cached.ply" --timings
expect cache_second_run 0 "spirv .* [1-9][0-9]* from the cache, 0 compiled" -- env VOXC_CACHE_DIR="$work/fresh-cache" "$voxc" run "$work/mat.vox" \
    --device lavapipe -o "$work/cached.ply" --timings
expect cache_off 0 "0 from the cache, [1-9][0-9]* compiled \(--no-cache\)" -- env VOXC_CACHE_DIR="$work/fresh-cache" "$voxc" run "$work/mat.vox" \
    --device lavapipe -o "$work/cached.ply" --timings --no-cache
find "$work/fresh-cache/spirv" -name '*.spv' -exec sh -c 'printf garbage > "$1"' _ {} \;
expect cache_damaged_rebuilt 0 "0 from the cache, [1-9][0-9]* compiled" -- env VOXC_CACHE_DIR="$work/fresh-cache" "$voxc" run "$work/mat.vox" \
    --device lavapipe -o "$work/cached.ply" --timings

# a run whose mesh is empty says so and still succeeds
printf 'world { size = [16, 16, 16]; chunk = 8; }\nstart { fill { value = 0; } }\n' > "$work/air.vox"
expect empty_mesh_warning 0 "warning: the mesh is empty" -- "$voxc" run "$work/air.vox" --device lavapipe -o "$work/air.ply"

# compile replaces the package directory as a whole, touches nothing when its bytes would not
# change, and never replaces a directory voxc did not write
(cd "$work" && "$voxc" compile "$src/examples/overhang.vox" -o pkg_spelled >/dev/null 2>&1)
stamp_before=$(find "$work/pkg_spelled" -printf '%i %T@ %p\n' | sort)
expect compile_dot_slash_up_to_date 0 "up to date" -- bash -c 'cd "$1" && "$2" compile "$3" -o ./pkg_spelled/' _ \
    "$work" "$voxc" "$src/examples/overhang.vox"
expect compile_absolute_up_to_date 0 "up to date" -- "$voxc" compile "$src/examples/overhang.vox" -o "$work/pkg_spelled"
expect_same compile_spelling_same_manifest "$work/pkg_overhang/manifest.json" "$work/pkg_spelled/manifest.json"
if [ "$stamp_before" = "$(find "$work/pkg_spelled" -printf '%i %T@ %p\n' | sort)" ]; then
    echo "ok   compile_up_to_date_untouched"; passed=$((passed + 1))
else
    echo "FAIL compile_up_to_date_untouched: inodes or mtimes changed"; failed=$((failed + 1))
fi
expect compile_replaces 0 "wrote" -- "$voxc" compile "$work/air.vox" -o "$work/pkg_spelled"
if [ -e "$work/pkg_spelled/kernels/overhang_sweep0.spv" ] || compgen -G "$work/.pkg_spelled.voxc-tmp.*" >/dev/null; then
    echo "FAIL compile_no_stale_kernels"; failed=$((failed + 1))
else
    echo "ok   compile_no_stale_kernels"; passed=$((passed + 1))
fi
mkdir "$work/notes" && printf 'mine\n' > "$work/notes/todo.txt"
expect compile_foreign_dir 1 "not a voxc package.*todo\.txt" -- "$voxc" compile "$work/air.vox" -o "$work/notes"
expect compile_foreign_dir_kept 0 "^mine$" -- cat "$work/notes/todo.txt"

# lsystem: the expanded string, stats and skeleton of a block; json/obj skeletons written
# atomically and never over an input; limits found at run time are located E0012; crossover
# of grammar (7) A and B at brackets 3,2 prints grammar (8) C and D as blocks that check
expect help_lsystem 0 "--expansions.*--seed|--format" -- "$voxc" lsystem --help
expect help_lsystem_cross 0 "--brackets" -- "$voxc" lsystem cross --help
expect lsystem_text 0 "string \(5798 symbols\)" -- "$voxc" lsystem "$src/examples/lsystem_branches.vox" branches
expect lsystem_endpoints 0 "597 endpoints" -- "$voxc" lsystem "$src/examples/lsystem_branches.vox" branches
expect lsystem_grammar4 0 "string \(13 symbols\): FLFLF\[FUFFDF\]" -- "$voxc" lsystem "$src/examples/lsystem_macros.vox" macros
expect lsystem_octagon 0 "final position \(0\.000000, 0\.000000, 0\.000000\)" -- "$voxc" lsystem "$src/examples/lsystem_line.vox" line
expect lsystem_expansions 0 "string \(7 symbols\): RFRFRFZ" -- "$voxc" lsystem "$src/examples/lsystem_line.vox" line --expansions 3
expect lsystem_truncated 0 "symbols left out" -- "$voxc" lsystem "$src/examples/lsystem_branches.vox" branches --expansions 6
expect lsystem_json 0 "wrote .*skeleton\.json" -- "$voxc" lsystem "$src/examples/lsystem_macros.vox" macros --format json -o "$work/skeleton.json"
expect lsystem_json_valid 0 "" -- python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert len(d['segments']) == 7 and len(d['endpoints']) == 1" "$work/skeleton.json"
expect lsystem_obj 0 "^l 1 2 3" -- "$voxc" lsystem "$src/examples/lsystem_abop_hilbert.vox" hilbert --format obj
expect lsystem_obj_extension 1 "must end in \.obj" -- "$voxc" lsystem "$src/examples/lsystem_macros.vox" macros --format obj -o "$work/skeleton.txt"
expect lsystem_bad_name 1 "no lsystem named 'nope' \(it declares: macros\)" -- "$voxc" lsystem "$src/examples/lsystem_macros.vox" nope
expect lsystem_no_name 1 "needs a FILE and the NAME" -- "$voxc" lsystem "$src/examples/lsystem_macros.vox"
cp "$src/examples/lsystem_macros.vox" "$work/macros.vox"
expect lsystem_out_is_input 1 "is the input" -- "$voxc" lsystem "$work/macros.vox" macros -o "$work/macros.vox"
expect_same lsystem_out_is_input_untouched "$src/examples/lsystem_macros.vox" "$work/macros.vox"
expect lsystem_limit 1 "lsystem_branches\.vox:[0-9]+:[0-9]+: error E0012: lsystem 'branches'.*maxSymbols" -- "$voxc" lsystem "$src/examples/lsystem_branches.vox" branches --expansions 12
# 65 F and two tips per rewrite: 4.3 million symbols (under maxSymbols) but more moves than maxSegments
printf 'world { size = [8, 8, 8]; }\nlsystem many {\n  expansions = 16;\n  production Z { "%sZZ"; }\n}\n' "$(printf 'F%.0s' $(seq 65))" > "$work/segments.vox"
expect lsystem_segments 1 "segments\.vox:2:9: error E0012: lsystem 'many'.*maxSegments" -- "$voxc" lsystem "$work/segments.vox" many
printf 'world { size = [8, 8, 8]; }\nlsystem a {\n  production Z { "FF[RFLFRF[LFFFFZ]FZ]F[LFZ]"; }\n}\n' > "$work/gram7a.vox"
printf 'world { size = [8, 8, 8]; }\nlsystem b {\n  production Z { "FF[RFZ]F[LFLFRFFLFRFZ]"; }\n}\n' > "$work/gram7b.vox"
expect lsystem_cross_c 0 '"FF\[RFLFRF\[LFFFFZ\]FZ\]F\[LFLFRFFLFRFZ\]"' -- "$voxc" lsystem cross "$work/gram7a.vox:a" "$work/gram7b.vox:b" --brackets 3,2
expect lsystem_cross_d 0 '"FF\[RFZ\]F\[LFZ\]"' -- "$voxc" lsystem cross "$work/gram7a.vox:a" "$work/gram7b.vox:b" --brackets 3,2
{ echo 'world { size = [8, 8, 8]; }'; "$voxc" lsystem cross "$work/gram7a.vox:a" "$work/gram7b.vox:b" --brackets 3,2; } > "$work/crossed.vox"
expect lsystem_cross_checks 0 "ok" -- "$voxc" check "$work/crossed.vox"
expect lsystem_cross_range 1 "bracket 4" -- "$voxc" lsystem cross "$work/gram7a.vox:a" "$work/gram7b.vox:b" --brackets 4,2
expect lsystem_cross_reference 1 "FILE:NAME" -- "$voxc" lsystem cross "$work/gram7a.vox" "$work/gram7b.vox:b" --brackets 1,1
# lsystem_cave: the example carves a non-empty, watertight cave, the same at every chunk size
expect lsystem_cave_mesh 0 "[1-9][0-9]* triangles, 0 boundary edges, 0 non-manifold edges.*watertight" -- \
    "$voxc" run "$src/examples/lsystem_cave.vox" --device lavapipe --chunk 8 -o "$work/lsystem_cave8.ply" \
    --voxels "$work/lsystem_cave8.npy"
expect lsystem_cave_chunk_32 0 "" -- "$voxc" run "$src/examples/lsystem_cave.vox" --device lavapipe --voxels "$work/lsystem_cave.npy"
expect_same lsystem_cave_chunk_8_vs_32 "$work/lsystem_cave.npy" "$work/lsystem_cave8.npy"
printf 'world { size = [8, 8, 8]; }\nlsystem a { production Z { "FZ"; } }\npipeline { start; subtract a; }\n' > "$work/carve.vox"
expect lsystem_not_carvable 1 "E0013: 'a' is an lsystem; carving" -- "$voxc" run "$work/carve.vox" -o "$work/carve.ply"
expect_no_file lsystem_not_carvable_no_mesh "$work/carve.ply"
# curves: run and interp report the example's host solves; the same voxels at chunk 8 as at 32
expect curves_run_solves 0 "curves 'cliffs' \(64x32x64 cells, solved on the host\): normals 5 levels, [1-9][0-9]* V-cycles, max residual [0-9.e+-]+ -> [0-9.e+-]+; parameters" -- \
    "$voxc" run "$src/examples/curves_cliff.vox" --device lavapipe --chunk 8 -o "$work/curves_cliff8.ply" \
    --voxels "$work/curves_cliff8.npy"
expect curves_interp_solves 0 "curves 'cliffs' .*parameters 5 levels" -- "$voxc" interp "$src/examples/curves_cliff.vox"
# --trace: per solve the five levels' full-multigrid residuals, coarsest first, then each V-cycle's
expect curves_interp_trace_levels 0 "  normals full multigrid per level, coarsest first: 4x2x4 [0-9.e+-]+, 8x4x8 [0-9.e+-]+, 16x8x16 [0-9.e+-]+, 32x16x32 [0-9.e+-]+, 64x32x64 [0-9.e+-]+$" -- \
    "$voxc" interp "$src/examples/curves_cliff.vox" --trace --trace-limit 0
expect curves_interp_trace_cycles 0 "  parameters max residual: full multigrid [0-9.e+-]+, V-cycle 1 [0-9.e+-]+" -- \
    "$voxc" interp "$src/examples/curves_cliff.vox" --trace --trace-limit 0
# the solve runs after the check, as a phase of its own
expect curves_solve_phase 0 "solve +[0-9.]+  curves and terrain blocks" -- "$voxc" run "$src/examples/curves_cliff.vox" --device lavapipe \
    --timings --voxels "$work/curves_cliff.npy"
expect_same curves_cliff_chunk_8_vs_32 "$work/curves_cliff.npy" "$work/curves_cliff8.npy"
# --solve-on device: every curves pass on lavapipe, the host's voxels but for the noise
# displacement's last bits (warped_fbm's exp2, docs/curves.md "What runs where"); --no-cache, or the
# run reads the host's solve that an earlier run left in the solve cache
expect curves_solve_on_device 0 "curves 'cliffs' \(64x32x64 cells, solved, its global passes on 'llvmpipe" -- \
    "$voxc" run "$src/examples/curves_cliff.vox" --device lavapipe --solve-on device --no-cache --voxels "$work/curves_cliff_device.npy"
expect curves_solve_on_device_close_voxels 0 "^ok$" -- /usr/bin/python3 -c "
import numpy as np, sys
a, b = np.load(sys.argv[1]), np.load(sys.argv[2])
assert a.shape == b.shape and np.abs(a - b).max() <= 1e-5 and (a != b).mean() < 0.05, np.abs(a - b).max()
print('ok')" "$work/curves_cliff.npy" "$work/curves_cliff_device.npy"
expect curves_solve_on_bad 1 "--solve-on: gpu not in \{device,host\}" -- \
    "$voxc" run "$src/examples/curves_cliff.vox" --solve-on gpu --voxels "$work/curves_bad.npy"
# --dump: solved channels as .npy that NumPy (Debian's python3-numpy) reads; the density channel
# is the voxels (the example sets its whole grid), normals are unit, the raw distance is finite
# (every cell is reached), rock (< 0) at the bottom and air (> 0) at the top
expect curves_dump 0 "wrote .*curves_ny\.npy" -- "$voxc" interp "$src/examples/curves_cliff.vox" \
    --voxels "$work/curves_dump_voxels.npy" --dump density="$work/curves_density.npy" \
    --dump cliffs.normal_x="$work/curves_nx.npy" --dump normal_y="$work/curves_ny.npy" \
    --dump normal_z="$work/curves_nz.npy" --dump distance="$work/curves_distance.npy"
expect curves_dump_numpy 0 "^ok$" -- /usr/bin/python3 -c "
import numpy as np, sys
v, d, x, y, z, s = (np.load(p) for p in sys.argv[1:])
assert d.dtype == np.float32 and d.shape == (64, 32, 64) == s.shape == y.shape, d.shape
assert (d == v).all()
n = np.sqrt(x * x + y * y + z * z)
assert np.abs(n - 1).max() < 1e-5, np.abs(n - 1).max()
assert np.isfinite(s).all() and (s[:, 0, :] < 0).all() and (s[:, -1, :] > 0).all()
print('ok')" "$work/curves_dump_voxels.npy" "$work/curves_density.npy" "$work/curves_nx.npy" "$work/curves_ny.npy" \
    "$work/curves_nz.npy" "$work/curves_distance.npy"
expect curves_dump_unknown_channel 1 "--dump 'pressure=.*': unknown channel 'pressure'; the channels are density, normal_x" -- \
    "$voxc" interp "$src/examples/curves_cliff.vox" --dump pressure="$work/curves_p.npy"
expect curves_dump_unknown_block 1 "--dump rocks.density: the file has no curves block 'rocks'" -- \
    "$voxc" run "$src/examples/curves_cliff.vox" --device lavapipe --dump rocks.density="$work/curves_rocks.npy"
expect_no_file curves_dump_unknown_block_no_file "$work/curves_rocks.npy"
expect curves_dump_region 1 "interp: --dump writes a curves block's whole box, which a --region run does not keep" -- \
    "$voxc" interp "$src/examples/curves_cliff.vox" --region 0,0,0:8,8,8 --dump density="$work/curves_region.npy"
printf 'world { size = [8, 8, 8]; }\ncurves c { box = [[0, 0, 0], [7, 7, 8]]; }\npipeline { start; union c; }\n' > "$work/curves_box.vox"
expect curves_box_outside 1 "curves_box\.vox:2:18: error E0007: the box \[0, 0, 0\] to \[7, 7, 8\]" -- \
    "$voxc" run "$work/curves_box.vox" -o "$work/curves_box.ply"
expect_no_file curves_box_no_mesh "$work/curves_box.ply"

# evolve: a generation of variants, each a .vox that checks, with previews; the same inputs give
# the same files; picks continue into the next generation
expect trace_lsystem_lengths 0 "lsystem net after 3 expansions: 358 symbols" -- "$voxc" interp "$src/examples/lsystem_cave.vox" --trace-lsystem net
printf 'world { size = [8, 8, 8]; }\nlsystem net {\n  seed = 3;\n  expansions = 2;\n  production Z { "CZ"; "HZ"; }\n  macro C { "FLFZ" tunnel 1; "FRFZ" tunnel 1; }\n  macro H { "FUFZ" room 1; }\n}\n' > "$work/choices.vox"
expect trace_lsystem_choices 0 "lsystem net expansion 2: symbol Z at [0-9]+ took production [12] of 2" -- "$voxc" interp "$work/choices.vox" --trace-lsystem net
expect trace_lsystem_unknown 1 "no lsystem named 'nope' \(it declares: net\)" -- "$voxc" interp "$work/choices.vox" --trace-lsystem nope
# --seed is the file's seed: a carve (seeded while checking) comes out as if the file said it
sed 's/  seed = 7;/  seed = 9;/' "$src/examples/lsystem_cave.vox" > "$work/cave_seed9.vox"
"$voxc" interp "$work/cave_seed9.vox" --voxels "$work/seed9_file.npy" >/dev/null 2>&1
expect seed_override_run 0 "" -- "$voxc" interp "$src/examples/lsystem_cave.vox" --seed 9 --voxels "$work/seed9_flag.npy"
expect_same seed_override_is_the_file_seed "$work/seed9_file.npy" "$work/seed9_flag.npy"
"$voxc" interp "$src/examples/lsystem_cave.vox" --voxels "$work/seed7.npy" >/dev/null 2>&1
expect seed_override_changes_the_carve 1 "" -- cmp -s "$work/seed7.npy" "$work/seed9_flag.npy"
# terrain: a block's maps as files, written together or not at all
expect terrain_maps 0 "terrain 'valley': levels 2..8 \(256\^2 cells\), [0-9]+ erosion steps" -- "$voxc" terrain "$src/examples/valley.vox" valley --heightmap "$work/valley.png" --height "$work/valley_h.npy" --water "$work/valley_w.npy" --sediment "$work/valley_s.npy" --difference "$work/valley_d.npy"
expect terrain_heightmap_16bit 0 "" -- python3 -c "import struct,sys; b=open(sys.argv[1],'rb').read(); assert b[:8] == b'\x89PNG\r\n\x1a\n' and struct.unpack('>II', b[16:24]) == (256, 256) and b[24] == 16 and b[25] == 0" "$work/valley.png"
expect terrain_npy 0 "" -- test -s "$work/valley_s.npy"
# the eroded difference: the valley's floor raised by sediment, its slopes cut
expect terrain_difference 0 "^ok$" -- /usr/bin/python3 -c "
import numpy as np, sys
d = np.load(sys.argv[1]) * 40
print('ok' if d.shape == (256, 1, 256) and d.min() < -2 and d.max() > 2 else (d.shape, d.min(), d.max()))" "$work/valley_d.npy"
expect terrain_unknown 1 "no terrain named 'hills' \(it declares: valley\)" -- "$voxc" terrain "$src/examples/valley.vox" hills --heightmap "$work/hills.png"
expect terrain_extension 1 "must end in \.png" -- "$voxc" terrain "$src/examples/valley.vox" valley --heightmap "$work/valley.jpg" --height "$work/valley2.npy"
expect_no_file terrain_extension_nothing_written "$work/valley2.npy"
# Erosion steps on the device (--solve-on device): the same voxels as on the host, bit for bit
# (--no-cache: each run solves, rather than reading the other's table from the solve cache). The
# valley's maps stop at level 6 (64^2 cells) so lavapipe's steps take seconds; vulkan_GpuErosion
# compares every channel of the steps themselves.
sed 's/levels = \[2, 8\];/levels = [2, 6];/' "$src/examples/valley.vox" > "$work/valley_level6.vox"
expect terrain_level6_file 0 "" -- grep -q "levels = \[2, 6\];" "$work/valley_level6.vox"
expect terrain_erosion_on_device 0 "terrain erosion steps ran on llvmpipe" -- \
    "$voxc" run "$work/valley_level6.vox" --device lavapipe --solve-on device --no-cache --voxels "$work/valley_device.npy"
expect terrain_erosion_on_host 0 "solve .* 1 solved, 0 from the cache" -- \
    "$voxc" run "$work/valley_level6.vox" --device lavapipe --solve-on host --no-cache --timings --voxels "$work/valley_host.npy"
expect_same terrain_erosion_device_equals_host "$work/valley_host.npy" "$work/valley_device.npy"
# a package holds the buffers the compiler fills (data/*.bin), and voxc knows them as its own
expect compile_point_sets 0 "wrote [0-9]+ kernels" -- "$voxc" compile "$src/examples/lsystem_cave.vox" -o "$work/cavepkg"
expect compile_point_sets_file 0 "" -- test -s "$work/cavepkg/data/point_sets.bin"
expect compile_point_sets_again 0 "is up to date" -- "$voxc" compile "$src/examples/lsystem_cave.vox" -o "$work/cavepkg"
echo x > "$work/cavepkg/data/notes.txt"
expect compile_foreign_data 1 "voxc did not write 'data/notes.txt'" -- "$voxc" compile "$src/examples/lsystem_cave.vox" -o "$work/cavepkg"
expect help_evolve 0 "--population UINT" -- "$voxc" evolve --help
expect evolve_writes 0 "wrote 4 variants of lsystem 'macros' \(generation 1" -- "$voxc" evolve "$src/examples/lsystem_macros.vox" macros --population 4 -o "$work/gen1"
for k in 1 2 3 4; do
    expect "evolve_variant_${k}_checks" 0 "ok" -- "$voxc" check "$work/gen1/variant_$k.vox"
done
expect evolve_summary 0 "" -- python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['generation'] == 1 and [v['file'] for v in d['variants']] == ['variant_%d.vox' % k for k in range(1, 5)] and all(v['segments'] > 0 for v in d['variants'])" "$work/gen1/generation.json"
expect evolve_pictures 0 "" -- python3 -c "import sys; assert all(open(p, 'rb').read(8) == b'\x89PNG\r\n\x1a\n' for p in sys.argv[1:])" "$work/gen1/contact_sheet.png" "$work/gen1/variant_1.png" "$work/gen1/variant_4.png"
"$voxc" evolve "$src/examples/lsystem_macros.vox" macros --population 4 -o "$work/gen1_again" >/dev/null 2>&1
expect evolve_deterministic 0 "" -- diff -r "$work/gen1" "$work/gen1_again"
expect evolve_next_generation 0 "generation 2" -- "$voxc" evolve "$work/gen1/variant_2.vox" macros --with "$work/gen1/variant_3.vox:macros" --generation 2 --population 3 -o "$work/gen2"
expect evolve_input_inside_output 1 "" -- "$voxc" evolve "$work/gen1/variant_1.vox" macros -o "$work/gen1"
expect_same evolve_input_untouched "$work/gen1/variant_1.vox" "$work/gen1_again/variant_1.vox"
expect evolve_population_range 1 "--population must be 1..64" -- "$voxc" evolve "$src/examples/lsystem_macros.vox" macros --population 0 -o "$work/gen0"
expect_no_file evolve_population_nothing_written "$work/gen0"

finish
