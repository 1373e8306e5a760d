import { tmpdir } from "node:os";
import { join } from "node:path";
import { defineConfig } from "vitest/config";

/** Unit tests that open serial ports (over socat PTYs) in the test process itself. */
const SERIAL_PORT_TESTS = "tests/unit/cli-serial.test.ts";

export default defineConfig({
  test: {
    // Vitest's default on a 2-core machine is one worker (cores - 1), which runs every file one after another;
    // most of the suite waits on a browser or a child process rather than the CPU, so two workers fit.
    maxWorkers: 2,
    // rbc keeps its shelf of uploaded motions in its config folder: tests (and the rbc they spawn) use a folder
    // of their own, never the user's ~/.config/rbc.
    env: { RBC_CONFIG_DIR: join(tmpdir(), `rbc-test-config-${process.pid}`) },
    reporters: process.env.CI
      ? ["default", ["json", { outputFile: "test-results/vitest.json" }]]
      : ["default"],
    projects: [
      {
        extends: true,
        test: {
          name: "unit",
          include: ["tests/unit/**/*.test.ts", "tests/interop/**/*.test.ts"],
          exclude: [SERIAL_PORT_TESTS],
          environment: "node",
          // Worker threads start faster than forked processes, and these files need no process of their own
          // (the CLI tests spawn theirs).
          pool: "threads",
          testTimeout: 10_000,
        },
      },
      {
        extends: true,
        test: {
          // The serialport package's native addon crashes inside a worker thread, so the one file that opens
          // ports in its own process runs in a forked process.
          name: "serial",
          include: [SERIAL_PORT_TESTS],
          environment: "node",
          pool: "forks",
          testTimeout: 10_000,
        },
      },
      {
        extends: true,
        test: {
          name: "e2e",
          include: ["tests/e2e/**/*.test.ts"],
          environment: "node",
          // A guard against a hang, not a measure of speed: a browser test's time is mostly CPU, and with two
          // suites at once on a 2-core machine the longest (owner-round2's walk of every view at two widths in
          // two languages) took 57 s, twice its time alone.
          testTimeout: 120_000,
          hookTimeout: 120_000,
          // expect.poll waits for what the page or the demo robot does next. Its default of 1 s is short on a
          // starved 2-core machine (the Servos test once missed it in CI); a poll that succeeds returns at once.
          expect: { poll: { timeout: 10_000 } },
          // Two browser files at a time (one per core): each has its own Chromium and page, and the app build
          // they share is made once (tests/e2e/harness.ts is safe when two files start together).
          fileParallelism: true,
        },
      },
    ],
  },
});
