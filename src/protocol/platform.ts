/** The robot's platform byte and its name (docs/protocol.md §2.2). */

export type Platform = "HUNO" | "DINO" | "DOGY" | "PF2";

/** Platform byte of a reply → the robot's mode (docs/protocol.md §2.2). */
export function platformName(platform: number): Platform | `unknown (${number})` {
  switch (platform) {
    case 1:
      return "HUNO";
    case 2:
      return "DINO";
    case 3:
      return "DOGY";
    case 4:
      return "PF2";
    default:
      return `unknown (${platform})`;
  }
}
