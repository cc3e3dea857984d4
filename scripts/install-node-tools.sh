#!/usr/bin/env bash
# Installs the Node tools the mesh tests run (pinned): Khronos' glTF validator and three.js,
# whose GLTFLoader reads our .glb files as an engine would. They go to .node-tools/ (ignored by
# git); the tests fail, not skip, when they are missing, so CI runs this before testing.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
prefix="$root/.node-tools"
wanted=(gltf-validator@2.0.0-dev.3.10 three@0.187.0)
have() { [ -f "$prefix/node_modules/$1/package.json" ] && grep -q "\"version\": \"$2\"" "$prefix/node_modules/$1/package.json"; }
if have gltf-validator 2.0.0-dev.3.10 && have three 0.187.0; then
  exit 0
fi
command -v npm >/dev/null || { echo "install-node-tools: npm is missing (apt-get install npm)" >&2; exit 1; }
mkdir -p "$prefix"
echo "install-node-tools: installing ${wanted[*]} into $prefix"
npm install --prefix "$prefix" --no-audit --no-fund --no-save --silent "${wanted[@]}"
