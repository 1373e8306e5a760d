import { RbcError } from "../device/errors.ts";
import { LinkError } from "../link/transport.ts";
import type { Notice } from "./app-state.ts";
import { domErrorName } from "./serial-ports.ts";

/** Turns failures into notices: what went wrong in the user's terms, with the technical detail apart. */

/** "RbcTimeoutError (timeout): The robot did not answer …" — for the "Details" disclosure. */
export function technicalDetail(e: unknown): string {
  if (e instanceof RbcError || e instanceof LinkError) {
    const cause = e.cause === undefined ? "" : ` — caused by ${technicalDetail(e.cause)}`;
    return `${e.name} (${e.code}): ${e.message}${cause}`;
  }
  if (e instanceof Error) return `${e.name}: ${e.message}`;
  return String(e);
}

/** The message a person reads: RbcError and LinkError messages already say what to do. */
export function errorMessage(e: unknown): string {
  if (e instanceof RbcError || e instanceof LinkError) return e.message;
  if (e instanceof Error && e.message) return e.message;
  return "Something unexpected went wrong.";
}

export function errorNotice(lead: string, e: unknown): Notice {
  return { tone: "danger", text: `${lead} ${errorMessage(e)}`, detail: technicalDetail(e) };
}

export function connectProblem(e: unknown): Notice {
  if (e instanceof LinkError || e instanceof RbcError) {
    return { tone: "danger", text: `Could not connect. ${e.message}`, detail: technicalDetail(e) };
  }
  return errorNotice("Could not connect.", e);
}

/** Why requestPort() failed, and whether to open the "Can't find your robot?" help. */
export function chooserProblem(e: unknown): { notice: Notice; showHelp: boolean } {
  const name = domErrorName(e);
  if (name === "NotFoundError") {
    return {
      notice: {
        tone: "warning",
        text: "No port was chosen. If your robot's port was not in the list, the checks below usually find why.",
        detail: technicalDetail(e),
      },
      showHelp: true,
    };
  }
  if (name === "SecurityError") {
    return {
      notice: {
        tone: "danger",
        text: "The browser did not allow this page to use serial ports. Check the site's permissions (the icon left of the address) or your organisation's browser policy, then try again.",
        detail: technicalDetail(e),
      },
      showHelp: false,
    };
  }
  return { notice: errorNotice("The port chooser failed.", e), showHelp: true };
}
