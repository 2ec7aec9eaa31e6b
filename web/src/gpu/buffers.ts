// The kernel's buffers on the device: WebGPU's usage flags, a storage
// buffer filled at creation, and a buffer read back (tests, the ringed
// agent's HUD numbers).

/** WebGPU's buffer usage and map mode flags (the spec's numbers; TypeScript's DOM library types them but declares no values). */
export const USAGE = { MAP_READ: 0x1, COPY_SRC: 0x4, COPY_DST: 0x8, VERTEX: 0x20, UNIFORM: 0x40, STORAGE: 0x80, QUERY_RESOLVE: 0x200 } as const;
const MAP_READ_MODE = 0x1;

export function storage(device: GPUDevice, data: ArrayBufferView, extra: number = 0, label = "funnel"): GPUBuffer {
  // A binding needs a non-empty buffer; sizes are multiples of 4 anyway.
  const size = Math.max(16, Math.ceil(data.byteLength / 16) * 16);
  const b = device.createBuffer({ label, size, usage: USAGE.STORAGE | USAGE.COPY_DST | USAGE.COPY_SRC | extra, mappedAtCreation: true });
  new Uint8Array(b.getMappedRange()).set(new Uint8Array(data.buffer, data.byteOffset, data.byteLength));
  b.unmap();
  return b;
}

/** Reads `size` bytes of `buffer` back (tests, the ringed agent's HUD numbers). */
export async function readBack(device: GPUDevice, buffer: GPUBuffer, size: number, offset = 0): Promise<ArrayBuffer> {
  const staging = device.createBuffer({ size, usage: USAGE.MAP_READ | USAGE.COPY_DST });
  const enc = device.createCommandEncoder();
  enc.copyBufferToBuffer(buffer, offset, staging, 0, size);
  device.queue.submit([enc.finish()]);
  await staging.mapAsync(MAP_READ_MODE);
  const out = staging.getMappedRange().slice(0);
  staging.destroy();
  return out;
}
