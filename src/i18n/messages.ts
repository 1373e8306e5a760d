import { defineMessages } from "./catalogue.ts";

/** The units the panel and the command line write numbers with (units.ts). */
export const unitMessages = defineMessages({
  "unit.bytes": { en: { one: "{count} byte", other: "{count} bytes" }, ko: "{count}바이트" },
  "unit.kilobytes": { en: "{size} KB", ko: "{size}KB" },
  "unit.seconds": { en: "{seconds} s", ko: "{seconds}초" },
  "unit.milliseconds": { en: "{ms} ms", ko: "{ms}ms" },
});
