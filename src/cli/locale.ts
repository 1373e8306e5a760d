import { isLocale, type Locale } from "../i18n/locale.ts";

/**
 * The language rbc speaks: `--lang en|ko` on the command line, else the environment's (the first of LC_ALL,
 * LC_MESSAGES and LANG that is set, as POSIX orders them: "ko_KR.UTF-8" → Korean), else English. What rbc
 * prints for people follows it; `--json` output, packet traces and file names do not change.
 */

/** The environment variables that name the language of messages, the one that wins first. */
export const LOCALE_VARS = ["LC_ALL", "LC_MESSAGES", "LANG"] as const;

/** "ko_KR.UTF-8", "ko", "ko-KR" → Korean; "C", "en_GB.UTF-8", "POSIX", "kok_IN" → English. */
export function localeOfTag(tag: string): Locale {
  const primary = tag
    .trim()
    .split(/[-_.@]/)[0]
    ?.toLowerCase();
  return primary === "ko" ? "ko" : "en";
}

/** The language the environment asks for: the first of LC_ALL, LC_MESSAGES, LANG that is set and not empty. */
export function localeFromEnv(env: NodeJS.ProcessEnv): Locale {
  for (const name of LOCALE_VARS) {
    const value = env[name]?.trim();
    if (value) return localeOfTag(value);
  }
  return "en";
}

/**
 * The value of `--lang` in `argv` (`--lang ko` or `--lang=ko`, before any `--`), the last one given; `undefined`
 * when there is none. Read before the command parses its options, so that even a wrong command line is
 * answered in the language asked for.
 */
export function langArgument(argv: readonly string[]): string | undefined {
  let value: string | undefined;
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i]!;
    if (arg === "--") break;
    if (arg === "--lang") value = argv[++i] ?? "";
    else if (arg.startsWith("--lang=")) value = arg.slice("--lang=".length);
  }
  return value;
}

/**
 * The language for this run: `--lang` when it names one rbc speaks, else the environment's. `invalid` holds a
 * `--lang` value that is neither "en" nor "ko" (main refuses it, in the environment's language).
 */
export function cliLocale(
  argv: readonly string[],
  env: NodeJS.ProcessEnv,
): { locale: Locale; invalid: string | undefined } {
  const lang = langArgument(argv);
  if (lang === undefined) return { locale: localeFromEnv(env), invalid: undefined };
  const wanted = lang.trim().toLowerCase();
  if (isLocale(wanted)) return { locale: wanted, invalid: undefined };
  return { locale: localeFromEnv(env), invalid: lang };
}
