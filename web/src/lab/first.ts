// The inline script of the lab's HTML (vite.config.ts, firstFrame):
// draws the default playground's first frame from the data the build wrote
// beside it (firstframe.ts), before the page's modules and core arrive.
import { drawFirstFrame } from "./firstframe";

drawFirstFrame(window.__firstFrameData);
