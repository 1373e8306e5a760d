/**
 * Why the 3D view cannot draw. The view shows the message in place of the picture; the `code` is stable for
 * programs and tests.
 */
export class Robot3dError extends Error {
  override name = "Robot3dError";
  constructor(
    readonly code: Robot3dErrorCode,
    message: string,
  ) {
    super(message);
  }
}

export type Robot3dErrorCode =
  /** The browser offers no WebGL 2 here (switched off, blocked, or no graphics driver). */
  | "robot3d-no-webgl"
  /** The 3D module could not be loaded (offline before it was first fetched). */
  | "robot3d-load-failed";

export const NO_WEBGL_TEXT =
  "The 3D view needs WebGL 2, which this browser does not offer here (it may be switched off, or the graphics driver blocked). The scene table describes the motion in text.";

export const LOAD_FAILED_TEXT =
  "The 3D view could not be loaded (offline since the panel was opened?). The scene table describes the motion in text.";
