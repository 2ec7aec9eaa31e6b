// FNV-1a, 32 bits, over the bytes of float arrays (their bit patterns,
// little-endian): a state's fingerprint, equal exactly when the bits are.
// The lab checks its first frame against the core's scene with it; the test
// build's hooks compare worlds stepped on one core and in workers.

/** FNV-1a (hex) over the bytes of `arrays`, in order. */
export function fnvHex(...arrays: Float32Array[]): string {
  let h = 0x811c9dc5;
  for (const a of arrays) {
    const b = new Uint8Array(a.buffer, a.byteOffset, a.byteLength);
    for (let k = 0; k < b.length; k++) h = Math.imul(h ^ (b[k] ?? 0), 0x01000193);
  }
  return (h >>> 0).toString(16).padStart(8, "0");
}
