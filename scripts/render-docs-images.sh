#!/usr/bin/env bash
# Renders every picture in docs/images that shows an example (docs/examples.md, docs/tutorial.md)
# with `voxc render` on lavapipe (the same pixels on every machine with the same Mesa): ambient
# occlusion and shadows on, and a cut-away (--cut) for every cave example so its passages show.
# Usage: scripts/render-docs-images.sh [VOXC] (default: build/compiler/driver/voxc).
# The flagship's picture is made apart (docs/examples.md gives its command: minutes on 2 cores), as
# are the terrain maps drawn by scripts/shade-terrain.py.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
voxc=${1:-$root/build/compiler/driver/voxc}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for example in overhang cave_grammar terrain ledges fields arch cliff; do
    "$voxc" render "$root/examples/$example.vox" -o "$root/docs/images/$example.png" --size 400x400 --device lavapipe
done
# The cave cut open along its start (x > 16): its mouth in the z = 0 face, the tunnel diving in.
"$voxc" render "$root/examples/cave.vox" -o "$root/docs/images/cave.png" --size 400x400 \
    --cut 'x>16' --camera 110,60,70:16,14,30 --device lavapipe
# The weathered overhang: the example's closing comment's variant (probability 0.35, 12 iterations).
sed -e 's/iterations = 6;/iterations = 12;/' -e 's/^\(  rule [a-z_]* {\)$/\1 probability = 0.35;/' \
    "$root/examples/overhang.vox" > "$work/overhang_weathered.vox"
"$voxc" render "$work/overhang_weathered.vox" -o "$root/docs/images/overhang_weathered.png" --size 400x400 \
    --device lavapipe
# The cave network with the rock above y = 60 cut away, from above its south side.
"$voxc" render "$root/examples/caves.vox" -o "$root/docs/images/caves.png" --size 640x400 \
    --cut 'y>60' --camera 128,260,330:128,40,128 --device lavapipe
# The L-system network and the speleothems it holds, cut open at the turtle's height.
"$voxc" render "$root/examples/lsystem_cave.vox" -o "$root/docs/images/lsystem_cave.png" --size 400x400 \
    --cut 'y>20' --device lavapipe
"$voxc" render "$root/examples/speleothems.vox" -o "$root/docs/images/speleothems.png" --size 400x400 \
    --cut 'y>21' --device lavapipe
# Dey's cave grammar, cut open across the eroded face: the passages' profile.
"$voxc" render "$root/examples/cave_grammar.vox" -o "$root/docs/images/cave_grammar_cut.png" --size 400x400 \
    --cut 'z>32' --camera 110,70,120:36,28,32 --device lavapipe
# The cliff face from the floor's side.
"$voxc" render "$root/examples/curves_cliff.vox" -o "$root/docs/images/curves_cliff.png" --size 400x400 \
    --camera -60,60,120:32,12,32 --device lavapipe
# Into the tunnel's mouth, under the vaulted roof.
"$voxc" render "$root/examples/curves_cave.vox" -o "$root/docs/images/curves_cave.png" --size 400x400 \
    --camera 52,26,-52:32,11,32 --device lavapipe
# Up the terraces' steps.
"$voxc" render "$root/examples/curves_terrace.vox" -o "$root/docs/images/curves_terrace.png" --size 400x400 \
    --camera -40,50,-40:32,12,32 --device lavapipe
# Down the canyon, where the stamped arches span it.
"$voxc" render "$root/examples/arches_between_cliffs.vox" -o "$root/docs/images/arches_between_cliffs.png" \
    --size 400x400 --camera 64,120,-50:64,14,64 --device lavapipe
# The island's cliffs at the water line, where the caves open.
"$voxc" render "$root/examples/sea_caves.vox" -o "$root/docs/images/sea_caves.png" --size 400x400 \
    --camera -50,60,-50:64,18,64 --device lavapipe
# The same island cut just above the water line, the caves' floors flooded.
"$voxc" render "$root/examples/sea_caves.vox" -o "$root/docs/images/sea_caves_cut.png" --size 400x400 \
    --cut 'y>23' --camera -50,90,-50:64,18,64 --device lavapipe
# The mesa's cliff with the mouths of its stamped burrows.
"$voxc" render "$root/examples/mesa_burrows.vox" -o "$root/docs/images/mesa_burrows.png" --size 400x400 \
    --camera -40,45,-40:40,17,40 --device lavapipe
# The mesa cut at the burrows' height: the networks inside the rock.
"$voxc" render "$root/examples/mesa_burrows.vox" -o "$root/docs/images/mesa_burrows_cut.png" --size 400x400 \
    --cut 'y>20' --camera -40,70,-40:40,17,40 --device lavapipe
# The lava tube's mouth under the ridge, in the x = 127 face.
"$voxc" render "$root/examples/canyon.vox" -o "$root/docs/images/canyon.png" --size 640x400 \
    --camera 230,75,110:64,14,56 --device lavapipe
# The range from the north-east, its peak in snow.
"$voxc" render "$root/examples/mountains.vox" -o "$root/docs/images/mountains.png" --size 640x400 \
    --camera 150,90,-40:64,24,64 --device lavapipe
# The imported ridge from the south-east: the arch over the river, the ledge on the far ridge,
# the boulder with the cave coming out through it.
"$voxc" render "$root/examples/imported_ridge.vox" -o "$root/docs/images/imported_ridge.png" --size 640x400 \
    --camera 170,80,170:64,14,64 --device lavapipe
# The road curve through the imported ridge, cut open along it: the tunnel under the crest.
"$voxc" render "$root/examples/carved_ridge.vox" -o "$root/docs/images/carved_ridge.png" --size 640x400 \
    --camera 190,45,30:64,20,36 --cut "x>64" --device lavapipe
# The two boulders in their fillets of earth.
"$voxc" render "$root/examples/boulders.vox" -o "$root/docs/images/boulders.png" --size 640x400 \
    --camera -30,60,-30:40,14,44 --device lavapipe
for example in scene valley; do
    "$voxc" render "$root/examples/$example.vox" -o "$root/docs/images/$example.png" --size 640x400 --device lavapipe
done
# docs/tutorial.md: each step's file as its command draws it.
for step in 01_ground 02_weathering 03_arch 05_cliff 06_valley; do
    "$voxc" render "$root/examples/tutorial/$step.vox" -o "$root/docs/images/tutorial-${step%%_*}.png" --size 640x360 \
        --device lavapipe
done
"$voxc" render "$root/examples/tutorial/04_cave.vox" -o "$root/docs/images/tutorial-04.png" --size 640x360 \
    --cut 'z>104' --device lavapipe
