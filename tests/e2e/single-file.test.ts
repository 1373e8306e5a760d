import { readFile, rm } from "node:fs/promises";
import { join } from "node:path";
import { pathToFileURL } from "node:url";
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { launchChromium } from "../support/chromium.ts";
import { buildOnce, ROOT } from "./harness.ts";
import { buildSingleFile, cspViolations, injectedPage, walkPanel, watchRequests } from "./single-harness.ts";
import "./rbc-test-globals.ts";

let browser: Browser;
let built: { dir: string; file: string };
let fakeSerial: string;

beforeAll(async () => {
  [built, { fakeSerial }] = await Promise.all([buildSingleFile(), buildOnce()]);
  browser = await launchChromium();
});

afterAll(async () => {
  await browser?.close();
  if (built) await rm(built.dir, { recursive: true, force: true });
});

describe("the one-file panel (npm run build:single)", () => {
  it("is one HTML file whose CSP allows no origin, only its own inline code by hash, and no eval", async () => {
    const html = await readFile(built.file, "utf8");
    const csp = /<meta http-equiv="Content-Security-Policy" content="([^"]+)"/.exec(html)?.[1] ?? "";
    const directives = new Map(
      csp.split(";").map((d) => {
        const [name, ...values] = d.trim().split(/\s+/);
        return [name, values] as const;
      }),
    );
    expect(directives.get("default-src")).toEqual(["'none'"]);
    for (const name of ["script-src", "style-src"]) {
      const values = directives.get(name) ?? [];
      expect(values.length).toBeGreaterThan(0);
      for (const v of values) expect(v).toMatch(/^'sha256-[A-Za-z0-9+/]+=*'$/);
    }
    expect(directives.get("connect-src")).toEqual(["'none'"]);
    expect(directives.get("img-src")).toEqual(["data:"]);
    expect(csp).not.toMatch(/unsafe-eval|unsafe-inline|'self'|https?:|\*/);
    // Nothing to fetch beside it: no script or style sheet file, no manifest, the icon inline.
    expect(html).not.toMatch(/<script[^>]*\bsrc=/);
    expect(html).not.toMatch(/<link[^>]*rel="(stylesheet|modulepreload|manifest)"/);
    expect(html).toMatch(/<link rel="icon" href="data:image\/svg\+xml,/);
    expect(html).not.toMatch(/\bimport\(\s*["'`]/);
  });

  it("opened from disk: demo robot and serial robot, every view, an example uploaded, no request at all", async () => {
    const { page, context } = await injectedPage(browser, fakeSerial);
    const fileUrl = pathToFileURL(built.file).href;
    const seen = watchRequests(page, (url) => url === fileUrl || url.startsWith(`${fileUrl}#`));
    await page.goto(fileUrl);
    expect(await page.evaluate(() => window.isSecureContext)).toBe(true);
    await walkPanel(page);
    // No service worker on a file:// page.
    expect(await page.evaluate(() => navigator.serviceWorker?.controller ?? null)).toBeNull();
    expect(await page.getByTestId("update-prompt").count()).toBe(0);

    expect(seen.unexpected).toEqual([]);
    expect(seen.requests.filter((u) => !u.startsWith("data:") && !u.startsWith("blob:"))).toEqual([fileUrl]);
    expect(seen.errors).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("its version links to the changelog inside the page, which opens from disk with no request", async () => {
    const { page, context } = await injectedPage(browser, fakeSerial);
    const fileUrl = pathToFileURL(built.file).href;
    const seen = watchRequests(page, (url) => url === fileUrl || url.startsWith(`${fileUrl}#`));
    await page.goto(fileUrl);
    const firstHeading = /^# (.+)$/m.exec(await readFile(join(ROOT, "CHANGELOG.md"), "utf8"))?.[1] ?? "";
    expect(firstHeading).not.toBe("");
    const changelog = page.getByRole("heading", { level: 1, name: firstHeading, exact: true });
    expect(await changelog.isVisible()).toBe(false);
    await page.getByTestId("panel-version").getByRole("link", { name: "What changed" }).click();
    await changelog.waitFor();
    expect(new URL(page.url()).hash).toBe("#changelog");
    // Back to the panel, on the view it was on.
    await page.getByRole("link", { name: "← RBC Panel" }).click();
    await changelog.waitFor({ state: "hidden" });
    await page.getByRole("button", { name: "Try the demo robot" }).waitFor();
    expect(seen.unexpected).toEqual([]);
    expect(seen.errors).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });
});
