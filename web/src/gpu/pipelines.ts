// The kernel's compiled WGSL and compute pipelines, kept per device and
// source: a kernel built again for a new world (each new GPU crowd of the
// lab, each sampled step of a parity check) reuses them instead of compiling the
// same code again, which over SwiftShader (a CPU emulation) costs seconds
// for separation's eleven entry points. A changed source (a parity check's
// planted change) is compiled on its own.

const modules = new WeakMap<GPUDevice, Map<string, Promise<GPUShaderModule>>>();
const pipelines = new WeakMap<GPUShaderModule, Map<string, Promise<GPUComputePipeline>>>();

/** `cache`'s entry for `key` under `owner`, made by `make` once; a failed one is dropped, so a later call tries again. */
function once<K extends object, V>(cache: WeakMap<K, Map<string, Promise<V>>>, owner: K, key: string, make: () => Promise<V>): Promise<V> {
  let byKey = cache.get(owner);
  if (!byKey) {
    byKey = new Map();
    cache.set(owner, byKey);
  }
  const known = byKey.get(key);
  if (known) return known;
  const made = make();
  byKey.set(key, made);
  made.catch(() => byKey.delete(key));
  return made;
}

/** Compiles the kernel's module, refusing one with errors (their messages joined). */
export function compile(device: GPUDevice, code: string): Promise<GPUShaderModule> {
  return once(modules, device, code, async () => {
    const module = device.createShaderModule({ label: "funnel.wgsl", code });
    const info = await module.getCompilationInfo();
    const errors = info.messages.filter((m) => m.type === "error");
    if (errors.length > 0) throw new Error(`funnel.wgsl: ${errors.map((m) => `${m.lineNum}:${m.linePos} ${m.message}`).join("; ")}`);
    return module;
  });
}

/** The compute pipeline of `module`'s `entryPoint` (its bind group layout "auto"). */
export function pipelineOf(device: GPUDevice, module: GPUShaderModule, entryPoint: string): Promise<GPUComputePipeline> {
  return once(pipelines, module, entryPoint, () => device.createComputePipelineAsync({ layout: "auto", compute: { module, entryPoint } }));
}
