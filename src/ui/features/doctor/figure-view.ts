import { html, nothing, type SVGTemplateResult, svg, type TemplateResult } from "lit-html";
import type { ServoReading } from "../../../device/servo-doctor/index.ts";
import type { KeysWithoutParams } from "../../../i18n/catalogue.ts";
import type { DoctorTranslator, doctorMessages } from "./messages.ts";
import {
  FIGURE_HEIGHT,
  FIGURE_MIDDLE,
  FIGURE_WIDTH,
  type FigurePoint,
  figurePoints,
  markOf,
  type ServoMark,
} from "./model.ts";

/**
 * The flat HUNO figure: each servo 0-15 a mark on the robot, facing the viewer (its left on the viewer's right),
 * coloured by what the scan read and shaped so that colour is never the only cue (a filled circle answered, a
 * ring with a bar a high load, a dashed ring silent, a diamond garbled, a thin ring not read). A click picks the
 * servo. It is a picture of the table beside it, which is the accessible form: the SVG is hidden from screen
 * readers and its marks are not focusable (the table's buttons pick a servo by keyboard).
 */

const R = 10;

function shape(mark: ServoMark, p: FigurePoint): SVGTemplateResult {
  if (mark === "garbled") {
    const d = R + 2;
    return svg`<polygon class="mark-shape" points=${`${p.x},${p.y - d} ${p.x + d},${p.y} ${p.x},${p.y + d} ${p.x - d},${p.y}`} />`;
  }
  if (mark === "high-load") {
    return svg`<circle class="mark-shape" cx=${p.x} cy=${p.y} r=${R} /><line class="mark-bar" x1=${p.x - R - 3} y1=${p.y + R + 3} x2=${p.x + R + 3} y2=${p.y + R + 3} />`;
  }
  return svg`<circle class="mark-shape" cx=${p.x} cy=${p.y} r=${R} />`;
}

function servoMark(
  p: FigurePoint,
  mark: ServoMark,
  picked: boolean,
  onPick: (id: number) => void,
): SVGTemplateResult {
  return svg`
    <g class=${`servo-mark mark--${mark}${picked ? " is-picked" : ""}`} data-servo=${p.id} @click=${() => onPick(p.id)}>
      ${picked ? svg`<circle class="mark-pick" cx=${p.x} cy=${p.y} r=${R + 5} />` : nothing}
      ${shape(mark, p)}
      <text class="mark-id" x=${p.x} y=${p.y} dy="0.35em">${p.id}</text>
    </g>
  `;
}

/** The body: head, trunk, the limbs as lines through their servos. */
function body(points: readonly FigurePoint[]): SVGTemplateResult {
  const at = (id: number) => points[id] ?? { x: 0, y: 0 };
  const limb = (ids: number[], from: { x: number; y: number }) =>
    svg`<polyline class="limb" points=${[from, ...ids.map(at)].map((q) => `${q.x},${q.y}`).join(" ")} />`;
  const m = FIGURE_MIDDLE;
  return svg`
    <circle class="body" cx=${m} cy="34" r="18" />
    <rect class="body" x=${m - 30} y="58" width="60" height="78" rx="10" />
    ${limb([10, 11, 12], { x: m + 28, y: 70 })}
    ${limb([13, 14, 15], { x: m - 28, y: 70 })}
    ${limb([0, 1, 2, 3, 4], { x: m + 18, y: 136 })}
    ${limb([5, 6, 7, 8, 9], { x: m - 18, y: 136 })}
    <line class="foot" x1=${m + 10} y1="284" x2=${m + 46} y2="284" />
    <line class="foot" x1=${m - 10} y1="284" x2=${m - 46} y2="284" />
  `;
}

const LEGEND: readonly { mark: ServoMark; key: KeysWithoutParams<typeof doctorMessages> }[] = [
  { mark: "answered", key: "doctor.legend.answered" },
  { mark: "high-load", key: "doctor.legend.highLoad" },
  { mark: "silent", key: "doctor.legend.silent" },
  { mark: "garbled", key: "doctor.legend.garbled" },
  { mark: "unread", key: "doctor.legend.unread" },
];

function legendSwatch(mark: ServoMark): TemplateResult {
  const p: FigurePoint = { id: 0, x: 14, y: 14, side: "left" };
  return html`<svg class="legend-swatch" viewBox="0 0 28 30" width="22" height="24" aria-hidden="true">
    <g class=${`servo-mark mark--${mark}`}>${shape(mark, p)}</g>
  </svg>`;
}

export function servoFigure(
  t: DoctorTranslator,
  readings: readonly ServoReading[],
  highLoad: readonly number[],
  picked: number | undefined,
  onPick: (id: number) => void,
): TemplateResult {
  const points = figurePoints();
  const byId = new Map(readings.map((r) => [r.id, r]));
  return html`
    <figure class="servo-figure" data-testid="servo-figure">
      <svg
        viewBox=${`0 0 ${FIGURE_WIDTH} ${FIGURE_HEIGHT}`}
        role="presentation"
        aria-hidden="true"
        focusable="false"
      >
        ${body(points)}
        <text class="side-label" x="6" y="14">${t("doctor.figure.itsRight")}</text>
        <text class="side-label" x=${FIGURE_WIDTH - 6} y="14" text-anchor="end">${t("doctor.figure.itsLeft")}</text>
        ${points.map((p) => servoMark(p, markOf(byId.get(p.id), highLoad), p.id === picked, onPick))}
      </svg>
      <figcaption>
        <ul class="mark-legend" aria-label=${t("doctor.legend.label")}>
          ${LEGEND.map(({ mark, key }) => html`<li>${legendSwatch(mark)}<span>${t(key)}</span></li>`)}
        </ul>
      </figcaption>
    </figure>
  `;
}
