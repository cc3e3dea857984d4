#!/usr/bin/env bash
# Usage: view_test.sh VOXC SOURCE_DIR. `voxc view` under Xvfb on lavapipe, driven by a script as a
# user would drive it: load scene.vox, carve two holes and add a bump by clicking, save the edits, reload after the
# file changes, keep the last world after a typo and show its diagnostics in the panel; a large curves block previewed
# coarse, then refined after a slider move. Its screenshots must equal `voxc render` of the
# replayed edits with the same camera (max channel difference <= 2, docs/viewer.md). Fails, never
# skips, when xvfb-run is missing. Prints "N passed, N failed" last.
set -u
voxc=$1
src=$2
. "$(dirname "$0")/../support/expect.sh"
compare="python3 $(dirname "$0")/../support/png_compare.py"
if ! command -v xvfb-run >/dev/null; then
    fail "xvfb-run is missing: scripts/install-deps.sh installs xvfb"
    finish
fi
work=$(mktemp -d)
viewer_pid=
trap '[ -n "$viewer_pid" ] && kill "$viewer_pid" 2>/dev/null; rm -rf "$work"' EXIT
export VOXC_CACHE_DIR="$work/cache"
size=480x270
camera=150,110,170:48,24,48
cp "$src/examples/scene.vox" "$work/scene.vox"
cp "$src/examples/scene.vox" "$work/original.vox"

# Script errors are located and nothing opens.
printf 'camera iso\nzoom 3\ncarve 1\n' >"$work/bad.txt"
expect script_errors 1 "bad\.txt:2:1: error E0008: unknown action 'zoom'" -- \
    "$voxc" view "$work/scene.vox" --script "$work/bad.txt"
expect script_arity 1 "bad\.txt:3:1: error E0006: 'carve' takes 2 operands, not 1" -- \
    "$voxc" view "$work/scene.vox" --script "$work/bad.txt"
expect no_display 1 "needs a display" -- env -u DISPLAY -u WAYLAND_DISPLAY "$voxc" view "$work/scene.vox" --device lavapipe

cat >"$work/actions.txt" <<ACTIONS
camera $camera
screenshot $work/before.png
set radius 5
carve 240 135
carve 200 150
add 300 190
save-edits $work/edits.json
screenshot $work/carved.png
wait-change 300
screenshot $work/reloaded.png
set bridge.peak 2
screenshot $work/slider.png
screenshot-window $work/slider_window.png
wait-change 300
screenshot $work/typo.png
screenshot-window $work/typo_window.png
undo
screenshot $work/undone.png
ACTIONS
xvfb-run -a -s "-screen 0 1024x768x24" "$voxc" view "$work/scene.vox" --device lavapipe --size $size \
    --script "$work/actions.txt" >"$work/log" 2>&1 &
viewer_pid=$!

# wait_for PATTERN COUNT: until the log holds PATTERN COUNT times (or the viewer ended).
wait_for() {
    for _ in $(seq 1 600); do
        [ "$(grep -c -- "$1" "$work/log")" -ge "$2" ] && return 0
        kill -0 "$viewer_pid" 2>/dev/null || return 1
        sleep 0.5
    done
    return 1
}
if wait_for "waiting for" 1; then
    # The arch's peak drops from 10 to 4: a change the reload must show.
    sed -i 's/  peak = 10;/  peak = 4;/' "$work/scene.vox"
    cp "$work/scene.vox" "$work/changed.vox"
    sed 's/  peak = 4;/  peak = 2;/' "$work/scene.vox" >"$work/slider.vox" # what the slider makes of it
    wait_for "waiting for" 2 && sed -i 's/  radius = 4;/  radius = 4/' "$work/scene.vox" # a missing ';'
fi
wait "$viewer_pid"
code=$?
viewer_pid=
if [ "$code" -eq 0 ]; then pass "viewer_script_ran"; else fail "viewer_script_ran: exit $code"; tail -30 "$work/log"; fi

expect reloaded 0 "view: reloaded .*scene\.vox" -- cat "$work/log"
expect typo_shown 0 "scene\.vox does not check \(the file changed\); keeping the last good world:" -- cat "$work/log"
expect typo_located 0 "scene\.vox:[0-9]+:[0-9]+: error E0001" -- cat "$work/log"
expect carve_visible 0 "differing [1-9]" -- $compare "$work/before.png" "$work/carved.png"
expect last_world_kept 0 "max 0, " -- $compare "$work/slider.png" "$work/typo.png"
# The panel shows the diagnostics: the window changes (thousands of pixels of red text) though the world does not.
expect typo_in_window 0 "differing [0-9]{4,} " -- $compare "$work/slider_window.png" "$work/typo_window.png" 8
expect undo_visible 0 "differing [1-9]" -- $compare "$work/typo.png" "$work/undone.png"
expect slider_reran 0 "view: reloaded .*\(bridge\.peak = 2; " -- cat "$work/log"
expect slider_visible 0 "differing [1-9]" -- $compare "$work/reloaded.png" "$work/slider.png"

# The same pictures from `voxc render` of the replayed edits, same camera and size (the window
# shades without the light render measures in the voxels).
"$voxc" render "$work/original.vox" --edits "$work/edits.json" -o "$work/render_carved.png" --camera $camera \
    --size $size --device lavapipe --no-ao --no-shadows >/dev/null 2>&1
"$voxc" render "$work/changed.vox" --edits "$work/edits.json" -o "$work/render_reloaded.png" --camera $camera \
    --size $size --device lavapipe --no-ao --no-shadows >/dev/null 2>&1
"$voxc" render "$work/slider.vox" --edits "$work/edits.json" -o "$work/render_slider.png" --camera $camera \
    --size $size --device lavapipe --no-ao --no-shadows >/dev/null 2>&1
expect carved_equals_render 0 "max [0-2], " -- $compare "$work/carved.png" "$work/render_carved.png"
expect reloaded_equals_render 0 "max [0-2], " -- $compare "$work/reloaded.png" "$work/render_reloaded.png"
expect slider_equals_render 0 "max [0-2], " -- $compare "$work/slider.png" "$work/render_slider.png"
expect reload_visible 0 "differing [1-9]" -- $compare "$work/carved.png" "$work/reloaded.png"
expect add_takes_the_surface_material 0 '"op": "add".*"material": "grass"' -- cat "$work/edits.json"
expect edits_replay 0 "3 applied on the host, 3 of them changed voxels" -- \
    "$voxc" run "$work/original.vox" --edits "$work/edits.json" -o "$work/replayed.ply" --device lavapipe

# Opening with --edits replays them (read once the file checks, with its materials); a broken
# edits file is a located error before any world is shown.
printf 'camera %s\nscreenshot %s\n' "$camera" "$work/opened.png" >"$work/open.txt"
xvfb-run -a -s "-screen 0 1024x768x24" "$voxc" view "$work/original.vox" --device lavapipe --size $size \
    --edits "$work/edits.json" --script "$work/open.txt" >/dev/null 2>&1
expect opened_edits_equal_render 0 "max [0-2], " -- $compare "$work/opened.png" "$work/render_carved.png"
printf '[{"op": "carve"}\n' >"$work/broken_edits.json"
expect broken_edits_refused 1 "broken_edits\.json:2:1: error E0001" -- xvfb-run -a -s "-screen 0 1024x768x24" \
    "$voxc" view "$work/original.vox" --device lavapipe --edits "$work/broken_edits.json" --script "$work/open.txt"
# Progressive preview: a curves block of 442,368 cells, not in the (fresh) solve cache, is shown
# solved on a box twice as coarse, then replaced by the full solve; a slider move previews again.
# The refined picture is `voxc render`'s of the file with the slider's value written in.
export VOXC_CACHE_DIR="$work/progressive_cache"
cp "$src/tests/viewer/progressive_cliff.vox" "$work/cliff.vox"
sed 's/material = sandstone; amplitude = 1.5; }/material = sandstone; amplitude = 4; }/' "$work/cliff.vox" >"$work/cliff4.vox"
cliff_camera=150,100,170:48,20,48
cat >"$work/progressive.txt" <<ACTIONS
camera $cliff_camera
set cliffs.face.constraint[1].amplitude 4
screenshot $work/cliff_coarse.png
wait-refined 300
screenshot $work/cliff_refined.png
ACTIONS
xvfb-run -a -s "-screen 0 1024x768x24" "$voxc" view "$work/cliff.vox" --device lavapipe --size $size \
    --script "$work/progressive.txt" >"$work/progressive_log" 2>&1
expect progressive_ran 0 "wrote .*cliff_refined\.png" -- cat "$work/progressive_log"
expect preview_shown 0 "\(cliffs\.face\.constraint\[1\]\.amplitude = 4; a coarse preview while the full solve runs; " -- \
    cat "$work/progressive_log"
expect preview_refined 0 "\(the full solve replaced the preview; " -- cat "$work/progressive_log"
"$voxc" render "$work/cliff4.vox" -o "$work/render_cliff4.png" --camera $cliff_camera --size $size \
    --device lavapipe --no-ao --no-shadows >/dev/null 2>&1
expect refined_equals_render 0 "max [0-2], " -- $compare "$work/cliff_refined.png" "$work/render_cliff4.png"
expect coarse_differs 0 "differing [1-9]" -- $compare "$work/cliff_coarse.png" "$work/cliff_refined.png"
finish
