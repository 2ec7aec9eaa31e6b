// Would a quantised η table load faster, and what would
// it cost in accuracy? Reads tables/eta.bin (format v1: η f32 × N, speed
// f32 × N, flags u8 × N), and for each storage variant prints the bytes
// raw / gzip -6 (what the server sends) / brotli, the gunzip time in Node,
// and the largest change to η and speed; it writes each lossy variant
// decoded back to a v1 file (OUT/eta-VARIANT.bin, CRC recomputed) so the
// envelope study can run on exactly what a browser would load:
//   node web/test/table-quant.mjs OUTDIR
//   steer envelope --n 10000 --seed 2 --only standard --brief --table OUTDIR/eta-i16.bin
import { readFileSync, writeFileSync, mkdirSync } from "node:fs";
import { gzipSync, gunzipSync, brotliCompressSync, constants } from "node:zlib";
import { resolve, dirname } from "node:path";
import { fileURLToPath } from "node:url";
import { options } from "./options.mjs";

const root = resolve(dirname(fileURLToPath(import.meta.url)), "../..");
const { positionals } = options(
  `Quantised η table variants: bytes, gunzip time, largest change; lossy variants written to OUTDIR.
Usage: node web/test/table-quant.mjs [OUTDIR]   (default /tmp/eta-quant)`,
  {},
  { positionals: 1 },
);
const out = resolve(positionals[0] ?? "/tmp/eta-quant");
mkdirSync(out, { recursive: true });
const bytes = readFileSync(resolve(root, "tables/eta.bin"));
const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
const counts = [0, 1, 2, 3, 4].map((i) => dv.getUint32(60 + 4 * i, true));
const n = counts.reduce((a, b) => a * b, 1);
const axesLen = counts.reduce((a, b) => a + b, 0);
const etaOff = 80 + 4 * axesLen;
const spdOff = etaOff + 4 * n;
const flagOff = spdOff + 4 * n;
if (flagOff + n + 4 !== bytes.length) throw new Error("unexpected layout");
const vMax = dv.getFloat32(16 + 4, true);
const eta = new Float32Array(bytes.buffer.slice(bytes.byteOffset + etaOff, bytes.byteOffset + spdOff));
const spd = new Float32Array(bytes.buffer.slice(bytes.byteOffset + spdOff, bytes.byteOffset + flagOff));
const flags = bytes.subarray(flagOff, flagOff + n);

const CRC = new Uint32Array(256).map((_, k) => { let c = k; for (let j = 0; j < 8; j++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1; return c >>> 0; });
const crc32 = (b) => { let c = 0xffffffff; for (let i = 0; i < b.length; i++) c = CRC[(c ^ b[i]) & 0xff] ^ (c >>> 8); return (c ^ 0xffffffff) >>> 0; };

function sizes(name, payload) {
  const gz = gzipSync(payload, { level: 6 });
  const br = brotliCompressSync(payload, { params: { [constants.BROTLI_PARAM_QUALITY]: 11, [constants.BROTLI_PARAM_SIZE_HINT]: payload.length } });
  const t0 = performance.now();
  for (let k = 0; k < 5; k++) gunzipSync(gz);
  const ms = (performance.now() - t0) / 5;
  console.log(`${name.padEnd(34)} raw ${(payload.length / 1e6).toFixed(3)} MB  gzip ${(gz.length / 1e6).toFixed(3)} MB  brotli ${(br.length / 1e6).toFixed(3)} MB  gunzip ${ms.toFixed(1)} ms`);
}

function writeV1(name, eta2, spd2) {
  const b = Buffer.from(bytes);
  Buffer.from(eta2.buffer).copy(b, etaOff);
  Buffer.from(spd2.buffer).copy(b, spdOff);
  b.writeUInt32LE(crc32(b.subarray(0, b.length - 4)), b.length - 4);
  writeFileSync(resolve(out, `eta-${name}.bin`), b);
}

function err(name, eta2, spd2) {
  let de = 0, ds = 0, sum = 0, cnt = 0;
  for (let i = 0; i < n; i++) {
    if (flags[i] & 2) { const e = Math.abs(eta2[i] - eta[i]); de = Math.max(de, e); sum += e; cnt++; }
    ds = Math.max(ds, Math.abs(spd2[i] - spd[i]));
  }
  console.log(`${"".padEnd(34)} max |Δη| ${(de * 180 / Math.PI).toExponential(2)}°, mean ${(sum / cnt * 180 / Math.PI).toExponential(2)}°; max |Δspeed| ${ds.toExponential(2)} m/s`);
}

// 1. f32 as shipped (the server gzips it).
sizes("f32 (shipped)", bytes);
// 2. f32, bytes of each field split into planes (lossless, same bits).
const planes = (f) => { const u = new Uint8Array(f.buffer); const o = new Uint8Array(u.length); const m = f.length; for (let i = 0; i < m; i++) for (let j = 0; j < 4; j++) o[j * m + i] = u[4 * i + j]; return o; };
sizes("f32 byte planes (lossless)", Buffer.concat([planes(eta), planes(spd), flags]));
// 3. η i16 (π/32767 rad steps), speed u16 (v_max/65535 steps).
{
  const qe = new Int16Array(n), qs = new Uint16Array(n);
  const e2 = new Float32Array(n), s2 = new Float32Array(n);
  for (let i = 0; i < n; i++) {
    qe[i] = Math.round((eta[i] / Math.PI) * 32767);
    e2[i] = Math.fround((qe[i] * Math.PI) / 32767);
    qs[i] = Math.round((spd[i] / vMax) * 65535);
    s2[i] = Math.fround((qs[i] * vMax) / 65535);
  }
  const pl = (a) => { const u = new Uint8Array(a.buffer); const o = new Uint8Array(u.length); const m = a.length; for (let i = 0; i < m; i++) { o[i] = u[2 * i]; o[m + i] = u[2 * i + 1]; } return o; };
  sizes("η i16 + speed u16", Buffer.concat([Buffer.from(qe.buffer), Buffer.from(qs.buffer), flags]));
  sizes("η i16 + speed u16, byte planes", Buffer.concat([pl(qe), pl(qs), flags]));
  err("i16", e2, s2);
  writeV1("i16", e2, s2);
}
// 4. η f16 (speed kept f32): error only and sizes.
{
  const f16 = (x) => { // round to nearest f16, back to f32
    const a = Math.abs(x); if (a === 0) return x; const e = Math.floor(Math.log2(a)); const q = 2 ** (e - 10); return Math.sign(x) * Math.round(a / q) * q;
  };
  const e2 = new Float32Array(n); const h = new Uint16Array(n);
  for (let i = 0; i < n; i++) { e2[i] = Math.fround(f16(eta[i])); h[i] = i; }
  err("f16 η", e2, spd);
  writeV1("f16", e2, spd);
}
// 5. η i8 (π/127 rad ≈ 1.4° steps): for scale.
{
  const e2 = new Float32Array(n); const q = new Int8Array(n);
  for (let i = 0; i < n; i++) { q[i] = Math.round((eta[i] / Math.PI) * 127); e2[i] = Math.fround((q[i] * Math.PI) / 127); }
  sizes("η i8 + speed u16", Buffer.concat([Buffer.from(q.buffer), Buffer.alloc(2 * n), flags]));
  err("i8 η", e2, spd);
  writeV1("i8", e2, spd);
}
