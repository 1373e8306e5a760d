import { describe, expect, it } from "vitest";
import {
  COMMAND_BY_TYPE,
  commandName,
  WRITE_ACTION_TYPE,
  WRITE_MOTION_TYPE,
} from "../../src/protocol/commands.ts";
import { packetName, packetNameMessages } from "../../src/ui/features/log/packet-names.ts";

describe("the Log view's packet names (issue 33)", () => {
  const types = [WRITE_MOTION_TYPE, WRITE_ACTION_TYPE, ...COMMAND_BY_TYPE.keys()];
  it("name every packet the protocol names: in English its own name, in Korean a translation", () => {
    for (const type of types) {
      expect(packetName(type, "en"), `type 0x${type.toString(16)}`).toBe(commandName(type));
      const ko = packetName(type, "ko") ?? "";
      expect(ko).not.toBe(commandName(type));
      expect(ko).toMatch(/[가-힣]/);
    }
    expect(Object.keys(packetNameMessages)).toHaveLength(types.length);
    expect(packetName(0x7e, "ko")).toBeUndefined();
  });
});
