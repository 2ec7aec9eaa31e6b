// A preview server in its own process (the perf harness's first-frame
// loads with `--server child`, so the server does not share the
// harness's Node process and its CDP traffic, as a user's server would
// not). Prints the URL on its first line; serves until killed.
import { parseArgs } from "node:util";
import { serve } from "./harness.mjs";

// One optional argument: the dist to serve (default: the test build).
const { positionals } = parseArgs({ allowPositionals: true });
const { url } = await serve(positionals[0] || undefined);
console.log(url);
