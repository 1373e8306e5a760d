import type { Locale } from "../../i18n/locale.ts";
import { stopHoldsPoseText } from "../../i18n/outcomes/stop-pose.ts";
import { type Translator, translator } from "../../i18n/translate.ts";
import { FACTORY_ZEROS, STANDARD_ZEROS } from "../../protocol/zeros.ts";
import type { CommandHelp } from "../command.ts";
import { cliMessages } from "../messages.ts";
import { builtInMotionList } from "../motion-names.ts";
import { FAULT_KINDS } from "../sim-faults.ts";
import { soundList } from "../sound-names.ts";
import type { helpMessages } from "./messages.ts";

/**
 * Each command's help (`rbc COMMAND --help`, and its line in `rbc --help`) in the language of `t`: what
 * `CommandDef.help` gives. The texts are in messages.ts; flags and examples stay as they are typed.
 */

type HelpTranslator = Translator<typeof helpMessages>;
type Help = (t: HelpTranslator) => CommandHelp;

/** The trace lines `rbc log --help` shows (a trace is never translated). */
const TRACE_EXAMPLE = [
  "     0.001  PC→RBC  leave direct mode (blind)       FF E0 FB 01 00 1A",
  "     0.052  PC→RBC  0x12 Read firmware version      FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01",
  "     0.055  RBC→PC  0x12 Read firmware version      FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 17 15",
].join("\n");

/** What a failure of a JSON-lines command ends with. */
const JSON_FAILURE = '{"ok":false,"error":{…}}';

/** The question `rbc play` asks before a real robot moves, as it asks it. */
function playQuestion(locale: Locale): string {
  const t = translator(cliMessages, locale);
  return t("cli.play.question", { warning: t("cli.play.moveWarning") });
}

export const COMMAND_HELP = {
  ports: (t) => ({
    summary: t("cliHelp.ports.summary"),
    description: t("cliHelp.ports.description"),
    options: [],
  }),
  shelf: (t) => ({
    summary: t("cliHelp.shelf.summary"),
    description: t("cliHelp.shelf.description"),
    options: [],
  }),
  info: (t) => ({
    summary: t("cliHelp.info.summary"),
    description: t("cliHelp.info.description"),
    options: [],
  }),
  zeros: (t) => ({
    summary: t("cliHelp.zeros.summary"),
    description: t("cliHelp.zeros.description", {
      reference: STANDARD_ZEROS.join(" "),
      factory: FACTORY_ZEROS.join(" "),
    }),
    options: [
      ["--backup-dir DIR", t("cliHelp.zeros.backupDir")],
      ["--force", t("cliHelp.zeros.force")],
    ],
  }),
  upload: (t) => ({
    summary: t("cliHelp.upload.summary"),
    description: t("cliHelp.upload.description"),
    options: [
      ["--reset", t("cliHelp.upload.reset")],
      ["--action", t("cliHelp.upload.action")],
      ["-y, --yes", t("cliHelp.upload.yes")],
    ],
  }),
  run: (t) => ({
    summary: t("cliHelp.run.summary"),
    description: t("cliHelp.run.description", {
      motions: builtInMotionList(t.locale),
      holds: stopHoldsPoseText(t.locale),
    }),
    options: [["-y, --yes", t("cliHelp.run.yes")]],
  }),
  play: (t) => ({
    summary: t("cliHelp.play.summary"),
    description: t("cliHelp.play.description", { question: playQuestion(t.locale) }),
    options: [
      ["--scenes A-B", t("cliHelp.play.scenes")],
      ["-y, --yes", t("cliHelp.play.yes")],
    ],
  }),
  stop: (t) => ({
    summary: t("cliHelp.stop.summary"),
    description: t("cliHelp.stop.description", { holds: stopHoldsPoseText(t.locale) }),
    options: [],
  }),
  limp: (t) => ({
    summary: t("cliHelp.limp.summary"),
    description: t("cliHelp.limp.description"),
    options: [["-y, --yes", t("cliHelp.limp.yes")]],
  }),
  servos: (t) => ({
    summary: t("cliHelp.servos.summary"),
    description: t("cliHelp.servos.description"),
    options: [
      ["--ids A-B", t("cliHelp.servos.ids")],
      ["-y, --yes", t("cliHelp.servos.yes")],
    ],
  }),
  rbm: (t) => ({
    summary: t("cliHelp.rbm.summary"),
    description: t("cliHelp.rbm.description"),
    options: [
      ["--serial N", t("cliHelp.rbm.serial")],
      ["--zeros", t("cliHelp.rbm.zeros")],
      ["-o, --output OUT", t("cliHelp.rbm.output")],
    ],
  }),
  sound: (t) => ({
    summary: t("cliHelp.sound.summary"),
    description: t("cliHelp.sound.description", { sounds: soundList(t.locale) }),
    options: [],
  }),
  sensors: (t) => ({
    summary: t("cliHelp.sensors.summary"),
    description: t("cliHelp.sensors.description", { failure: JSON_FAILURE }),
    options: [
      ["--interval-ms MS", t("cliHelp.sensors.interval")],
      ["--count N", t("cliHelp.sensors.count")],
    ],
  }),
  log: (t) => ({
    summary: t("cliHelp.log.summary"),
    description: t("cliHelp.log.description", { trace: TRACE_EXAMPLE }),
    options: [],
  }),
  flash: (t) => ({
    summary: t("cliHelp.flash.summary"),
    description: t("cliHelp.flash.description"),
    options: [
      ["-y, --yes", t("cliHelp.flash.yes")],
      ["--recover", t("cliHelp.flash.recover")],
      ["--demo-file", t("cliHelp.flash.demoFile")],
    ],
  }),
  sim: (t) => ({
    summary: t("cliHelp.sim.summary"),
    description: t("cliHelp.sim.description"),
    options: [
      ["--pty", t("cliHelp.sim.pty")],
      ["--count N", t("cliHelp.sim.count")],
      ["--latency-ms N", t("cliHelp.sim.latency")],
      ["--baud-pacing", t("cliHelp.sim.baudPacing")],
      ["--fault KIND", t("cliHelp.sim.fault", { kinds: FAULT_KINDS.join(", ") })],
      ["--fault-every N", t("cliHelp.sim.faultEvery")],
      ["--fault-delay-ms N", t("cliHelp.sim.faultDelay")],
      ["--no-serial", t("cliHelp.sim.noSerial")],
      ["--no-status", t("cliHelp.sim.noStatus")],
      ["--firmware X.Y", t("cliHelp.sim.firmware")],
      ["--platform N", t("cliHelp.sim.platform")],
      ["--repeat-replies", t("cliHelp.sim.repeatReplies")],
      ["--repeat-type 0xNN", t("cliHelp.sim.repeatType")],
      ["--repeat-distance", t("cliHelp.sim.repeatDistance")],
      ["--firmware-events", t("cliHelp.sim.firmwareEvents")],
      ["--busy-motion N", t("cliHelp.sim.busyMotion")],
      ["--user-firmware", t("cliHelp.sim.userFirmware")],
      ["--no-memory-read", t("cliHelp.sim.noMemoryRead")],
      ["--servos-silent", t("cliHelp.sim.servosSilent")],
      ["--sound-reply-at-once", t("cliHelp.sim.soundReplyAtOnce")],
      ["--quick-repeat-posture", t("cliHelp.sim.quickRepeatPosture")],
      ["--no-zero-write", t("cliHelp.sim.noZeroWrite")],
      ["--servo-missing N", t("cliHelp.sim.servoMissing")],
      ["--servo-duplicate N", t("cliHelp.sim.servoDuplicate")],
      ["--servo-replacement N", t("cliHelp.sim.servoReplacement")],
      ["--servo-loaded N", t("cliHelp.sim.servoLoaded")],
      ["--servo-late N:MS", t("cliHelp.sim.servoLate")],
      ["--stale-servo-bytes N", t("cliHelp.sim.staleServoBytes")],
      ["--quiet", t("cliHelp.sim.quiet")],
      ["-p, --port PATH", t("cliHelp.sim.port")],
    ],
  }),
} as const satisfies Readonly<Record<string, Help>>;
