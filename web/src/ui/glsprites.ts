// Agents by the hundred thousand: one WebGL2 instanced draw of
// oriented triangles, read straight from the core's typed arrays (no loop
// over agents in JavaScript), on a WebGL2 canvas laid over the page's 2D
// canvas (same box, transparent, pointer-events: none), so everything else
// (grid, path, targets) stays 2D and the browser composites the two layers.
// Not drawImage onto the 2D canvas: where that canvas is not on the GPU
// (software 2D, as in headless Chromium) every frame would read the GL
// pixels back and stall ("GPU stall due to ReadPixels"). The PNG export
// composites the layer once (`withGlLayer`). Pages use it above
// GL_THRESHOLD agents; below, and where WebGL2 is missing, the 2D paths of
// sprites.ts draw.
//
// Instances come from an interleaved Float32Array: the lab's state records
// (stride STATE_STRIDE, x / y / θ / mode at their StateField offsets) or the
// crowd's positions + velocities (heading = velocity direction).

import type { Surface } from "./canvas";
import type { View } from "./view";

/** Above this many agents the pages draw through WebGL2 when they can. */
export const GL_THRESHOLD = 2000;

/** Where an instance's numbers are in the float array(s) handed to `draw`. */
export interface InstanceLayout {
  /** Floats per instance in `a`. */
  stride: number;
  x: number;
  y: number;
  /** Heading θ (rad) at this offset of `a`, or null: heading along the velocity in `b` (2 floats per instance). */
  theta: number | null;
  /** Palette index at this offset of `a` (0..3), or null: palette[0]. */
  colour: number | null;
}

const VS = `#version 300 es
in vec2 a_corner;
in vec2 a_pos;
in float a_theta;
in vec2 a_vel;
in float a_colour;
uniform vec2 u_centre;
uniform float u_scale;
uniform vec2 u_half;
uniform float u_size;
uniform int u_velocity;
uniform vec4 u_palette[4];
out vec4 v_colour;
void main() {
  vec2 d;
  if (u_velocity == 1) {
    float l = length(a_vel);
    d = l > 0.0 ? a_vel / l : vec2(1.0, 0.0);
  } else {
    d = vec2(cos(a_theta), sin(a_theta));
  }
  vec2 local = vec2(a_corner.x * d.x - a_corner.y * d.y, a_corner.x * d.y + a_corner.y * d.x) * u_size;
  vec2 px = (a_pos - u_centre) * u_scale + local;
  gl_Position = vec4(px / u_half, 0.0, 1.0);
  v_colour = u_palette[clamp(int(a_colour + 0.5), 0, 3)];
}`;

const FS = `#version 300 es
precision mediump float;
in vec4 v_colour;
out vec4 o;
void main() { o = v_colour; }`;

interface Gl {
  canvas: HTMLCanvasElement;
  gl: WebGL2RenderingContext;
  prog: WebGLProgram;
  vao: WebGLVertexArrayObject;
  bufA: WebGLBuffer;
  bufB: WebGLBuffer;
  loc: Record<string, number>;
  uni: Record<string, WebGLUniformLocation | null>;
}

function compile(gl: WebGL2RenderingContext, type: number, src: string): WebGLShader | null {
  const sh = gl.createShader(type);
  if (!sh) return null;
  gl.shaderSource(sh, src);
  gl.compileShader(sh);
  return gl.getShaderParameter(sh, gl.COMPILE_STATUS) ? sh : null;
}

function create(): Gl | null {
  const canvas = document.createElement("canvas");
  canvas.className = "gl-agents";
  canvas.setAttribute("aria-hidden", "true");
  Object.assign(canvas.style, { position: "absolute", pointerEvents: "none", display: "none" });
  // Only a GPU's WebGL: a software one (SwiftShader, e.g. headless Chromium)
  // rasterises on the CPU and the compositor reads every frame back ("GPU
  // stall due to ReadPixels"); there the 2D sprites draw, unless `?draw=gl`.
  const gl = canvas.getContext("webgl2", {
    antialias: false,
    premultipliedAlpha: true,
    alpha: true,
    preserveDrawingBuffer: false,
    failIfMajorPerformanceCaveat: DRAW !== "gl",
  });
  if (!gl) return null;
  if (DRAW !== "gl") {
    // failIfMajorPerformanceCaveat lets SwiftShader through in headless Chromium: ask the renderer's name.
    const info = gl.getExtension("WEBGL_debug_renderer_info");
    const renderer = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : "";
    if (/swiftshader|llvmpipe|software/i.test(renderer)) return null;
  }
  const vs = compile(gl, gl.VERTEX_SHADER, VS);
  const fs = compile(gl, gl.FRAGMENT_SHADER, FS);
  const prog = gl.createProgram();
  if (!vs || !fs || !prog) return null;
  gl.attachShader(prog, vs);
  gl.attachShader(prog, fs);
  gl.linkProgram(prog);
  if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) return null;
  const vao = gl.createVertexArray();
  const corners = gl.createBuffer();
  const bufA = gl.createBuffer();
  const bufB = gl.createBuffer();
  if (!vao || !corners || !bufA || !bufB) return null;
  gl.bindVertexArray(vao);
  // The same triangle as sprites.ts `triangle`: nose 1 ahead, base 0.6 behind, half-width 0.55.
  gl.bindBuffer(gl.ARRAY_BUFFER, corners);
  gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([1, 0, -0.6, 0.55, -0.6, -0.55]), gl.STATIC_DRAW);
  const loc: Record<string, number> = {};
  for (const n of ["a_corner", "a_pos", "a_theta", "a_vel", "a_colour"]) loc[n] = gl.getAttribLocation(prog, n);
  const uni: Record<string, WebGLUniformLocation | null> = {};
  for (const n of ["u_centre", "u_scale", "u_half", "u_size", "u_velocity", "u_palette"]) uni[n] = gl.getUniformLocation(prog, n);
  const c = loc["a_corner"]!;
  gl.enableVertexAttribArray(c);
  gl.vertexAttribPointer(c, 2, gl.FLOAT, false, 0, 0);
  gl.bindVertexArray(null);
  return { canvas, gl, prog, vao, bufA, bufB, loc, uni };
}

/** Colour "#rrggbb" as linear [r, g, b, 1] in 0..1. */
function rgba(hex: string): number[] {
  const n = parseInt(hex.slice(1), 16);
  return [((n >> 16) & 0xff) / 255, ((n >> 8) & 0xff) / 255, (n & 0xff) / 255, 1];
}

/** One per page canvas; `draw` returns false when WebGL2 is unavailable (the caller draws in 2D). */
export class GlSprites {
  private g: Gl | null | undefined = undefined;

  /** Whether WebGL2 works here (creates the context on first call). */
  available(): boolean {
    if (this.g === undefined) {
      try {
        this.g = create();
      } catch {
        this.g = null;
      }
    }
    return this.g !== null;
  }

  /** Hides the layer (a frame drawn without it). */
  hide(): void {
    if (this.g) this.g.canvas.style.display = "none";
  }

  /**
   * Draws `count` instances of `a` (and velocities `b` when the layout has
   * no θ) as triangles `sizePx` CSS pixels long, coloured from `palette`
   * (up to 4 "#rrggbb"), onto `s` with `view`'s transform.
   */
  draw(s: Surface, view: View, a: Float32Array, b: Float32Array | null, count: number, layout: InstanceLayout, palette: string[], sizePx: number): boolean {
    if (!this.available() || count <= 0) return count <= 0;
    const { canvas, gl, prog, vao, bufA, bufB, loc, uni } = this.g!;
    const W = s.canvas.width;
    const H = s.canvas.height;
    if (canvas.width !== W || canvas.height !== H) {
      canvas.width = W;
      canvas.height = H;
    }
    // Over the 2D canvas, box for box, right after it (later overlays stay on top).
    const under = s.canvas;
    if (canvas.previousElementSibling !== under) under.after(canvas);
    const st = canvas.style;
    const [l, t, w, h] = [`${under.offsetLeft}px`, `${under.offsetTop}px`, `${s.width}px`, `${s.height}px`];
    if (st.left !== l || st.top !== t || st.width !== w || st.height !== h || st.display !== "block") Object.assign(st, { left: l, top: t, width: w, height: h, display: "block" });
    gl.viewport(0, 0, W, H);
    gl.clearColor(0, 0, 0, 0);
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.useProgram(prog);
    gl.bindVertexArray(vao);
    const F = 4;
    const inst = (name: string, buf: WebGLBuffer, size: number, stride: number, offset: number): void => {
      const l = loc[name]!;
      if (l < 0) return;
      gl.bindBuffer(gl.ARRAY_BUFFER, buf);
      gl.enableVertexAttribArray(l);
      gl.vertexAttribPointer(l, size, gl.FLOAT, false, stride * F, offset * F);
      gl.vertexAttribDivisor(l, 1);
    };
    const constant = (name: string, v: number): void => {
      const l = loc[name]!;
      if (l < 0) return;
      gl.disableVertexAttribArray(l);
      gl.vertexAttrib2f(l, v, 0);
    };
    gl.bindBuffer(gl.ARRAY_BUFFER, bufA);
    gl.bufferData(gl.ARRAY_BUFFER, a.subarray(0, count * layout.stride), gl.STREAM_DRAW);
    inst("a_pos", bufA, 2, layout.stride, layout.x);
    if (layout.y !== layout.x + 1) throw new Error("GlSprites: y must follow x");
    if (layout.theta !== null) inst("a_theta", bufA, 1, layout.stride, layout.theta);
    else constant("a_theta", 0);
    if (layout.colour !== null) inst("a_colour", bufA, 1, layout.stride, layout.colour);
    else constant("a_colour", 0);
    if (layout.theta === null && b) {
      gl.bindBuffer(gl.ARRAY_BUFFER, bufB);
      gl.bufferData(gl.ARRAY_BUFFER, b.subarray(0, 2 * count), gl.STREAM_DRAW);
      inst("a_vel", bufB, 2, 2, 0);
    } else constant("a_vel", 1);
    const k = s.dpr;
    gl.uniform2f(uni["u_centre"]!, view.cx, view.cy);
    gl.uniform1f(uni["u_scale"]!, view.scale * k);
    gl.uniform2f(uni["u_half"]!, W / 2, H / 2);
    gl.uniform1f(uni["u_size"]!, sizePx * k);
    gl.uniform1i(uni["u_velocity"]!, layout.theta === null ? 1 : 0);
    const pal = [0, 1, 2, 3].flatMap((i) => rgba(palette[Math.min(i, palette.length - 1)] ?? "#000000"));
    gl.uniform4fv(uni["u_palette"]!, new Float32Array(pal));
    gl.drawArraysInstanced(gl.TRIANGLES, 0, 3, count);
    gl.bindVertexArray(null);
    return true;
  }
}

/** `canvas` with the WebGL agent layer over it (if shown) composited into a copy: what the PNG export saves. */
export function withGlLayer(canvas: HTMLCanvasElement): HTMLCanvasElement {
  const gl = canvas.nextElementSibling;
  if (!(gl instanceof HTMLCanvasElement) || !gl.classList.contains("gl-agents") || gl.style.display === "none") return canvas;
  const copy = document.createElement("canvas");
  copy.width = canvas.width;
  copy.height = canvas.height;
  const ctx = copy.getContext("2d");
  if (!ctx) return canvas;
  ctx.drawImage(canvas, 0, 0);
  ctx.drawImage(gl, 0, 0, canvas.width, canvas.height);
  return copy;
}

/** "webgl2" | "sprites" | "triangles": which path drew the agents, on the canvas's data-agents attribute (tests read it). */
export function markPath(canvas: HTMLCanvasElement, path: "webgl2" | "sprites" | "triangles"): void {
  if (canvas.dataset["agents"] !== path) canvas.dataset["agents"] = path;
}

/** `?draw=2d` in the page's address forces the 2D paths, `?draw=gl` WebGL2 even where it is software (tests, same-run comparisons). */
const DRAW = typeof location !== "undefined" ? new URLSearchParams(location.search).get("draw") : null;
export const FORCE_2D = DRAW === "2d";
