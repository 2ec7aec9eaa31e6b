// The η table on the wire (issue 17, "a faster start"): the file's 4-byte
// words split into four byte planes (byte 0 of every word, then byte 1, …;
// the 0–3 trailing bytes as they are). Lossless — the core gets the very
// bytes of tables/eta.bin, so every η and every golden hash is unchanged —
// but the planes compress far better: the f32 exponents and high mantissa
// bytes repeat where the low bytes are noise. gzip -6: 1.215 MB → 0.541 MB
// (brotli 0.479 MB). A quantised table (η as i16, speed as u16) was
// measured too: 0.475 MB gzipped with its planes, arrival figures equal
// on the held-out seed, but its η differ in the last bits, so trajectories
// and the golden hashes would change for 12 % fewer bytes
// (web/test/table-quant.mjs, README figures).

const LITTLE = new Uint8Array(new Uint32Array([1]).buffer)[0] === 1;

/** The planes of `b` (what the server sends, gzipped). */
export function toPlanes(b: Uint8Array): Uint8Array {
  const m = b.length >>> 2;
  const out = new Uint8Array(b.length);
  for (let i = 0; i < m; i++) for (let j = 0; j < 4; j++) out[j * m + i] = b[4 * i + j]!;
  out.set(b.subarray(4 * m), 4 * m);
  return out;
}

/** The file's bytes from its planes (about 5 ms for the 3.3 MB table). */
export function fromPlanes(p: Uint8Array): Uint8Array {
  const m = p.length >>> 2;
  const out = new Uint8Array(p.length);
  if (LITTLE) {
    const w = new Uint32Array(out.buffer, 0, m);
    for (let i = 0; i < m; i++) w[i] = (p[i]! | (p[m + i]! << 8) | (p[2 * m + i]! << 16) | (p[3 * m + i]! << 24)) >>> 0;
  } else {
    for (let i = 0; i < m; i++) for (let j = 0; j < 4; j++) out[4 * i + j] = p[j * m + i]!;
  }
  out.set(p.subarray(4 * m), 4 * m);
  return out;
}
