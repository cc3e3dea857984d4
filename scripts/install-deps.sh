#!/usr/bin/env bash
# Installs the Debian packages voxc needs, only those that are missing.
set -euo pipefail
packages=(
  cmake g++ ninja-build pkg-config make # make: examples/embed/Makefile (tests/pipeline)
  antlr4 libantlr4-runtime-dev
  glslang-dev glslang-tools spirv-tools
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers
  libglm-dev libfmt-dev libcli11-dev nlohmann-json3-dev libmeshoptimizer-dev
  libgtest-dev libbenchmark-dev libnoise-dev zlib1g-dev libpng-dev
  libopenvdb-dev libboost-dev # voxc-bench's meshing peer, OpenVDB's volumeToMesh; a mesh block's meshToVolume
  libtinygltf-dev libtiff-dev # mesh blocks read glTF; heightmap blocks read float TIFF
  libopenvdb-tools python3-openvdb # OpenVDB's own vdb_print and Python module open a voxc world tile (tests/world)
  assimp-utils # assimp's command line opens a voxc .glb with its post-processing (tests/mesh/assimp_materials_test.sh)
  libopenmpi-dev openmpi-bin # voxc world under mpirun (tests/world)
  libglfw3-dev libimgui-dev libstb-dev # voxc view: the window and its panel (runtime/viewer)
  xvfb xauth # xvfb-run: the viewer's test under a virtual display (tests/viewer)
  ccache python3-numpy
  python3-dev pybind11-dev python3-pytest python3-setuptools python3-venv python3-pip # the Python module (python/, tests/python)
  python3-matplotlib # docs/python.md's walk-through (tests/python)
  blender # the Blender add-on's headless test (editors/blender); 153 packages, 570 MB installed
  clang libclang-rt-14-dev
  lld # scripts/build.sh links with it
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node runs the glTF validator and three.js in the mesh tests; any Node 18+ with npm will do
# (a Node from elsewhere already brings its own npm, which Debian's npm package would conflict with).
command -v npm >/dev/null || missing+=(nodejs npm)
if [ ${#missing[@]} -ne 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# Without the npm registry the build still works; the mesh_glb_validator test then fails.
"$(dirname "$0")/install-node-tools.sh" ||
  echo "install-deps: warning: the Node tools could not be installed; the mesh_glb_validator test will fail" >&2
