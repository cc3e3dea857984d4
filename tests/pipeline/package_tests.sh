#!/usr/bin/env bash
# Usage: package_tests.sh BUILD_DIR SOURCE_DIR WITH_LIBVOXC(0|1). Installs voxc from BUILD_DIR into
# a temporary prefix, then uses it as a project would (docs/embedding.md): a CMake project builds
# a ruleset with find_package(voxc) and voxc_add_ruleset, rebuilding exactly when an input
# changed; with libvoxc, the C example in examples/embed links against the installed library
# through pkg-config (and through CMake), generates a grid, and loads a compiled package (refusing
# a missing, foreign, corrupt or other version's one). Prints "N passed, N failed" last.
set -u
build=$1
src=$2
with_libvoxc=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/../support/expect.sh"

prefix=$work/prefix
expect install 0 "" -- cmake --install "$build" --prefix "$prefix"
expect installed_voxc 0 "voxc 0.1.0" -- "$prefix/bin/voxc" --version
# OpenVDB comes in with the module installed beside voxc's libraries, loaded by a mesh input's check
# (voxc/vdb/Vdb.h), from the prefix and not from the build.
expect installed_openvdb_module 0 "calling init: $prefix/lib[^ ]*/voxc/libvoxc-openvdb\.so" -- \
    env LD_DEBUG=libs "$prefix/bin/voxc" check "$src/examples/boulders.vox"

# A project that builds a ruleset: compiled once, then only when the .vox or its rule file changes.
cp -r "$src/tests/pipeline/project" "$work/proj"
expect project_configure 0 "" -- cmake -S "$work/proj" -B "$work/proj/build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix"
expect project_build 0 "voxc: compiling world.vox" -- cmake --build "$work/proj/build"
expect project_package 0 "" -- test -s "$work/proj/build/packages/world/manifest.json"
expect project_nothing_changed 0 "no work to do" -- cmake --build "$work/proj/build"
touch "$work/proj/world.vox"
expect project_vox_touched 0 "voxc: compiling world.vox" -- cmake --build "$work/proj/build"
expect project_then_nothing 0 "no work to do" -- cmake --build "$work/proj/build"
touch "$work/proj/tunnels.rules"
expect project_rules_touched 0 "voxc: compiling world.vox" -- cmake --build "$work/proj/build"
expect project_rules_then_nothing 0 "no work to do" -- cmake --build "$work/proj/build"
sed -i 's/seed = 3;/seed = 4;/' "$work/proj/world.vox"
expect project_vox_edited 0 "voxc: compiling world.vox" -- cmake --build "$work/proj/build"
expect project_new_seed 0 "" -- grep -q '"seed": 4' "$work/proj/build/packages/world/manifest.json"
printf 'pipeline { nope; }\n' >> "$work/proj/world.vox"
expect project_error_located 1 "world.vox:[0-9]+:[0-9]+: error E" -- cmake --build "$work/proj/build"

# The same project with the Makefile generator.
cp -r "$src/tests/pipeline/project" "$work/projmake"
expect make_configure 0 "" -- cmake -S "$work/projmake" -B "$work/projmake/build" -G "Unix Makefiles" -DCMAKE_PREFIX_PATH="$prefix"
expect make_build 0 "voxc: compiling world.vox" -- cmake --build "$work/projmake/build"
expect make_nothing_changed 0 "" -- bash -c "! cmake --build '$work/projmake/build' | grep -q 'voxc: compiling'"
touch "$work/projmake/tunnels.rules"
expect make_rules_touched 0 "voxc: compiling world.vox" -- cmake --build "$work/projmake/build"

if [ "$with_libvoxc" = 1 ]; then
    lib=$(echo "$prefix"/lib*/libvoxc.so.0.1.0 "$prefix"/lib/*/libvoxc.so.0.1.0)
    lib=$(ls $lib 2>/dev/null | head -1)
    expect libvoxc_installed 0 "" -- test -f "$lib"
    # only the C API is exported; the C++ inside stays private
    expect libvoxc_exports_only_c_api 0 "" -- bash -c "nm -D --defined-only '$lib' | awk '{print \$3}' | grep -v '^voxc_' | grep -v '^_init\$\|^_fini\$' | (! grep .)"
    pcdir=$(dirname "$(ls "$prefix"/lib*/pkgconfig/voxc.pc "$prefix"/lib/*/pkgconfig/voxc.pc 2>/dev/null | head -1)")
    # Every library libvoxc.so needs at run time is in the .pc file (Requires.private or
    # Libs.private), so pkg-config --static lists it; libc, the loader and libgcc_s come with the compiler.
    needed=$(readelf -d "$lib" | sed -nE 's/.*NEEDED.*\[lib([^.]+)\.so.*/\1/p' | grep -vx 'c\|gcc_s\|ld-linux-x86-64')
    static_libs=$(PKG_CONFIG_PATH="$pcdir" pkg-config --static --libs voxc)
    for name in $needed; do
        expect "pc_lists_needed_$name" 0 "" -- bash -c "grep -qw -- '-l$name' <<<'$static_libs'"
    done
    expect pc_lists_fmt_and_antlr 0 "" -- bash -c "grep -qw -- '-lfmt' <<<'$static_libs' && grep -qw -- '-lantlr4-runtime' <<<'$static_libs'"
    cp -r "$src/examples/embed" "$work/embed"
    expect embed_make 0 "" -- env PKG_CONFIG_PATH="$pcdir" make -C "$work/embed"
    expect embed_links_installed 0 "$prefix" -- ldd "$work/embed/embed"
    # The example's mesh is voxc run's, vertex for vertex (the same host marching cubes).
    "$prefix/bin/voxc" run "$src/examples/overhang.vox" -o "$work/overhang.ply" --mesh-on host > "$work/run.out" 2>&1
    counts=$(grep -Eo '[0-9]+ vertices, [0-9]+ triangles' "$work/run.out" | head -1)
    expect embed_vulkan 0 "mesh: $counts" -- "$work/embed/embed" "$src/examples/overhang.vox" vulkan
    expect embed_interpreter 0 "mesh: $counts" -- "$work/embed/embed" "$src/examples/overhang.vox" interpreter
    expect embed_materials 0 "  (sand|grass|dirt|bedrock|sandstone): [0-9]+ triangles" -- "$work/embed/embed" "$src/examples/scene.vox" interpreter
    expect embed_error_message 1 "nope.vox: error E0100" -- "$work/embed/embed" "$work/nope.vox"
    expect embed_openvdb_module 0 "calling init: $prefix/lib[^ ]*/voxc/libvoxc-openvdb\.so" -- \
        env LD_DEBUG=libs "$work/embed/embed" "$src/examples/boulders.vox" interpreter
    expect embed_cmake_configure 0 "" -- cmake -S "$work/embed" -B "$work/embed/build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix"
    expect embed_cmake_build 0 "" -- cmake --build "$work/embed/build"
    expect embed_cmake_runs 0 "grid 32x16x32 at 0,0,0: 8192 of 16384 voxels solid" -- "$work/embed/build/embed" "$src/tests/pipeline/project/world.vox" interpreter
    # A box of the world at odd offsets: the voxels and the mesh of `voxc interp/run --region`.
    box=10,5,3:40,37,29
    "$prefix/bin/voxc" run "$src/examples/overhang.vox" --region "$box" -o "$work/box.ply" --chunk 8 > "$work/box.out" 2>&1
    box_counts=$(grep -Eo '[0-9]+ vertices, [0-9]+ triangles' "$work/box.out" | head -1)
    "$prefix/bin/voxc" interp "$src/examples/overhang.vox" --region "$box" --voxels "$work/box.npy" > /dev/null 2>&1
    box_solid=$(python3 - "$work/box.npy" <<'PY'
import array, struct, sys
data = open(sys.argv[1], "rb").read()
assert data[:6] == b"\x93NUMPY" and data[6] == 1 and b"'<f4'" in data[:128]
header = struct.unpack("<H", data[8:10])[0]
print(sum(1 for d in array.array("f", data[10 + header:]) if d > 0.5))
PY
)
    for backend in vulkan interpreter; do
        "$work/embed/embed" "$src/examples/overhang.vox" $backend "$box" > "$work/box_$backend.out" 2>&1
        expect "embed_region_voxels_$backend" 0 "grid 30x32x26 at 10,5,3: $box_solid of 24960 voxels solid" -- cat "$work/box_$backend.out"
        expect "embed_region_mesh_$backend" 0 "mesh: $box_counts" -- cat "$work/box_$backend.out"
    done
    expect embed_region_outside 1 "not inside the grid" -- "$work/embed/embed" "$src/examples/overhang.vox" vulkan 0,0,0:999,1,1

    # A compiled package loads (its SPIR-V, no GLSL compiler) and generates what its .vox does.
    pkg=$work/overhang_pkg
    expect package_compile 0 "" -- "$prefix/bin/voxc" compile "$src/examples/overhang.vox" -o "$pkg"
    expect embed_package_vulkan 0 "mesh: $counts" -- "$work/embed/embed" "$pkg" vulkan
    expect embed_package_interpreter 0 "mesh: $counts" -- "$work/embed/embed" "$pkg" interpreter
    expect embed_package_region 0 "grid 30x32x26 at 10,5,3: $box_solid of 24960 voxels solid" -- "$work/embed/embed" "$pkg" vulkan "$box"
    # The seed and chunk it was compiled with, and its copy of the rule file, with the sources gone.
    cp -r "$src/tests/pipeline/project" "$work/moved"
    expect package_compile_seed 0 "" -- "$prefix/bin/voxc" compile "$work/moved/world.vox" -o "$work/moved_pkg" --seed 9 --chunk 8
    "$prefix/bin/voxc" run "$work/moved/world.vox" --seed 9 --chunk 8 -o "$work/moved.ply" --mesh-on host > "$work/moved.out" 2>&1
    moved_counts=$(grep -Eo '[0-9]+ vertices, [0-9]+ triangles' "$work/moved.out" | head -1)
    rm -r "$work/moved"
    expect embed_package_seed_chunk_rules 0 "mesh: $moved_counts" -- "$work/embed/embed" "$work/moved_pkg" vulkan
    # Refused with the reason: foreign, another version, corrupt files.
    mkdir "$work/foreign" && echo hi > "$work/foreign/notes.txt"
    expect embed_package_foreign 1 "voxc did not write 'notes.txt'" -- "$work/embed/embed" "$work/foreign"
    broken() { rm -rf "$work/broken"; cp -r "$pkg" "$work/broken"; }
    broken; sed -i 's/"voxc_version": "[^"]*"/"voxc_version": "0.0.1"/' "$work/broken/manifest.json"
    expect embed_package_version 1 "written by voxc 0.0.1 and this is voxc 0.1.0" -- "$work/embed/embed" "$work/broken"
    spv=$(ls "$pkg"/kernels/*.spv | head -1)
    broken; printf '\x01' | dd of="$work/broken/kernels/$(basename "$spv")" bs=1 seek=40 conv=notrunc status=none
    expect embed_package_corrupt_spirv 1 "kernels/$(basename "$spv") does not match its SHA-256" -- "$work/embed/embed" "$work/broken"
    # Edits that keep each file's size (one that changes it is refused before it is read: the
    # manifest gives every file's byte count).
    broken; sed -i '1s/^./ /' "$work/broken/sources/0.vox"
    expect embed_package_edited_source 1 "sources/0.vox does not match its SHA-256" -- "$work/embed/embed" "$work/broken"
    broken; echo "// edited" >> "$work/broken/sources/0.vox"
    expect embed_package_resized_source 1 "sources/0.vox is [0-9]+ bytes and manifest.json says [0-9]+" -- "$work/embed/embed" "$work/broken"
    broken; sed -i '1s/^./ /' "$work/broken/kernels/$(basename "$spv" .spv).comp"
    expect embed_package_edited_glsl 1 "whose GLSL differs from its copy" -- "$work/embed/embed" "$work/broken"
    broken; sed -i 's/"halo": \[/"halo": [1,/' "$work/broken/manifest.json"
    expect embed_package_edited_manifest 1 "manifest.json differs from what its sources compile to" -- "$work/embed/embed" "$work/broken"
fi

finish
