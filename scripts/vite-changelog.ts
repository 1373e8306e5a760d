/**
 * The changelog shipped with the panel (issue 33, item 13): the version at the foot of the page links to the
 * project's CHANGELOG.md as it was when that panel was built, and the link works offline.
 *
 * - The hosted build (`npm run build`) gets `changelog.html` beside index.html: CHANGELOG.md as a small page of its
 *   own (its own CSP: no script, its one style by hash). The service worker precaches it with the other pages, so
 *   it opens offline too. The dev server serves the same page at the same address.
 * - The one-file panel (`npm run build:single`) has nothing beside it: the changelog is inside the page, a section
 *   at the end of the body that shows (over the panel) only when the address ends in `#changelog`. Its style is
 *   an inline `<style>`, hashed into the page's CSP like the panel's own.
 *
 * The link's target is `CHANGELOG_HREF` / `SINGLE_FILE_CHANGELOG_HREF` (vite.config.ts defines it for
 * src/ui/version.ts). The Markdown is the small subset CHANGELOG.md uses: headings, "- " list items (continued by
 * indented lines), paragraphs, `code`, **strong**, *emphasis* and [links](…); everything else is plain text.
 */
import { createHash } from "node:crypto";
import { readFileSync } from "node:fs";
import type { Plugin } from "vite";

/** The hosted build's changelog page, beside index.html. */
export const CHANGELOG_FILE = "changelog.html";
/** Where the hosted panel's version links to (relative: the panel lives under any sub-path). */
export const CHANGELOG_HREF = `./${CHANGELOG_FILE}`;
/** The one-file panel's changelog section, and its link. */
export const SINGLE_FILE_CHANGELOG_ID = "changelog";
export const SINGLE_FILE_CHANGELOG_HREF = `#${SINGLE_FILE_CHANGELOG_ID}`;

const escapeHtml = (text: string) =>
  text.replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;").replace(/"/g, "&quot;");

/**
 * Inline Markdown: `code` first (nothing inside it is markup), then links, strong and emphasis. Only web and
 * in-page links stay links: the repository's other files (docs/…) are not shipped with the panel.
 */
function inline(text: string): string {
  return text
    .split(/(`[^`]*`)/)
    .map((part) => {
      if (part.startsWith("`") && part.endsWith("`") && part.length >= 2)
        return `<code>${escapeHtml(part.slice(1, -1))}</code>`;
      return escapeHtml(part)
        .replace(/\[([^\]]+)\]\(([^)\s]+)\)/g, (_m, label: string, href: string) =>
          /^(https?:\/\/|#)/.test(href) ? `<a href="${href}">${label}</a>` : label,
        )
        .replace(/\*\*([^*]+)\*\*/g, "<strong>$1</strong>")
        .replace(/(^|[\s(])\*([^*\s][^*]*)\*/g, "$1<em>$2</em>");
    })
    .join("");
}

/** CHANGELOG.md as HTML (the subset it uses, see above). */
export function changelogHtml(markdown: string): string {
  const out: string[] = [];
  let paragraph: string[] = [];
  let item: string[] | undefined;
  let inList = false;
  const flushParagraph = () => {
    if (paragraph.length > 0) out.push(`<p>${inline(paragraph.join(" "))}</p>`);
    paragraph = [];
  };
  const flushItem = () => {
    if (item) out.push(`<li>${inline(item.join(" "))}</li>`);
    item = undefined;
  };
  const closeList = () => {
    flushItem();
    if (inList) out.push("</ul>");
    inList = false;
  };
  for (const raw of markdown.replace(/\r\n?/g, "\n").split("\n")) {
    const line = raw.trimEnd();
    const heading = /^(#{1,6})\s+(.*)$/.exec(line);
    const bullet = /^[-*]\s+(.*)$/.exec(line);
    if (heading) {
      flushParagraph();
      closeList();
      const level = heading[1]!.length;
      out.push(`<h${level}>${inline(heading[2]!)}</h${level}>`);
    } else if (bullet) {
      flushParagraph();
      flushItem();
      if (!inList) out.push("<ul>");
      inList = true;
      item = [bullet[1]!];
    } else if (line === "") {
      flushParagraph();
      closeList();
    } else if (item && /^\s/.test(raw)) {
      item.push(line.trim());
    } else {
      closeList();
      paragraph.push(line.trim());
    }
  }
  flushParagraph();
  closeList();
  return out.join("\n");
}

/** The changelog's look, the same in the page of its own and in the one-file panel's section. */
const PAGE_STYLE = `
  :root { color-scheme: light dark; }
  body { margin: 0; font: 16px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif; }
  main { max-width: 48rem; margin: 0 auto; padding: 1.5rem 1rem 3rem; }
  h1 { font-size: 1.75rem; } h2 { font-size: 1.35rem; margin-top: 2rem; } h3 { font-size: 1.1rem; }
  code { font-family: ui-monospace, Menlo, Consolas, monospace; font-size: 0.92em; }
  li { margin: 0.25rem 0; }
`;

const sha256 = (text: string) => `'sha256-${createHash("sha256").update(text, "utf8").digest("base64")}'`;

/** `changelog.html`: CHANGELOG.md as a page of its own, with no script and a CSP that allows only its style. */
export function changelogPage(markdown: string): string {
  const policy = `default-src 'none'; style-src ${sha256(PAGE_STYLE)}; base-uri 'none'; form-action 'none'`;
  return `<!doctype html>
<html lang="en">
  <head>
    <meta charset="utf-8" />
    <meta http-equiv="Content-Security-Policy" content="${policy}" />
    <meta name="viewport" content="width=device-width, initial-scale=1" />
    <meta name="color-scheme" content="light dark" />
    <title>Changelog · RBC Panel</title>
    <style>${PAGE_STYLE}</style>
  </head>
  <body>
    <main>
${changelogHtml(markdown)}
    </main>
  </body>
</html>
`;
}

/**
 * The one-file panel's changelog: hidden until the address ends in #changelog, then over the whole panel, with
 * a link back (an empty hash is no route: the panel stays on its view). Its rules are scoped to the section.
 */
export function singleFileChangelogSection(markdown: string): string {
  const id = SINGLE_FILE_CHANGELOG_ID;
  const style = `
  #${id} { display: none; }
  #${id}:target { display: block; position: fixed; inset: 0; z-index: 1000; overflow: auto;
    background: Canvas; color: CanvasText; font: 16px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif; }
  #${id} .changelog-body { max-width: 48rem; margin: 0 auto; padding: 1rem 1rem 3rem; }
  #${id} h1 { font-size: 1.75rem; } #${id} h2 { font-size: 1.35rem; margin-top: 2rem; }
  #${id} h3 { font-size: 1.1rem; } #${id} li { margin: 0.25rem 0; }
  #${id} code { font-family: ui-monospace, Menlo, Consolas, monospace; font-size: 0.92em; }
`;
  return `<style>${style}</style>
    <section id="${id}" lang="en" aria-label="Changelog" tabindex="-1">
      <div class="changelog-body">
        <p><a href="#">← RBC Panel</a></p>
${changelogHtml(markdown)}
      </div>
    </section>`;
}

/** The plugin: `single` for the one-file panel (the section inside the page), otherwise changelog.html. */
export function shippedChangelog(options: { file: string; single: boolean }): Plugin {
  const read = () => readFileSync(options.file, "utf8");
  return {
    name: "rbc-shipped-changelog",
    configureServer(server) {
      server.middlewares.use((req, res, next) => {
        if (!req.url || new URL(req.url, "http://dev").pathname !== `/${CHANGELOG_FILE}`) return next();
        res.setHeader("content-type", "text/html; charset=utf-8");
        res.end(changelogPage(read()));
      });
    },
    buildStart() {
      this.addWatchFile(options.file);
    },
    transformIndexHtml: {
      order: "post",
      handler(html, ctx) {
        if (!options.single || ctx.server) return html;
        if (!html.includes("</body>")) throw new Error("index.html has no </body> for the changelog section");
        return html.replace("</body>", () => `  ${singleFileChangelogSection(read())}\n  </body>`);
      },
    },
    generateBundle() {
      if (options.single) return;
      this.emitFile({ type: "asset", fileName: CHANGELOG_FILE, source: changelogPage(read()) });
    },
  };
}
