// Opening WebGPU for the funnelling kernel: an adapter and a device with
// the largest storage buffers the adapter allows (a million agents'
// buffers exceed the 128 MiB default binding), timestamp queries where
// offered, or why there is none (the page then keeps its workers).

export interface GpuOpened {
  device: GPUDevice;
  /** The adapter as the browser names it (vendor, architecture, description). */
  label: string;
  /** A software adapter (SwiftShader, a CPU emulation) rather than a GPU. */
  emulated: boolean;
  /** Timestamp queries granted (`timestamp-query`). */
  timestamps: boolean;
}

export type GpuAccess = GpuOpened | { absent: string };

let opened: Promise<GpuAccess> | null = null;

/** The page's device, opened once; `{ absent }` says why there is none. */
export function openGpu(): Promise<GpuAccess> {
  opened ??= open();
  return opened;
}

async function open(): Promise<GpuAccess> {
  const gpu = (navigator as Navigator & { gpu?: GPU }).gpu;
  if (!gpu) return { absent: "this browser offers no WebGPU" };
  let adapter: GPUAdapter | null = null;
  try {
    adapter = await gpu.requestAdapter({ powerPreference: "high-performance" });
  } catch (e) {
    return { absent: `no WebGPU adapter (${e instanceof Error ? e.message : String(e)})` };
  }
  if (!adapter) return { absent: "no WebGPU adapter" };
  const timestamps = adapter.features.has("timestamp-query");
  const l = adapter.limits;
  try {
    const device = await adapter.requestDevice({
      requiredFeatures: timestamps ? ["timestamp-query"] : [],
      requiredLimits: {
        maxStorageBufferBindingSize: l.maxStorageBufferBindingSize,
        maxBufferSize: l.maxBufferSize,
      },
    });
    const info = adapter.info;
    const label = [info.vendor, info.architecture, info.description].filter((s) => s).join(" ") || "WebGPU adapter";
    const fallback = (info as GPUAdapterInfo & { isFallbackAdapter?: boolean }).isFallbackAdapter === true;
    const emulated = fallback || /swiftshader|llvmpipe|software/i.test(`${label} ${info.device}`);
    return { device, label, emulated, timestamps };
  } catch (e) {
    return { absent: `no WebGPU device (${e instanceof Error ? e.message : String(e)})` };
  }
}
