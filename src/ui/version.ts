import { html, nothing, type TemplateResult } from "lit-html";
import type { Locale } from "../i18n/locale.ts";
import { translator } from "../i18n/translate.ts";
import { uiMessages } from "./messages.ts";

/**
 * Which panel this is: the package version and the commit it was built from, and where its changes are
 * listed: the CHANGELOG.md shipped with this build (scripts/vite-changelog.ts: `./changelog.html` beside the
 * hosted panel, `#changelog` inside the one-file panel; both open offline). vite.config.ts fills these in at
 * build time (`define`); where they are not defined (unit tests), the panel says "development".
 */
declare const __RBC_VERSION__: string;
declare const __RBC_COMMIT__: string;
declare const __RBC_CHANGELOG_URL__: string;

export interface PanelVersion {
  version: string;
  commit: string;
  /** The shipped changelog; empty where there is none (unit tests). */
  changelogUrl: string;
}

export const PANEL_VERSION: PanelVersion = {
  version: typeof __RBC_VERSION__ === "string" ? __RBC_VERSION__ : "development",
  commit: typeof __RBC_COMMIT__ === "string" ? __RBC_COMMIT__ : "unknown",
  changelogUrl: typeof __RBC_CHANGELOG_URL__ === "string" ? __RBC_CHANGELOG_URL__ : "",
};

/** "Version 0.1.0 (67f4344)" / "버전 0.1.0 (67f4344)". */
export function versionText(info: PanelVersion = PANEL_VERSION, locale: Locale = "en"): string {
  const t = translator(uiMessages, locale);
  return info.commit === "unknown"
    ? t("version.number", { version: info.version })
    : t("version.numberCommit", { version: info.version, commit: info.commit });
}

/**
 * A small line for the foot of the page: the version and "What changed". The changelog page opens in a new tab
 * (leaving the panel would drop the robot's connection); the one-file panel's section is in the page itself.
 */
export function versionFooter(info: PanelVersion = PANEL_VERSION, locale: Locale = "en"): TemplateResult {
  const t = translator(uiMessages, locale);
  return html`
    <p class="muted panel-version" data-testid="panel-version">
      ${t("panel.name")} · ${versionText(info, locale)}${
        info.changelogUrl
          ? info.changelogUrl.startsWith("#")
            ? html` · <a href=${info.changelogUrl} data-testid="changelog-link">${t("version.whatChanged")}</a>`
            : html` · <a href=${info.changelogUrl} target="_blank" rel="noopener" data-testid="changelog-link">${t("version.whatChanged")}</a>`
          : nothing
      }
    </p>
  `;
}
