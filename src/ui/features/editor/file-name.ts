/** The file name a motion is saved under (pure). */

/** Longest file name stem the editor suggests. */
const MAX_STEM = 60;

/**
 * The file name a motion is saved under: its name with anything a file system may refuse (or a person may
 * stumble over: spaces, slashes, dots) turned into "-", and ".rbm". "Wave hello!" → "Wave-hello.rbm";
 * a name with nothing usable → "motion.rbm".
 */
export function motionFileName(name: string): string {
  const stem = name
    .replace(/[^A-Za-z0-9_-]+/g, "-")
    .replace(/-{2,}/g, "-")
    .replace(/^-+|-+$/g, "")
    .slice(0, MAX_STEM)
    .replace(/-+$/, "");
  return `${stem === "" ? "motion" : stem}.rbm`;
}
