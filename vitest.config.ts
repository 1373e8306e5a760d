import { defineConfig } from "vitest/config";

export default defineConfig({
  test: {
    // Vitest's default on a 2-core machine is one worker (cores - 1), which runs every file one after another;
    // most of the suite waits on a browser or a child process rather than the CPU, so two workers fit.
    maxWorkers: 2,
    reporters: process.env.CI
      ? ["default", ["json", { outputFile: "test-results/vitest.json" }]]
      : ["default"],
    projects: [
      {
        extends: true,
        test: {
          name: "unit",
          include: ["tests/unit/**/*.test.ts", "tests/interop/**/*.test.ts"],
          environment: "node",
          testTimeout: 10_000,
        },
      },
      {
        extends: true,
        test: {
          name: "e2e",
          include: ["tests/e2e/**/*.test.ts"],
          environment: "node",
          testTimeout: 60_000,
          hookTimeout: 120_000,
          // Two browser files at a time (one per core): each has its own Chromium and page, and the app build
          // they share is made once (tests/e2e/harness.ts is safe when two files start together).
          fileParallelism: true,
        },
      },
    ],
  },
});
