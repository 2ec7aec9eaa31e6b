// Files the pages hand to the browser's download: any blob, and the canvas
// as PNG.

import { withGlLayer } from "./glsprites";

export function download(name: string, blob: Blob): void {
  const url = URL.createObjectURL(blob);
  const a = document.createElement("a");
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

export function downloadPng(canvas: HTMLCanvasElement): void {
  // With the WebGL agent layer over it, the picture is both layers.
  withGlLayer(canvas).toBlob((b) => {
    if (b) download("steering-lab.png", b);
  }, "image/png");
}
