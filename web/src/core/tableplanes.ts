// The η table on the wire: the file's 4-byte words split into four byte
// planes (byte 0 of every word, then byte 1, …; the 0–3 trailing bytes as
// they are). Lossless: the core gets the very bytes of tables/eta.bin, so
// every η and every golden hash is the same. The planes compress far
// better (the f32 exponents and high mantissa bytes repeat where the low
// bytes are noise): gzipped, less than half the plain file. A quantised
// table would be smaller still, but its η differ in the last bits, so the
// trajectories and the golden hashes would change (web/test/table-quant.mjs
// measures it). The server (vite.config.ts) makes the planes with
// `toPlanes`, the page rejoins them with `fromPlanes`.

const LITTLE = new Uint8Array(new Uint32Array([1]).buffer)[0] === 1;

/** The planes of `b` (what the server sends, gzipped). */
export function toPlanes(b: Uint8Array): Uint8Array {
  const m = b.length >>> 2;
  const out = new Uint8Array(b.length);
  for (let i = 0; i < m; i++) for (let j = 0; j < 4; j++) out[j * m + i] = b[4 * i + j]!;
  out.set(b.subarray(4 * m), 4 * m);
  return out;
}

/** The file's bytes from its planes (whole words at a time where the host is little-endian). */
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
