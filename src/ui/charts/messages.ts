import { defineMessages } from "../../i18n/catalogue.ts";

/** The charts' own words (what a chart says is worded by its caller, in `ChartSpec`). */
export const chartMessages = defineMessages({
  "charts.loadFailed": {
    en: "The chart could not be loaded (offline?). The figures beside it are still current.",
    ko: "차트를 불러오지 못했어요 (오프라인인가요?). 옆의 수치는 여전히 최신 값이에요.",
  },
});
