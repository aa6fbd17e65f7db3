// Minimal offscreen renderer for the .glb files of `fftess check --gltf` (docs/cli.md, "3D view"), with Node alone (no
// packages): reads the glTF JSON and BIN chunks, takes the view from the file's camera node (translation, rotation
// quaternion, yfov, aspectRatio, znear), z-buffers the triangles (flat shaded by their normal, the material's base
// colour), then draws LINES and POINTS on top (depth-tested with a small bias). Writes a PNG.
//   node render.js VIEW.glb OUT.png [WIDTH] [X,Y,W,H: a crop, scaled up 3x]
// Not a test and not part of the build: it made docs/images/gltf_terrain_clamp_none.png.
const fs = require('fs'), zlib = require('zlib');
const [,, inPath, outPath, W0, crop] = process.argv;
const buf = fs.readFileSync(inPath);
const jsonLen = buf.readUInt32LE(12);
const gltf = JSON.parse(buf.slice(20, 20 + jsonLen).toString());
const binStart = 20 + jsonLen + 8;
const bin = buf.slice(binStart);
function acc(i) {
  const a = gltf.accessors[i], v = gltf.bufferViews[a.bufferView];
  const off = (v.byteOffset || 0) + (a.byteOffset || 0);
  if (a.componentType === 5126) return new Float32Array(bin.buffer, bin.byteOffset + off, a.count * 3);
  return new Uint32Array(bin.buffer, bin.byteOffset + off, a.count);
}
const camNode = gltf.nodes.find(n => n.camera !== undefined);
const cam = gltf.cameras[camNode.camera].perspective;
const W = parseInt(W0 || '960'), H = Math.round(W / cam.aspectRatio);
const [qx, qy, qz, qw] = camNode.rotation, t = camNode.translation;
// rotation matrix columns (camera axes in world)
const R = [[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
           [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
           [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]];
const f = 1 / Math.tan(cam.yfov / 2);
function project(x, y, z) { // world -> [sx, sy, depth] (depth = view-space distance)
  const dx = x - t[0], dy = y - t[1], dz = z - t[2];
  const cx = R[0][0] * dx + R[1][0] * dy + R[2][0] * dz; // R^T * d
  const cy = R[0][1] * dx + R[1][1] * dy + R[2][1] * dz;
  const cz = R[0][2] * dx + R[1][2] * dy + R[2][2] * dz;
  const w = -cz;
  if (w < cam.znear) return null;
  return [(cx * f / cam.aspectRatio / w * 0.5 + 0.5) * W, (0.5 - cy * f / w * 0.5) * H, w];
}
const img = new Float32Array(W * H * 3).fill(0.92), zb = new Float32Array(W * H).fill(Infinity);
const light = [0.3, 0.85, -0.4]; { const l = Math.hypot(...light); light.forEach((v, i) => light[i] = v / l); }
function tri(p0, p1, p2, col, shade) {
  const minX = Math.max(0, Math.floor(Math.min(p0[0], p1[0], p2[0]))), maxX = Math.min(W - 1, Math.ceil(Math.max(p0[0], p1[0], p2[0])));
  const minY = Math.max(0, Math.floor(Math.min(p0[1], p1[1], p2[1]))), maxY = Math.min(H - 1, Math.ceil(Math.max(p0[1], p1[1], p2[1])));
  const area = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]);
  if (area === 0) return;
  for (let y = minY; y <= maxY; ++y) for (let x = minX; x <= maxX; ++x) {
    const px = x + 0.5, py = y + 0.5;
    let w0 = ((p1[0] - px) * (p2[1] - py) - (p2[0] - px) * (p1[1] - py)) / area;
    let w1 = ((p2[0] - px) * (p0[1] - py) - (p0[0] - px) * (p2[1] - py)) / area;
    let w2 = 1 - w0 - w1;
    if (w0 < 0 || w1 < 0 || w2 < 0) continue;
    const z = 1 / (w0 / p0[2] + w1 / p1[2] + w2 / p2[2]);
    const k = y * W + x;
    if (z >= zb[k]) continue;
    zb[k] = z;
    for (let c = 0; c < 3; ++c) img[k * 3 + c] = col[c] * shade;
  }
}
function dot(x, y, col, size, z) {
  for (let yy = Math.floor(y - size); yy <= y + size; ++yy) for (let xx = Math.floor(x - size); xx <= x + size; ++xx) {
    if (xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
    const k = yy * W + xx;
    if (z > zb[k] * 1.002 + 0.01) continue;
    for (let c = 0; c < 3; ++c) img[k * 3 + c] = col[c];
  }
}
const overlay = [];
function drawMesh(meshIdx) {
  for (const prim of gltf.meshes[meshIdx].primitives) {
    const P = acc(prim.attributes.POSITION), I = prim.indices !== undefined ? acc(prim.indices) : null;
    const col = gltf.materials[prim.material].pbrMetallicRoughness.baseColorFactor;
    const mode = prim.mode === undefined ? 4 : prim.mode;
    if (mode === 4) {
      for (let k = 0; k + 2 < I.length; k += 3) {
        const a = I[k] * 3, b = I[k + 1] * 3, c = I[k + 2] * 3;
        const p0 = project(P[a], P[a + 1], P[a + 2]), p1 = project(P[b], P[b + 1], P[b + 2]), p2 = project(P[c], P[c + 1], P[c + 2]);
        if (!p0 || !p1 || !p2) continue;
        const ux = P[b] - P[a], uy = P[b + 1] - P[a + 1], uz = P[b + 2] - P[a + 2];
        const vx = P[c] - P[a], vy = P[c + 1] - P[a + 1], vz = P[c + 2] - P[a + 2];
        let nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        const nl = Math.hypot(nx, ny, nz) || 1;
        const shade = 0.35 + 0.65 * Math.abs((nx * light[0] + ny * light[1] + nz * light[2]) / nl);
        tri(p0, p1, p2, col, shade);
      }
    } else overlay.push({P, I, col, mode});
  }
}
function walk(n) { const node = gltf.nodes[n]; if (node.mesh !== undefined) drawMesh(node.mesh); (node.children || []).forEach(walk); }
gltf.scenes[gltf.scene || 0].nodes.forEach(walk);
for (const o of overlay) {
  if (o.mode === 1) {
    for (let k = 0; k + 1 < o.I.length; k += 2) {
      const a = o.I[k] * 3, b = o.I[k + 1] * 3;
      const p0 = project(o.P[a], o.P[a + 1], o.P[a + 2]), p1 = project(o.P[b], o.P[b + 1], o.P[b + 2]);
      if (!p0 || !p1) continue;
      const n = Math.ceil(Math.hypot(p1[0] - p0[0], p1[1] - p0[1])) + 1;
      for (let s = 0; s <= n; ++s) { const u = s / n; dot(p0[0] + u * (p1[0] - p0[0]), p0[1] + u * (p1[1] - p0[1]), o.col, 1, p0[2] + u * (p1[2] - p0[2])); }
    }
  } else if (o.mode === 0) {
    for (let k = 0; k < o.P.length; k += 3) { const p = project(o.P[k], o.P[k + 1], o.P[k + 2]); if (p) dot(p[0], p[1], o.col, 2, p[2]); }
  }
}
// PNG (optionally a crop x,y,w,h scaled up 3x)
let X0 = 0, Y0 = 0, CW = W, CH = H, S = 1;
if (crop) { [X0, Y0, CW, CH] = crop.split(',').map(Number); S = 3; }
const OW = CW * S, OH = CH * S;
const raw = Buffer.alloc((OW * 3 + 1) * OH);
for (let y = 0; y < OH; ++y) { raw[y * (OW * 3 + 1)] = 0; for (let x = 0; x < OW; ++x) { const k = ((Y0 + Math.floor(y / S)) * W + X0 + Math.floor(x / S)) * 3; for (let c = 0; c < 3; ++c) raw[y * (OW * 3 + 1) + 1 + x * 3 + c] = Math.max(0, Math.min(255, Math.round(Math.pow(img[k + c], 1 / 2.2) * 255))); } }
function chunk(type, data) { const l = Buffer.alloc(4); l.writeUInt32BE(data.length); const td = Buffer.concat([Buffer.from(type), data]); const c = Buffer.alloc(4); c.writeUInt32BE(zlib.crc32 ? zlib.crc32(td) >>> 0 : crc(td)); return Buffer.concat([l, td, c]); }
function crc(b) { let c, t = []; for (let n = 0; n < 256; n++) { c = n; for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1; t[n] = c >>> 0; } c = 0xffffffff; for (const x of b) c = t[(c ^ x) & 0xff] ^ (c >>> 8); return (c ^ 0xffffffff) >>> 0; }
const ihdr = Buffer.alloc(13); ihdr.writeUInt32BE(OW, 0); ihdr.writeUInt32BE(OH, 4); ihdr[8] = 8; ihdr[9] = 2;
fs.writeFileSync(outPath, Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', ihdr), chunk('IDAT', zlib.deflateSync(raw)), chunk('IEND', Buffer.alloc(0))]));
console.log('wrote', outPath, OW + 'x' + OH, 'overlay primitives', overlay.length);
