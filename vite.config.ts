import { execFileSync } from "node:child_process";
import { createHash, randomBytes } from "node:crypto";
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { defineConfig, type Plugin } from "vite";
import { VitePWA } from "vite-plugin-pwa";
import { viteSingleFile } from "vite-plugin-singlefile";
import { CHANGELOG_HREF, SINGLE_FILE_CHANGELOG_HREF, shippedChangelog } from "./scripts/vite-changelog.ts";
import { wordsPerLanguage } from "./scripts/vite-words-per-language.ts";

/** The policy of the built app: everything from our own origin, nothing inline, no eval. */
export const CONTENT_SECURITY_POLICY: Readonly<Record<string, string>> = {
  "default-src": "'self'",
  "script-src": "'self'",
  "style-src": "'self'",
  "img-src": "'self' data:",
  "connect-src": "'self'",
  "worker-src": "'self'",
  "manifest-src": "'self'",
  "object-src": "'none'",
  "base-uri": "'none'",
  "form-action": "'none'",
};

/**
 * The policy of the one-file panel (`npm run build:single`). It is opened from disk, where 'self' means
 * nothing useful, so it allows no origin at all: its own inline scripts and styles by their hashes (filled in
 * after the code is inlined), images only as data: URLs, no fetch, no worker, no manifest, still no eval.
 */
export const SINGLE_FILE_POLICY: Readonly<Record<string, string>> = {
  "default-src": "'none'",
  "script-src": "",
  "style-src": "",
  "img-src": "data:",
  "connect-src": "'none'",
  "worker-src": "'none'",
  "manifest-src": "'none'",
  "object-src": "'none'",
  "base-uri": "'none'",
  "form-action": "'none'",
};

/** The mode of `vite build --mode single`, and the one file it writes (into build.outDir, dist/ by default). */
export const SINGLE_FILE_MODE = "single";
export const SINGLE_FILE_NAME = "rbc-panel.html";

const CSP_PLACEHOLDER = "__RBC_SINGLE_FILE_CSP__";

function policyText(
  policy: Readonly<Record<string, string>>,
  overrides: Record<string, string> = {},
): string {
  return Object.entries({ ...policy, ...overrides })
    .map(([directive, value]) => `${directive} ${value}`.trim())
    .join("; ");
}

/** The project folder, as an absolute path without a trailing slash. */
const ROOT = fileURLToPath(new URL(".", import.meta.url)).replace(/\/$/, "");

const CHARSET = '<meta charset="utf-8" />';

/** Inserts `tags` right after the charset declaration, before anything that loads. */
function afterCharset(html: string, tags: string): string {
  if (!html.includes(CHARSET)) throw new Error(`index.html must contain ${CHARSET}`);
  return html.replace(CHARSET, () => `${CHARSET}\n    ${tags}`);
}

/**
 * Puts the CSP into index.html as a `<meta http-equiv>`. The build gets the strict policy as it is. The dev
 * server gets the same policy with one difference: Vite's dev client injects imported CSS as `<style>`
 * elements, so there style-src also allows a nonce that is random per server start (`html.cspNonce` makes
 * Vite put it on those elements). Everything else (no inline scripts, no `style=` attributes, no eval, no
 * other origins) is enforced in dev too, so a violation shows up while developing.
 *
 * It also starts the service worker's update prompt (src/ui/update-prompt.ts) from a module script that Vite
 * bundles into the entry chunk (an inline module in the source HTML is never inline in the built page). The
 * prompt and the service worker's registration load with import(), beside the first load rather than in it
 * (they have nothing to draw before a new version is ready; first load: issue 19).
 */
function contentSecurityPolicy(devNonce: string | undefined): Plugin {
  const policy = devNonce
    ? policyText(CONTENT_SECURITY_POLICY, { "style-src": `'self' 'nonce-${devNonce}'` })
    : policyText(CONTENT_SECURITY_POLICY);
  return {
    name: "rbc-content-security-policy",
    transformIndexHtml: {
      order: "pre",
      handler(html) {
        const withPolicy = afterCharset(
          html,
          `<meta http-equiv="Content-Security-Policy" content="${policy}" />`,
        );
        return withPolicy.replace(
          "</body>",
          () =>
            '  <script type="module">\n' +
            '      Promise.all([import("virtual:pwa-register"), import("/src/ui/update-prompt.ts")]).then(\n' +
            "        ([pwa, prompt]) => prompt.startUpdatePrompt(pwa.registerSW),\n" +
            "      );\n" +
            "    </script>\n  </body>",
        );
      },
    },
  };
}

const sha256 = (text: string) => `'sha256-${createHash("sha256").update(text, "utf8").digest("base64")}'`;

/**
 * The one-file panel: index.html without the web manifest (nothing to install from disk) and with the icon
 * as a data: URL; after vite-plugin-singlefile has inlined every script and style sheet (the lazily loaded
 * views too: code splitting is off), the CSP gets the hash of each inline `<script>` and `<style>`, and the
 * page is written as rbc-panel.html. Anything else left in the bundle fails the build: the file must need
 * nothing beside it.
 */
function singleFilePage(): Plugin {
  // encodeURIComponent leaves no quote, backtick, `$` or `\` in it: safe inside any string or attribute.
  const icon = readFileSync(new URL("public/icon.svg", import.meta.url), "utf8");
  const iconUrl = `data:image/svg+xml,${encodeURIComponent(icon)}`;
  return {
    name: "rbc-single-file-page",
    enforce: "post",
    // The top bar shows the icon by its public path ("./icon.svg"), a file that is not beside the one-file
    // panel: there it is the same data: URL.
    renderChunk(code) {
      return code.includes('"./icon.svg"') ? code.replaceAll('"./icon.svg"', () => `"${iconUrl}"`) : null;
    },
    transformIndexHtml: {
      order: "pre",
      handler(html) {
        const page = html
          .replace(/\s*<link rel="manifest"[^>]*>/, "")
          .replace(/<link rel="icon" href="[^"]*"/, () => `<link rel="icon" href="${iconUrl}"`);
        if (page.includes('rel="manifest"') || !page.includes(iconUrl))
          throw new Error("index.html: the icon or manifest link is not where the one-file build expects it");
        return afterCharset(
          page,
          `<meta http-equiv="Content-Security-Policy" content="${CSP_PLACEHOLDER}" />`,
        );
      },
    },
    generateBundle: {
      order: "post",
      handler(_options, bundle) {
        const names = Object.keys(bundle);
        const page = bundle["index.html"];
        if (page?.type !== "asset") throw new Error("the one-file build produced no index.html");
        const leftovers = names.filter((n) => n !== "index.html");
        if (leftovers.length > 0)
          throw new Error(`the one-file build left files beside the page: ${leftovers.join(", ")}`);
        const html = String(page.source);
        const scripts = [...html.matchAll(/<script\b[^>]*>([\s\S]*?)<\/script>/gi)];
        const styles = [...html.matchAll(/<style\b[^>]*>([\s\S]*?)<\/style>/gi)];
        if (scripts.some((m) => /\bsrc=/.test(m[0].slice(0, m[0].indexOf(">")))))
          throw new Error("the one-file page still loads a script from a file");
        if (/<link\b[^>]*rel="(?:stylesheet|modulepreload)"/.test(html))
          throw new Error("the one-file page still links a style sheet or module");
        const policy = policyText(SINGLE_FILE_POLICY, {
          "script-src": scripts.map((m) => sha256(m[1] ?? "")).join(" ") || "'none'",
          "style-src": styles.map((m) => sha256(m[1] ?? "")).join(" ") || "'none'",
        });
        if (!html.includes(CSP_PLACEHOLDER)) throw new Error("the one-file page lost its CSP placeholder");
        delete bundle["index.html"];
        this.emitFile({
          type: "asset",
          fileName: SINGLE_FILE_NAME,
          source: html.replace(CSP_PLACEHOLDER, () => policy),
        });
      },
    },
  };
}

function git(args: string[]): string | undefined {
  try {
    return execFileSync("git", args, { encoding: "utf8", stdio: ["ignore", "pipe", "ignore"] }).trim();
  } catch {
    return undefined;
  }
}

/**
 * What the page says about itself (src/ui/version.ts): the package version, the commit it was built from and
 * where its changes are listed: the changelog shipped with the build (scripts/vite-changelog.ts), a page beside
 * the hosted panel or a section inside the one-file panel, so the link works offline and needs no repository.
 */
function buildInfo(single: boolean): { version: string; commit: string; changelogUrl: string } {
  const pkg = JSON.parse(readFileSync(new URL("package.json", import.meta.url), "utf8")) as {
    version: string;
  };
  const commit = process.env.GITHUB_SHA?.slice(0, 7) ?? git(["rev-parse", "--short=7", "HEAD"]) ?? "unknown";
  return {
    version: pkg.version,
    commit,
    changelogUrl: single ? SINGLE_FILE_CHANGELOG_HREF : CHANGELOG_HREF,
  };
}

export default defineConfig(({ command, mode }) => {
  const devNonce = command === "serve" ? randomBytes(16).toString("base64") : undefined;
  const single = mode === SINGLE_FILE_MODE;
  const info = buildInfo(single);
  const changelog = shippedChangelog({ file: `${ROOT}/CHANGELOG.md`, single });
  return {
    // Relative paths, so the built app works from any folder of a static host (GitHub Pages: /<repository>/).
    base: "./",
    // The one-file panel carries its icon inline and has no manifest: nothing from public/ goes beside it.
    publicDir: single ? false : "public",
    server: { host: "127.0.0.1" },
    preview: { host: "127.0.0.1" },
    html: devNonce ? { cspNonce: devNonce } : {},
    define: {
      __RBC_VERSION__: JSON.stringify(info.version),
      __RBC_COMMIT__: JSON.stringify(info.commit),
      __RBC_CHANGELOG_URL__: JSON.stringify(info.changelogUrl),
    },
    build: single
      ? {
          target: "es2022",
          // Written beside the hosted build's files (dist/rbc-panel.html), which it leaves alone.
          outDir: "dist",
          emptyOutDir: false,
          sourcemap: false,
          // No preload links to polyfill: every module is in the page.
          modulePreload: false,
          // One page holds everything, three.js (the 3D robot) included.
          chunkSizeWarningLimit: 2000,
        }
      : {
          target: "es2022",
          sourcemap: true,
          // The CSP forbids data: scripts and inline styles, so never inline assets as data URLs.
          assetsInlineLimit: 0,
          // three.js (the 3D robot, 536 KB, 131 KB gzip) is one lazily loaded chunk, loaded only by the views
          // that show the robot; the first page load stays within its budget (npm run check:bundle).
          chunkSizeWarningLimit: 600,
          rolldownOptions: {
            output: {
              codeSplitting: {
                // Everything the first page needs (the entry's static imports, not the lazily loaded views)
                // in one chunk: a module the entry shares with a lazily loaded view would otherwise get a
                // chunk of its own, and each small file gzips worse than one (about 1.5 KB over the first
                // load, issue 19).
                groups: [{ name: "index", tags: ["$initial"] }],
              },
            },
          },
        },
    plugins: single
      ? [
          // Inlines scripts and styles; its recommended config turns code splitting off (Vite 8:
          // `codeSplitting: false`), so the lazily loaded views and the demo robot are in the page too.
          viteSingleFile(),
          singleFilePage(),
          changelog,
        ]
      : [
          contentSecurityPolicy(devNonce),
          changelog,
          // Each catalogue's languages in chunks of their own: the first load carries only the words of the
          // page's language (docs/i18n.md, "One language at a time"). Not in the one-file panel, which works
          // offline and so carries both.
          wordsPerLanguage({
            root: ROOT,
            locales: ["en", "ko"],
            runtime: `${ROOT}/src/i18n/split-catalogue.ts`,
            source: `${ROOT}/src`,
          }),
          VitePWA({
            // A new version waits until the owner chooses to reload (src/ui/update-prompt.ts): never a reload
            // by itself, which could cut an upload to the robot short.
            registerType: "prompt",
            // Registered by src/ui/update-prompt.ts (virtual:pwa-register), bundled into the entry chunk.
            injectRegister: false,
            // The web manifest is a static file in public/.
            manifest: false,
            workbox: {
              // Every built asset, including the lazily loaded views and the demo robot's simulator; not the
              // one-file panel, which is there to be downloaded.
              globPatterns: ["**/*.{js,css,html,svg,webmanifest}"],
              globIgnores: [SINGLE_FILE_NAME],
              navigateFallback: "index.html",
              navigateFallbackDenylist: [/rbc-panel\.html$/],
              cleanupOutdatedCaches: true,
              // The first visit is controlled at once (offline from then on); an update is not: it waits
              // for the owner's "Reload" (workbox answers the prompt's SKIP_WAITING message).
              clientsClaim: true,
              skipWaiting: false,
            },
          }),
        ],
  };
});
