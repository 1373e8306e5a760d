/**
 * The names a teacher gives the robots ("Robot 3", "Mina's robot"), kept in this browser by serial number
 * (IndexedDB, database "rbc-panel-class", store "names"), so the same robot gets its name again next lesson,
 * whichever port it is on. A robot that does not report a serial number (docs/protocol.md §3.5) cannot be
 * recognised again: its name lasts for the page. Storage sits behind `NameStorage`, so tests use a Map;
 * idb-keyval loads with the Class view.
 */

import { inEveryLanguage, type LocalText } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { type ClassTranslator, classMessages } from "./messages.ts";
import type { ClassRobot, ClassState } from "./state.ts";

export interface NameStorage {
  entries(): Promise<[serial: string, name: string][]>;
  set(serial: string, name: string): Promise<void>;
  remove(serial: string): Promise<void>;
}

/** A name is at most this long (it must fit a row on a phone). */
export const MAX_NAME_LENGTH = 40;

export function memoryNameStorage(map: Map<string, string> = new Map()): NameStorage {
  return {
    entries: async () => [...map.entries()],
    set: async (serial, name) => {
      map.set(serial, name);
    },
    remove: async (serial) => {
      map.delete(serial);
    },
  };
}

export const NAMES_DATABASE = "rbc-panel-class";
export const NAMES_STORE = "names";

export async function idbNameStorage(): Promise<NameStorage> {
  const idb = await import("idb-keyval");
  const store = idb.createStore(NAMES_DATABASE, NAMES_STORE);
  return {
    entries: async () =>
      (await idb.entries(store)).flatMap(([key, value]) =>
        typeof value === "string" ? [[String(key), value] as [string, string]] : [],
      ),
    set: (serial, name) => idb.set(serial, name, store),
    remove: (serial) => idb.del(serial, store),
  };
}

/** A name as typed, tidied: spaces trimmed and runs of white space made one, cut to MAX_NAME_LENGTH. */
export function tidyName(typed: string): string {
  return typed.replace(/\s+/g, " ").trim().slice(0, MAX_NAME_LENGTH);
}

/** The name the teacher gave it, else "Demo robot 2" or its port. */
export function robotTitle(t: ClassTranslator, c: ClassState, r: ClassRobot): string {
  const given = r.serialNumber ? c.names[r.serialNumber] : undefined;
  if (given) return given;
  return r.demoNumber !== undefined ? t("class.demoName", { number: r.demoNumber }) : r.portLabel;
}

/** Robot `id`'s name in every language (the top bar names it with its Stop result). */
export function robotNamed(c: ClassState, id: number): LocalText {
  const r = c.robots.find((robot) => robot.id === id);
  return inEveryLanguage((l) => (r ? robotTitle(translator(classMessages, l), c, r) : `#${id}`));
}

/** Robots named in a sentence, in the language's own way of listing: "Demo robot 1 and Mina's robot". */
export function robotList(t: ClassTranslator, c: ClassState, robots: readonly ClassRobot[]): string {
  const names = robots.map((r) => robotTitle(t, c, r));
  return new Intl.ListFormat(t.locale, { style: "long", type: "conjunction" }).format(names);
}
