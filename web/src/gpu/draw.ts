// Drawing the kernel's agents straight from its agent buffer: one
// instanced draw, three vertices per agent (an arrow along its heading,
// coloured by its mode), the buffer bound as an instance vertex buffer
// (pose at word 0, mode at word 10 of kernel.ts's layout). Nothing is read
// back: the pixels come from the same memory the compute pass wrote.

import { AGENT_MODE, AGENT_WORDS, USAGE, type FunnelKernel } from "./kernel";

const DRAW_WGSL = /* wgsl */ `
struct View { scale: vec2<f32>, offset: vec2<f32>, size: f32, pad0: f32, pad1: vec2<f32>, colors: array<vec4<f32>, 4> }
@group(0) @binding(0) var<uniform> view: View;
struct VOut { @builtin(position) pos: vec4<f32>, @location(0) color: vec4<f32> }

@vertex
fn vs(@builtin(vertex_index) vi: u32, @location(0) pose: vec3<f32>, @location(1) mode: u32) -> VOut {
  var corners = array<vec2<f32>, 3>(vec2<f32>(1.0, 0.0), vec2<f32>(-0.7, 0.55), vec2<f32>(-0.7, -0.55));
  let c = corners[vi] * view.size;
  let s = sin(pose.z);
  let k = cos(pose.z);
  let world = pose.xy + vec2<f32>(c.x * k - c.y * s, c.x * s + c.y * k);
  var out: VOut;
  out.pos = vec4<f32>(world * view.scale + view.offset, 0.0, 1.0);
  out.color = view.colors[min(mode, 3u)];
  return out;
}

@fragment
fn fs(v: VOut) -> @location(0) vec4<f32> { return v.color; }
`;

/** Where the agents are drawn: world metres to clip space, the arrow's
 *  length in metres, and the four mode colours (RGBA in 0..1, Mode order). */
export interface AgentView {
  scale: [number, number];
  offset: [number, number];
  size: number;
  colors: [number, number, number, number][];
}

/** Draws a kernel's agents on a WebGPU canvas. */
export class AgentDrawer {
  private readonly pipeline: GPURenderPipeline;
  private readonly uniform: GPUBuffer;
  private readonly bind: GPUBindGroup;

  constructor(private readonly device: GPUDevice, private readonly context: GPUCanvasContext) {
    const format = navigator.gpu.getPreferredCanvasFormat();
    context.configure({ device, format, alphaMode: "premultiplied" });
    const module = device.createShaderModule({ label: "agents draw", code: DRAW_WGSL });
    this.pipeline = device.createRenderPipeline({
      layout: "auto",
      vertex: {
        module,
        entryPoint: "vs",
        buffers: [{
          arrayStride: AGENT_WORDS * 4,
          stepMode: "instance",
          attributes: [
            { shaderLocation: 0, offset: 0, format: "float32x3" },
            { shaderLocation: 1, offset: AGENT_MODE * 4, format: "uint32" },
          ],
        }],
      },
      fragment: { module, entryPoint: "fs", targets: [{ format }] },
      primitive: { topology: "triangle-list" },
    });
    this.uniform = device.createBuffer({ size: 96, usage: USAGE.UNIFORM | USAGE.COPY_DST });
    this.bind = device.createBindGroup({ layout: this.pipeline.getBindGroupLayout(0), entries: [{ binding: 0, resource: { buffer: this.uniform } }] });
  }

  /** Encodes the draw of `kernel`'s agents as `view` places them (the canvas cleared first). */
  encode(enc: GPUCommandEncoder, kernel: FunnelKernel, view: AgentView): void {
    const u = new Float32Array(24);
    u.set([view.scale[0], view.scale[1], view.offset[0], view.offset[1], view.size]);
    view.colors.slice(0, 4).forEach((c, k) => u.set(c, 8 + 4 * k));
    this.device.queue.writeBuffer(this.uniform, 0, u);
    const pass = enc.beginRenderPass({
      colorAttachments: [{ view: this.context.getCurrentTexture().createView(), loadOp: "clear", storeOp: "store", clearValue: { r: 0, g: 0, b: 0, a: 0 } }],
    });
    pass.setPipeline(this.pipeline);
    pass.setBindGroup(0, this.bind);
    pass.setVertexBuffer(0, kernel.agents);
    pass.draw(3, kernel.n);
    pass.end();
  }

  destroy(): void {
    this.uniform.destroy();
  }
}
