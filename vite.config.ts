import { randomBytes } from "node:crypto";
import { defineConfig, type Plugin } from "vite";
import { VitePWA } from "vite-plugin-pwa";

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

function policyText(overrides: Record<string, string> = {}): string {
  return Object.entries({ ...CONTENT_SECURITY_POLICY, ...overrides })
    .map(([directive, value]) => `${directive} ${value}`)
    .join("; ");
}

/**
 * Puts the CSP into index.html as a `<meta http-equiv>`. The build gets the strict policy as it is. The dev
 * server gets the same policy with one difference: Vite's dev client injects imported CSS as `<style>`
 * elements, so there style-src also allows a nonce that is random per server start (`html.cspNonce` makes
 * Vite put it on those elements). Everything else (no inline scripts, no `style=` attributes, no eval, no
 * other origins) is enforced in dev too, so a violation shows up while developing.
 */
function contentSecurityPolicy(devNonce: string | undefined): Plugin {
  const policy = devNonce ? policyText({ "style-src": `'self' 'nonce-${devNonce}'` }) : policyText();
  const charset = '<meta charset="utf-8" />';
  return {
    name: "rbc-content-security-policy",
    transformIndexHtml: {
      order: "pre",
      handler(html) {
        // Right after the charset declaration, before anything that loads.
        if (!html.includes(charset)) throw new Error(`index.html must contain ${charset}`);
        return html.replace(
          charset,
          `${charset}\n    <meta http-equiv="Content-Security-Policy" content="${policy}" />`,
        );
      },
    },
  };
}

export default defineConfig(({ command }) => {
  const devNonce = command === "serve" ? randomBytes(16).toString("base64") : undefined;
  return {
    // Relative paths, so the built app works from any folder of a static host.
    base: "./",
    publicDir: "public",
    server: { host: "127.0.0.1" },
    preview: { host: "127.0.0.1" },
    html: devNonce ? { cspNonce: devNonce } : {},
    build: {
      target: "es2022",
      sourcemap: true,
      // The CSP forbids data: scripts and inline styles, so never inline assets as data URLs.
      assetsInlineLimit: 0,
    },
    plugins: [
      contentSecurityPolicy(devNonce),
      VitePWA({
        registerType: "autoUpdate",
        // Registration from a file (registerSW.js), never an inline script: the CSP forbids inline scripts.
        injectRegister: "script",
        // The web manifest is a static file in public/.
        manifest: false,
        workbox: {
          // Every built asset, including the lazily loaded views and the demo robot's simulator.
          globPatterns: ["**/*.{js,css,html,svg,webmanifest}"],
          navigateFallback: "index.html",
          cleanupOutdatedCaches: true,
          clientsClaim: true,
          skipWaiting: true,
        },
      }),
    ],
  };
});
