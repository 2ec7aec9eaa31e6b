// The npm package's element module (`make npm`): src/element/main.ts as one
// ES module, `funnel-figure.js`, beside the package's index.js. The core's
// glue stays out of it: the module imports the package's own
// `./pkg/steering.js` (one instance of the core with index.js, and the
// glue finds its .wasm beside itself), so nothing of the wasm is bundled.
import { defineConfig, type Plugin } from "vite";
import { resolve } from "node:path";

/** `…/pkg/steering.js` as the package's `./pkg/steering.js`, external. */
function packageGlue(): Plugin {
  return {
    name: "steering-package-glue",
    enforce: "pre",
    resolveId(source) {
      return /(^|\/)pkg\/steering\.js$/.test(source) ? { id: "./pkg/steering.js", external: true } : null;
    },
  };
}

export default defineConfig({
  base: "./",
  plugins: [packageGlue()],
  build: {
    outDir: resolve(import.meta.dirname, "../target/npm-element"),
    emptyOutDir: true,
    target: "es2022",
    minify: true,
    sourcemap: false,
    lib: { entry: resolve(import.meta.dirname, "src/element/main.ts"), formats: ["es"], fileName: () => "funnel-figure.js" },
  },
});
