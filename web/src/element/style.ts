// The element's own styles (its shadow root): the box it sizes itself to,
// the learn page's handle look (learn/learn.css), the bar under the canvas.
// The stage clips (overflow: clip, not hidden): a focused handle near its
// edge must not scroll the canvas aside.
export const STYLE = `
:host { display: block; position: relative; width: 100%; height: 360px; min-height: 160px; font: 13px system-ui, sans-serif; color: #222; contain: content; }
.stage { position: absolute; inset: 0 0 30px 0; border-radius: 4px; overflow: clip; }
canvas { display: block; width: 100%; height: 100%; touch-action: none; }
.handle { position: absolute; width: 26px; height: 26px; margin: -13px 0 0 -13px; padding: 0; border-radius: 50%; border: 2.5px solid #d62728; background: rgba(255,255,255,0.35); cursor: grab; touch-action: none; }
.handle:hover, .handle:focus-visible { background: rgba(255,255,255,0.8); outline: 3px solid #1f5fd1; outline-offset: 1px; }
.handle:active { cursor: grabbing; }
.bar { position: absolute; left: 0; right: 0; bottom: 0; height: 30px; display: flex; gap: 6px; align-items: center; overflow: hidden; white-space: nowrap; }
button { font: inherit; padding: 2px 8px; }
output { overflow: hidden; text-overflow: ellipsis; }
.note { color: #9a4a00; }
`;
