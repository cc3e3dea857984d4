// Checks .glb files as an engine would see them: the Khronos glTF-Validator must report no error,
// no warning and no unused object (degenerate triangles raised to errors), and three.js's
// GLTFLoader must load the mesh with the primitives, attribute counts and normalised colours the
// JSON declares. Usage: node check_glb.mjs NODE_TOOLS_DIR FILE.glb...  Exit 1 on any failure,
// including a missing tool (the tests must fail, not skip, without them).
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const [tools, ...files] = process.argv.slice(2);
if (!tools || files.length === 0) {
  console.error('usage: node check_glb.mjs NODE_TOOLS_DIR FILE.glb...');
  process.exit(1);
}
const load = (relative) => import(pathToFileURL(join(tools, 'node_modules', relative)).href);
let validator, GLTFLoader;
try {
  validator = (await load('gltf-validator/index.js')).default;
  ({ GLTFLoader } = await load('three/examples/jsm/loaders/GLTFLoader.js'));
} catch (e) {
  console.error(`check_glb: the Node tools are missing (run scripts/install-node-tools.sh): ${e.message}`);
  process.exit(1);
}

function glbJson(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const length = view.getUint32(12, true);
  return JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + length)));
}

async function threeLoad(bytes) {
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  return new Promise((resolve, reject) => new GLTFLoader().parse(buffer, '', resolve, reject));
}

let failed = 0;
for (const file of files) {
  const bytes = new Uint8Array(readFileSync(file));
  const problems = [];
  const report = await validator.validateBytes(bytes, {
    uri: file,
    maxIssues: 0,
    severityOverrides: { ACCESSOR_INDEX_TRIANGLE_DEGENERATE: 0 },
  });
  const issues = report.issues;
  for (const m of issues.messages) {
    if (m.severity <= 1 || m.code === 'UNUSED_OBJECT') problems.push(`validator ${m.code} at ${m.pointer ?? ''}: ${m.message}`);
  }

  const json = glbJson(bytes);
  const gltf = await threeLoad(bytes).catch((e) => { problems.push(`three.js: ${e.message ?? e}`); return null; });
  if (gltf) {
    const meshes = [];
    gltf.scene.traverse((o) => { if (o.isMesh) meshes.push(o); });
    const primitives = json.meshes ? json.meshes[0].primitives : [];
    if (meshes.length !== primitives.length) problems.push(`three.js: ${meshes.length} meshes for ${primitives.length} primitives`);
    meshes.forEach((mesh, i) => {
      const p = primitives[i];
      if (!p) return;
      const g = mesh.geometry;
      const count = json.accessors[p.attributes.POSITION].count;
      for (const [name, attribute] of [['position', 'POSITION'], ['normal', 'NORMAL']]) {
        if (!g.attributes[name] || g.attributes[name].count !== count) problems.push(`three.js: primitive ${i} ${attribute} count`);
      }
      if (!g.index || g.index.count !== json.accessors[p.indices].count) problems.push(`three.js: primitive ${i} index count`);
      if (mesh.material.name !== json.materials[p.material].name) problems.push(`three.js: primitive ${i} material name ${mesh.material.name}`);
      const base = json.materials[p.material].pbrMetallicRoughness.baseColorFactor;
      const c = mesh.material.color; // three.js keeps glTF's linear base colour as it is
      if (Math.abs(c.r - base[0]) > 1e-6 || Math.abs(c.g - base[1]) > 1e-6 || Math.abs(c.b - base[2]) > 1e-6)
        problems.push(`three.js: primitive ${i} colour ${c.r},${c.g},${c.b} for base colour ${base}`);
    });
  }
  const summary = `${issues.numErrors} errors, ${issues.numWarnings} warnings, ${issues.numInfos} infos, ${issues.numHints} hints`;
  if (problems.length) {
    failed++;
    console.log(`FAIL ${file}: ${summary}`);
    for (const p of problems) console.log(`  ${p}`);
  } else {
    console.log(`ok   ${file}: ${summary}; three.js loaded ${json.meshes ? json.meshes[0].primitives.length : 0} primitives`);
  }
}
process.exit(failed ? 1 : 0);
