import type { ParamArgs } from "../../../../i18n/catalogue.ts";
import { type LocalText, type Said, said } from "../../../../i18n/said.ts";
import { zerosLiveMessages } from "./messages.ts";

/** Trim live's and Capture zeros' outcomes as data: a key of their catalogue and its facts, worded at render. */
export const say = <K extends keyof typeof zerosLiveMessages & string>(
  key: K,
  ...facts: ParamArgs<(typeof zerosLiveMessages)[K], Said | LocalText>
): Said => said(zerosLiveMessages, key, ...facts);
