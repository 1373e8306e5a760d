/**
 * Attributes the bytes of a built JavaScript file to its sources using the file's source map (only the
 * "mappings", "sources" fields of a v3 map are read; no dependency). Used to say what fills the initial bundle.
 */

const BASE64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
const DIGIT = new Map([...BASE64].map((c, i) => [c, i]));

/** Decodes one segment of Base64 VLQ numbers. */
function decodeVlq(segment: string): number[] {
  const out: number[] = [];
  let value = 0;
  let shift = 0;
  for (const c of segment) {
    const digit = DIGIT.get(c);
    if (digit === undefined) throw new Error(`bad VLQ character "${c}"`);
    value += (digit & 31) << shift;
    if (digit & 32) {
      shift += 5;
      continue;
    }
    out.push(value & 1 ? -(value >>> 1) : value >>> 1);
    value = 0;
    shift = 0;
  }
  return out;
}

export interface SourceShare {
  source: string;
  /** Generated characters attributed to this source. */
  chars: number;
}

/**
 * Generated characters per source file, largest first. Characters not covered by any mapping are reported as
 * "(unmapped)". `code` is the generated file's text, `map` its parsed source map.
 */
export function bytesBySource(code: string, map: { sources: string[]; mappings: string }): SourceShare[] {
  const lines = code.split("\n");
  const totals = new Map<string, number>();
  const add = (source: string, n: number) => totals.set(source, (totals.get(source) ?? 0) + n);
  const mapLines = map.mappings.split(";");
  let sourceIndex = 0;
  for (let l = 0; l < lines.length; l++) {
    const line = lines[l] ?? "";
    const segments = (mapLines[l] ?? "").split(",").filter((s) => s.length > 0);
    let column = 0;
    let previousColumn = 0;
    let previousSource: string | undefined;
    for (const segment of segments) {
      const fields = decodeVlq(segment);
      column += fields[0] ?? 0;
      add(previousSource ?? "(unmapped)", column - previousColumn);
      if (fields.length >= 4) {
        sourceIndex += fields[1] ?? 0;
        previousSource = map.sources[sourceIndex] ?? "(unknown)";
      } else {
        previousSource = undefined;
      }
      previousColumn = column;
    }
    add(previousSource ?? "(unmapped)", line.length - previousColumn + 1);
  }
  return [...totals]
    .map(([source, chars]) => ({ source, chars }))
    .filter((s) => s.chars > 0)
    .sort((a, b) => b.chars - a.chars);
}

/** Groups sources by package (node_modules/<pkg>) or by folder under src/, for a short summary. */
export function groupShares(shares: readonly SourceShare[]): SourceShare[] {
  const totals = new Map<string, number>();
  for (const { source, chars } of shares) {
    const clean = source.replace(/\\/g, "/").replace(/^(\.\.\/)+/, "");
    const pkg = /node_modules\/((?:@[^/]+\/)?[^/]+)/.exec(clean);
    const src = /(?:^|\/)src\/([^/]+)\//.exec(clean);
    const key = pkg ? `npm:${pkg[1]}` : src ? `src/${src[1]}` : clean;
    totals.set(key, (totals.get(key) ?? 0) + chars);
  }
  return [...totals].map(([source, chars]) => ({ source, chars })).sort((a, b) => b.chars - a.chars);
}
