import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { changelogHtml, changelogPage, singleFileChangelogSection } from "../../scripts/vite-changelog.ts";

describe("the changelog shipped with the panel (scripts/vite-changelog.ts)", () => {
  it("renders the Markdown subset CHANGELOG.md uses, escaping everything else", () => {
    const html = changelogHtml(
      [
        "# Changelog",
        "",
        "Intro <b>not bold</b> & more,",
        "on two lines.",
        "",
        "## 0.2.0",
        "- One `a<b>` item",
        "  continued, **strong**, *em*, [docs](docs/protocol.md) and [site](https://example.org/).",
        "- Two [bad](javascript:alert(1))",
      ].join("\n"),
    );
    expect(html).toBe(
      [
        "<h1>Changelog</h1>",
        "<p>Intro &lt;b&gt;not bold&lt;/b&gt; &amp; more, on two lines.</p>",
        "<h2>0.2.0</h2>",
        "<ul>",
        '<li>One <code>a&lt;b&gt;</code> item continued, <strong>strong</strong>, <em>em</em>, docs and <a href="https://example.org/">site</a>.</li>',
        "<li>Two bad)</li>",
        "</ul>",
      ].join("\n"),
    );
  });

  it("the page and the one-file section carry the project's CHANGELOG.md, the page with no script", () => {
    const markdown = readFileSync(new URL("../../CHANGELOG.md", import.meta.url), "utf8");
    const page = changelogPage(markdown);
    expect(page).toContain("<h1>Changelog</h1>");
    expect(page).not.toMatch(/<script/i);
    expect(page).toMatch(/Content-Security-Policy" content="default-src 'none'; style-src 'sha256-/);
    expect(singleFileChangelogSection(markdown)).toMatch(/<section id="changelog"[\s\S]*<h1>Changelog<\/h1>/);
  });
});
