// What the browser suites of the package share: a plain static server of
// one folder (the user's: their page and node_modules, nothing of the
// repository), and headless Chromium through the front end's pinned
// playwright-core.
import { readFileSync } from "node:fs";
import { createServer } from "node:http";
import { createRequire } from "node:module";
import { extname, join, resolve, sep } from "node:path";
import { pathToFileURL } from "node:url";
import { repo } from "./install.mjs";

const requireFromWeb = createRequire(join(repo, "web/package.json"));
const playwright = await import(pathToFileURL(requireFromWeb.resolve("playwright-core")).href);
const chromium = playwright.chromium ?? playwright.default.chromium;

const CHROMIUM_ARGS = ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--disable-background-networking", "--disable-component-update", "--disable-sync", "--disable-quic", "--no-first-run",
  // No preloaded WebUI omnibox popups (web/test/harness.mjs says why).
  "--disable-features=WebUIOmniboxPopup,WebUIOmniboxAimPopup,WebUIOmniboxFullPopup"];
const TYPES = { ".html": "text/html", ".js": "text/javascript", ".wasm": "application/wasm", ".bin": "application/octet-stream", ".json": "application/json" };

/** Serves `root` (files only, nothing outside it) on 127.0.0.1. */
export function serve(root) {
  const server = createServer((req, res) => {
    const path = decodeURIComponent(new URL(req.url, "http://x").pathname);
    const file = resolve(root, "." + (path.endsWith("/") ? path + "index.html" : path));
    try {
      if (!file.startsWith(root + sep)) throw new Error("outside the root");
      const body = readFileSync(file);
      res.writeHead(200, { "content-type": TYPES[extname(file)] ?? "application/octet-stream" });
      res.end(body);
    } catch {
      res.writeHead(404).end();
    }
  });
  return new Promise((ok) => server.listen(0, "127.0.0.1", () => ok({ server, url: `http://127.0.0.1:${server.address().port}/` })));
}

/** Headless Chromium (Debian's). */
export function launch() {
  return chromium.launch({ executablePath: "/usr/bin/chromium", args: CHROMIUM_ARGS });
}
