// Worker side of time-box.ts: runs one fuzz target per message and answers with its verdict and duration.
// Plain JavaScript that loads the TypeScript targets through tsx's API (loader flags do not reach workers on
// Node 20).
import { parentPort } from "node:worker_threads";
import { tsImport } from "tsx/esm/api";

const { FUZZ_TARGETS } = await tsImport("./fuzz-targets.ts", import.meta.url);

parentPort?.on("message", (message) => {
  const start = performance.now();
  const verdict = FUZZ_TARGETS[message.target](message.input);
  parentPort?.postMessage({ id: message.id, verdict, ms: performance.now() - start });
});
parentPort?.postMessage({ ready: true });
