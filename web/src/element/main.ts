// The npm package's element module (`steering-core/funnel-figure.js`,
// built by `make npm`): defines <funnel-figure>, which loads the core, its
// η table and presets from beside this module (import.meta.url), so a plain
// HTML page needs only `<script type="module" src=".../funnel-figure.js">`.

import { FunnelFigure, setHome } from "./figure";

setHome(import.meta.url);
if (!customElements.get("funnel-figure")) customElements.define("funnel-figure", FunnelFigure);

export { FunnelFigure };
