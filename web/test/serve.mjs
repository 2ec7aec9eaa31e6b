// A preview server in its own process (issue 17: the perf harness's
// first-frame loads with `--child`, so the server does not share the
// harness's Node process and its CDP traffic, as a user's server would
// not). Prints the URL on its first line; serves until killed.
import { serve } from "./harness.mjs";

const { url } = await serve(process.argv[2] || undefined);
console.log(url);
