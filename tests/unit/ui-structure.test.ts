import { readdirSync, readFileSync, statSync } from "node:fs";
import { join, relative } from "node:path";
import { describe, expect, it } from "vitest";
import { controllerKey, Scope } from "../../src/ui/scope.ts";

/** The shape docs/architecture.md asks of the panel, checked on its sources. */

const UI = new URL("../../src/ui/", import.meta.url).pathname;

function sources(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return sources(path);
    return name.endsWith(".ts") && !name.endsWith(".d.ts") ? [path] : [];
  });
}

const files = sources(UI).map((path) => ({ path: relative(UI, path), text: readFileSync(path, "utf8") }));

describe("the panel's structure", () => {
  it("keeps no mutable state at module level (controllers live in the session's scopes)", () => {
    const offenders = files.flatMap(({ path, text }) =>
      text
        .split("\n")
        .map((line, i) => ({ line, at: `${path}:${i + 1}` }))
        .filter(
          ({ line }) =>
            /^(export )?(let|var) /.test(line) || /^(export )?const \w+(: [^=]+)? = new /.test(line),
        )
        .map(({ at, line }) => `${at}: ${line.trim()}`),
    );
    expect(offenders).toEqual([]);
  });

  it("has views that call actions and never write the store", () => {
    const views = files.filter(({ text }) => text.includes('from "lit-html"'));
    expect(views.length).toBeGreaterThan(10);
    const offenders = views.flatMap(({ path, text }) =>
      [...text.matchAll(/\.update\(|\bpatch[A-Z]\w*\(/g)].map((m) => `${path}: ${m[0]}`),
    );
    expect(offenders).toEqual([]);
  });

  it("keeps message catalogues (messages.ts) to data: they import nothing but src/i18n (docs/i18n.md)", () => {
    const catalogues = files.filter(({ path }) => path === "messages.ts" || path.endsWith("/messages.ts"));
    expect(catalogues.map((c) => c.path)).toEqual(
      expect.arrayContaining(["messages.ts", "shell/messages.ts"]),
    );
    const offenders = catalogues.flatMap(({ path, text }) =>
      [...text.matchAll(/from "([^"]+)"/g)]
        .map((m) => m[1] ?? "")
        .filter((from) => !/^(\.\.\/)+i18n\/[a-z-]+\.ts$/.test(from))
        .map((from) => `${path}: ${from}`),
    );
    expect(offenders).toEqual([]);
  });

  it("gives every feature its state, actions and views in src/ui/features/<name>/", () => {
    const features = readdirSync(join(UI, "features"));
    expect(features.sort()).toEqual([
      "class",
      "connection",
      "doctor",
      "editor",
      "firmware",
      "log",
      "motions",
      "robot",
      "sensors",
      "servos",
      "shelf",
      "zeros",
    ]);
    for (const feature of features) {
      const names = readdirSync(join(UI, "features", feature));
      expect(names, feature).toContain("state.ts");
      expect(
        names.some((n) => n === "actions.ts" || n.endsWith("-actions.ts")),
        feature,
      ).toBe(true);
    }
  });
});

describe("controller scopes", () => {
  it("create a controller once per scope, on first use, and dispose them when the scope ends", () => {
    const made: string[] = [];
    const disposed: string[] = [];
    const key = controllerKey("counter", (label: string) => {
      made.push(label);
      return { label, dispose: () => disposed.push(label) };
    });
    const first = new Scope("first", "connection");
    expect(first.peek(key)).toBeUndefined();
    expect(first.get(key)).toBe(first.get(key));
    const second = new Scope("second", "connection");
    expect(second.get(key)).not.toBe(first.get(key));
    expect(made).toEqual(["first", "second"]);
    first.dispose();
    first.dispose();
    expect(disposed).toEqual(["first"]);
    expect(first.ended).toBe(true);
    expect(first.peek(key)).toBeUndefined();
    expect(() => first.get(key)).toThrow(/has ended/);
  });

  it("dispose every controller even when one fails, the newest first", () => {
    const order: string[] = [];
    const a = controllerKey("a", () => ({ dispose: () => order.push("a") }));
    const b = controllerKey("b", () => ({
      dispose: () => {
        order.push("b");
        throw new Error("b failed");
      },
    }));
    const scope = new Scope(undefined, "page");
    scope.get(a);
    scope.get(b);
    scope.dispose();
    expect(order).toEqual(["b", "a"]);
  });
});
