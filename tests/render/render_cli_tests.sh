#!/usr/bin/env bash
# Usage: render_cli_tests.sh VOXC SOURCE_DIR. `voxc render` as a user runs it: clear errors for bad
# flags with nothing written, and pictures of the requested size. Prints "N passed, N failed" last.
set -u
voxc=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export VOXC_CACHE_DIR="$work/cache"
. "$(dirname "$0")/../support/expect.sh"

# png_size PATH: "WIDTHxHEIGHT" from the IHDR chunk.
png_size() {
    python3 -c 'import struct,sys; d=open(sys.argv[1],"rb").read(24); print("%dx%d" % struct.unpack(">II", d[16:24]))' "$1"
}

# png_compare A B: "max M, differing D of N" for two same-size 8-bit RGB PNGs (tests/support/png_compare.py).
png_compare() { python3 "$(dirname "$0")/../support/png_compare.py" "$@"; }

scene=$src/examples/scene.vox
expect help 0 "--camera" -- "$voxc" render --help
expect bad_camera 1 "--camera front: expected iso, top, side or X,Y,Z:TX,TY,TZ" -- \
    "$voxc" render "$scene" -o "$work/a.png" --camera front --device lavapipe
expect_no_file bad_camera_nothing_written "$work/a.png"
expect same_eye_and_target 1 "the eye and the target are the same point" -- \
    "$voxc" render "$scene" -o "$work/a.png" --camera 1,2,3:1,2,3 --device lavapipe
expect bad_size 1 "--size 1280by720: expected WIDTHxHEIGHT" -- "$voxc" render "$scene" -o "$work/a.png" --size 1280by720
expect zero_size 1 "--size 0x720: expected WIDTHxHEIGHT in pixels, each 1 to 8192" -- \
    "$voxc" render "$scene" -o "$work/a.png" --size 0x720
expect_no_file bad_size_nothing_written "$work/a.png"
expect not_png 1 "must end in" -- "$voxc" render "$scene" -o "$work/a.jpg"
expect no_output 1 "give -o PICTURE.png" -- "$voxc" render "$scene"
printf 'world { size = [8, 8, 8]; }\nrule r { match = nope; }\n' >"$work/bad.vox"
expect located_error 1 "bad\.vox:[0-9]+:[0-9]+: error E[0-9]{4}" -- "$voxc" render "$work/bad.vox" -o "$work/bad.png"
expect_no_file broken_program_nothing_written "$work/bad.png"
expect unwritable 1 "cannot write" -- "$voxc" render "$scene" -o /nonexistent-dir/x.png --device lavapipe

expect iso_validated 0 "validation layer: 0 messages" -- \
    "$voxc" render "$scene" -o "$work/iso.png" --size 320x200 --device lavapipe --validate --wireframe --chunk-borders
expect iso_size 0 "^320x200$" -- png_size "$work/iso.png"
expect top 0 "wrote .*top.png \(64x48" -- "$voxc" render "$scene" -o "$work/top.png" --size 64x48 --camera top --device lavapipe
expect top_again 0 "" -- "$voxc" render "$scene" -o "$work/top2.png" --size 64x48 --camera top --device lavapipe
expect deterministic 0 "" -- cmp "$work/top.png" "$work/top2.png"
expect plain_top 0 "" -- "$voxc" render "$scene" -o "$work/plain-top.png" --size 64x48 --camera top --device lavapipe --no-ao --no-shadows
expect side 0 "" -- "$voxc" render "$scene" -o "$work/side.png" --size 64x48 --camera side --device lavapipe
expect top_differs_from_side 1 "" -- cmp -s "$work/top.png" "$work/side.png"
expect explicit_camera 0 "camera 150,90,150:48,20,48" -- \
    "$voxc" render "$scene" -o "$work/eye.png" --size 64x48 --camera 150,90,150:48,20,48 --device lavapipe
expect mesh_run 0 "" -- "$voxc" run "$scene" -o "$work/scene.ply" --device lavapipe
expect mesh_file 0 "wrote .*mesh.png" -- "$voxc" render "$work/scene.ply" -o "$work/mesh.png" --size 64x48 --device lavapipe
# A mesh file has no voxels to measure light in: compared with the program drawn without it.
expect program_same_size 0 "" -- "$voxc" render "$scene" -o "$work/program.png" --size 64x48 --device lavapipe --no-ao --no-shadows
# The PLY's colours are its materials' as bytes: the two pictures differ by rounding at most.
expect mesh_file_in_its_colours 0 "^max [0-2], " -- png_compare "$work/mesh.png" "$work/program.png"
expect mesh_file_no_chunks 1 "--chunk-borders needs a .vox file" -- \
    "$voxc" render "$work/scene.ply" -o "$work/mesh2.png" --chunk-borders
expect mesh_file_no_edits 1 "--edits needs a .vox file" -- \
    "$voxc" render "$work/scene.ply" --edits "$src/examples/scene.edits.json" -o "$work/edits.png"
expect mesh_file_no_cut 1 "--cut needs a .vox file" -- "$voxc" render "$work/scene.ply" -o "$work/cut.png" --cut x>3
expect_no_file mesh_file_no_cut_nothing_written "$work/cut.png"
# Every mesh format voxc writes is drawn as the .ply is, in its materials' colours (the OBJ's .mtl,
# the .glb's linear base colours). Those two give materials to faces, so a vertex on a border
# between materials is drawn in each face's colour, where the .ply and the program blend the
# vertex's own: the same picture from both, and at most 5% of the program's pixels differ by more
# than rounding.
# few_differ A B: "ok" when at most 5% of the pixels differ by more than 2.
few_differ() {
    local out; out=$(png_compare "$1" "$2" 2)
    echo "$out"
    python3 -c 'import sys; d, n = int(sys.argv[1]), int(sys.argv[2]); print("ok" if 0 < n and d * 20 <= n else "too many")' \
        "$(echo "$out" | sed -E 's/.*differing ([0-9]+) of ([0-9]+).*/\1/')" "$(echo "$out" | sed -E 's/.*differing ([0-9]+) of ([0-9]+).*/\2/')"
}
expect mesh_glb 0 "" -- "$voxc" run "$scene" -o "$work/scene.glb" --device lavapipe
expect mesh_glb_drawn 0 "wrote .*glb.png \(64x48, 67560 triangles" -- \
    "$voxc" render "$work/scene.glb" -o "$work/glb.png" --size 64x48 --device lavapipe
expect mesh_glb_in_its_colours 0 "^ok$" -- few_differ "$work/glb.png" "$work/program.png"
expect mesh_obj 0 "" -- "$voxc" run "$scene" -o "$work/scene.obj" --device lavapipe
mv "$work/scene.obj" "$work/scene.OBJ"
expect mesh_obj_drawn 0 "wrote .*obj.png \(64x48, 67560 triangles" -- \
    "$voxc" render "$work/scene.OBJ" -o "$work/obj.png" --size 64x48 --device lavapipe
expect mesh_obj_same_as_glb 0 "^max 0, " -- png_compare "$work/obj.png" "$work/glb.png"
expect mesh_glb_no_region 1 "--region needs a .vox file" -- "$voxc" render "$work/scene.glb" -o "$work/r.png" --region 0,0,0:8,8,8
printf 'glTF not really' >"$work/broken.glb"
expect mesh_broken_glb 1 "'.*broken.glb' is not a mesh voxc can read" -- "$voxc" render "$work/broken.glb" -o "$work/broken.png"
expect_no_file mesh_broken_glb_nothing_written "$work/broken.png"

# Light measured in the voxels and cut-aways (tests/render/LightingTest.cpp checks what they show).
expect bad_cut 1 "--cut x=4: not a plane or a box; expected x>N" -- \
    "$voxc" render "$scene" -o "$work/cut.png" --cut x=4 --device lavapipe
expect_no_file bad_cut_nothing_written "$work/cut.png"
expect lit_differs_from_plain 1 "" -- cmp -s "$work/top.png" "$work/plain-top.png"
expect cut_validated 0 "cut away [0-9]+ voxels \(z>40\)" -- \
    "$voxc" render "$scene" -o "$work/cut.png" --size 64x48 --cut 'z>40' --device lavapipe --validate -v
expect cut_differs 1 "" -- cmp -s "$work/cut.png" "$work/program.png"

# One box of the world, as `run --region` computes it.
expect region 0 "region 10,0,10:60,64,60 of the world" -- \
    "$voxc" render "$scene" -o "$work/region.png" --size 64x48 --region 10,0,10:60,64,60 --device lavapipe
expect region_differs 1 "" -- cmp -s "$work/region.png" "$work/program.png"
expect region_outside 1 "the box must lie inside the world" -- \
    "$voxc" render "$scene" -o "$work/far.png" --region 0,0,0:500,10,10 --device lavapipe
expect_no_file region_outside_nothing_written "$work/far.png"
expect mesh_file_no_region 1 "--region needs a .vox file" -- \
    "$voxc" render "$work/scene.ply" -o "$work/r.png" --region 0,0,0:8,8,8

finish
