#!/usr/bin/env bash
# Usage: stage_debug_tests.sh VOXC THIS_DIR. Prints "N passed, N failed" last.
set -u
voxc=$1
here=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export VOXC_CACHE_DIR="$work/cache"
. "$here/../support/expect.sh"
scene="$here/weathering.vox"
stages=("start;" "weather;" "subtract tunnel material sand;" "paint band material moss;")
/usr/bin/python3 -c "import numpy" || { fail "Debian's python3 with numpy (scripts/install-deps.sh) is needed to compare the grids"; finish; }

# The scene with its pipeline cut after stage K, written out as a user would.
truncated() {
    local k=$1 out="$work/cut$1.vox"
    sed '/^pipeline {/,$d' "$scene" > "$out"
    { echo "pipeline {"; for ((i = 0; i <= k; i++)); do echo "  ${stages[$i]}"; done; echo "}"; } >> "$out"
    echo "$out"
}

# --after K is the truncated pipeline, bit for bit, on the interpreter and on the device (lavapipe).
for k in 0 1 2 3; do
    cut=$(truncated $k)
    expect "interp_cut_$k" 0 "" -- "$voxc" interp "$cut" --voxels "$work/cut$k.npy" --materials "$work/cut${k}m.npy"
    expect "interp_after_$k" 0 "the grid after stage $k of 3" -- "$voxc" interp "$scene" --after $k \
        --voxels "$work/after$k.npy" --materials "$work/after${k}m.npy"
    expect_same "interp_after_${k}_is_the_cut_voxels" "$work/cut$k.npy" "$work/after$k.npy"
    expect_same "interp_after_${k}_is_the_cut_materials" "$work/cut${k}m.npy" "$work/after${k}m.npy"
    expect "run_after_$k" 0 "the grid after stage $k of 3" -- "$voxc" run "$scene" --device lavapipe --after $k \
        --voxels "$work/run$k.npy" --materials "$work/run${k}m.npy"
    expect_same "run_after_${k}_is_the_cut_voxels" "$work/cut$k.npy" "$work/run$k.npy"
    expect_same "run_after_${k}_is_the_cut_materials" "$work/cut${k}m.npy" "$work/run${k}m.npy"
done

# A stage by its entry or its name is the stage at that position.
expect after_by_name 0 "" -- "$voxc" interp "$scene" --after weather --voxels "$work/byname.npy"
expect_same after_by_name_is_stage_1 "$work/after1.npy" "$work/byname.npy"
expect after_by_entry 0 "" -- "$voxc" interp "$scene" --after "subtract tunnel" --voxels "$work/byentry.npy"
expect_same after_by_entry_is_stage_2 "$work/after2.npy" "$work/byentry.npy"
expect after_unknown 1 "--after 'wether': no such pipeline stage \(the stages are: 0 start, 1 weather, 2 subtract tunnel, 3 paint band\); did you mean 'weather'\?" \
    -- "$voxc" interp "$scene" --after wether
expect after_out_of_range 1 "the pipeline has 4 stages, 0..3" -- "$voxc" interp "$scene" --after 4
expect after_and_diff 1 "give one" -- "$voxc" interp "$scene" --after 1 --diff 2

# --diff K: its counts, by kind and material, and its box equal a direct comparison of the grids
# after K-1 and after K (all air before stage 0); run prints the same report as interp.
count_changes() { # BEFORE.npy BEFORE_MATERIALS.npy AFTER.npy AFTER_MATERIALS.npy
    /usr/bin/python3 - "$@" <<'PY'
import sys, numpy as np
def load(path, shape=None):
    return np.load(path) if path != "-" else None
d0, m0, d1, m1 = (load(p) for p in sys.argv[1:5])
if d0 is None:
    d0, m0 = np.zeros_like(d1), np.zeros_like(m1)
s0, s1 = d0 > 0.5, d1 > 0.5
carved = s0 & ~s1
filled = ~s0 & s1
material = (s0 == s1) & (m0 != m1)
density = (s0 == s1) & (m0 == m1) & (d0.view(np.uint32) != d1.view(np.uint32))
changed = carved | filled | material | density
names = {0: "none", 1: "rock", 2: "sand", 3: "moss"}
def by(mask, mats):
    ids, counts = np.unique(mats[mask], return_counts=True)
    return ", ".join(f"{names[int(i)]} {int(c)}" for i, c in zip(ids, counts))
print(f"changed voxels: {int(changed.sum())}")
if carved.any(): print(f"carved: {int(carved.sum())} (was {by(carved, m0)})")
if filled.any(): print(f"filled: {int(filled.sum())} (now {by(filled, m1)})")
if material.any():
    pairs = sorted({(int(a), int(b)) for a, b in zip(m0[material], m1[material])})
    text = ", ".join(f"{names[a]} -> {names[b]} {int(((m0 == a) & (m1 == b) & material).sum())}" for a, b in pairs)
    print(f"material changed: {int(material.sum())} ({text})")
if density.any(): print(f"density changed: {int(density.sum())} (now {by(density, m1)})")
if changed.any():
    # voxc's .npy files have the shape (x, y, z)
    xs, ys, zs = np.nonzero(changed)
    print(f"box of the change: ({xs.min()},{ys.min()},{zs.min()})..({xs.max()},{ys.max()},{zs.max()})")
PY
}
# The report's lines in the same form: the padding and the box's size dropped.
report_lines() {
    sed -n 's/^  *//; s/:  */: /; s/ inclusive.*//; /^changed voxels\|^carved\|^filled\|^material changed\|^density changed\|^box of the change/p' \
        | sed 's/ (solid: density > 0.5)//'
}
for k in 0 1 2 3; do
    "$voxc" interp "$scene" --diff $k > "$work/diff$k.txt" 2>/dev/null
    if [ $k -eq 0 ]; then
        count_changes - - "$work/after0.npy" "$work/after0m.npy" > "$work/direct$k.txt"
    else
        count_changes "$work/after$((k - 1)).npy" "$work/after$((k - 1))m.npy" "$work/after$k.npy" "$work/after${k}m.npy" > "$work/direct$k.txt"
    fi
    if diff <(report_lines < "$work/diff$k.txt") "$work/direct$k.txt" > "$work/diffdiff$k.txt"; then
        pass "diff_${k}_counts_match_a_direct_comparison"
    else
        fail "diff_${k}_counts_match_a_direct_comparison"; cat "$work/diffdiff$k.txt"
    fi
    grep -q "^changed voxels: [1-9]" "$work/diff$k.txt" && pass "diff_${k}_changed_something" || fail "diff_${k}_changed_something"
    "$voxc" run "$scene" --device lavapipe --diff $k > "$work/rundiff$k.txt" 2>/dev/null
    expect_same "run_diff_${k}_is_interp_diff" "$work/diff$k.txt" "$work/rundiff$k.txt"
done
expect diff_slice_legend 0 "'-' carved  '\+' filled  'm' material changed  '~' density changed" -- "$voxc" interp "$scene" --diff weather --slice y=10
expect diff_slice_marks_carving 0 "^1?[0-9] \|.*-" -- "$voxc" interp "$scene" --diff weather --slice y=10
expect diff_writes_after 0 "" -- "$voxc" interp "$scene" --diff 2 --voxels "$work/diffafter.npy"
expect_same diff_writes_the_grid_after_the_stage "$work/after2.npy" "$work/diffafter.npy"

# Material slices with a legend.
expect material_slice 0 "legend: ' ' not solid \(density <= 0.5\)  '.' none  'r' rock  's' sand  'm' moss" \
    -- "$voxc" interp "$scene" --slice y=6 --channel material
expect material_slice_sand 0 "^ *[0-9]+ \|.*s.*\|$" -- "$voxc" interp "$scene" --slice z=12 --channel material
expect material_slice_run 0 "'m' moss" -- "$voxc" run "$scene" --device lavapipe --slice y=8 --channel material
expect bad_channel 1 "channel" -- "$voxc" interp "$scene" --slice y=6 --channel colour

# Trace filters: a written rule covers its symmetry variants; NAME@VARIANT one of them.
all=$("$voxc" interp "$scene" --trace 2>/dev/null | grep -c "rule chip")
named=$("$voxc" interp "$scene" --trace-rule chip 2>/dev/null | grep -c "rule chip")
variant=$("$voxc" interp "$scene" --trace-rule chip@rot90y 2>/dev/null | grep -c "rule chip")
only=$("$voxc" interp "$scene" --trace-rule chip@rot90y 2>/dev/null | grep -c "rule chip@rot90y")
[ "$all" -gt 0 ] && [ "$named" -eq "$all" ] && pass "trace_rule_covers_variants ($named of $all)" || fail "trace_rule_covers_variants: $named of $all"
[ "$variant" -gt 0 ] && [ "$variant" -lt "$all" ] && [ "$only" -eq "$variant" ] && pass "trace_rule_one_variant ($variant)" \
    || fail "trace_rule_one_variant: $variant ($only named so) of $all"
expect trace_rule_unknown 1 "--trace-rule 'chpi': no rule of that name in any grammar \(the rules are: chip\); did you mean 'chip'\?" \
    -- "$voxc" interp "$scene" --trace-rule chpi
expect trace_variant_unknown 1 "rule 'chip' has no such variant \(its variants are: chip@" -- "$voxc" interp "$scene" --trace-rule chip@rot45y
expect trace_grammar_unknown 1 "did you mean 'weather'" -- "$voxc" interp "$scene" --trace-grammar wether
expect trace_lsystem_unknown 1 "no lsystem named 'lin'; did you mean 'line'" -- "$voxc" interp "$here/../../examples/lsystem_line.vox" --trace-lsystem lin

# -q and -v on every verb; -q leaves stderr empty on success.
for verb in check compile run interp render explore lsystem evolve terrain world view lsp; do
    expect "quiet_flag_$verb" 0 "-q,--quiet" -- "$voxc" "$verb" --help
    expect "verbose_flag_$verb" 0 "-v,--verbose" -- "$voxc" "$verb" --help
done
"$voxc" interp -q "$scene" --voxels "$work/quiet.npy" 2> "$work/quiet.err" >/dev/null
[ $? -eq 0 ] && [ ! -s "$work/quiet.err" ] && pass interp_quiet || { fail interp_quiet; cat "$work/quiet.err"; }

# JSON diagnostics end in a summary record, not one more error.
printf 'world { size = [8, 8, 8]; }\ngrammar g { iteratons = 2; rule r { size = [1, 1, 1]; symbol { [IGN] } transform { [SET 1] } } }\n' > "$work/bad.vox"
"$voxc" check "$work/bad.vox" --diagnostics-format json 2> "$work/bad.json"
expect json_summary_last 0 '^\{"summary":\{"file":"[^"]*bad.vox","errors":1,"warnings":[0-9]+\}\}$' -- tail -1 "$work/bad.json"
if grep -q '"code":""' "$work/bad.json"; then fail "json_no_codeless_error"; else pass json_no_codeless_error; fi
expect json_fixit 0 '"fixits":\[\{"range":\{"start":\{"line":2,"column":13\},"end":\{"line":2,"column":22\}\},"replacement":"iterations"\}\]' \
    -- head -1 "$work/bad.json"
expect text_fixit 1 "      \|             iterations" -- "$voxc" check "$work/bad.vox"

finish
