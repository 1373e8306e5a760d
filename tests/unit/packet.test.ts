import { describe, expect, it } from "vitest";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import {
  COMMANDS,
  commandName,
  encodeDownloadStart,
  encodePacket,
  fromHex,
  toHex,
} from "../../src/protocol/index.ts";
import { EX } from "../fixtures/protocol-examples.ts";

describe("encodePacket (docs/protocol.md §8 requests)", () => {
  it("builds example 1, read firmware version", () => {
    expect(toHex(encodePacket(0x12, COMMANDS.readFirmwareVersion.request()))).toBe(EX.readVersion);
  });
  it("builds example 4, direct mode on", () => {
    expect(toHex(encodePacket(0x10, COMMANDS.enterDirectMode.request()))).toBe(EX.directOn);
  });
  it("builds example 6, run motion 7", () => {
    expect(toHex(encodePacket(0x14, COMMANDS.runMotion.request(7)))).toBe(EX.runMotion7);
  });
  it("builds example 7, sound 3", () => {
    expect(toHex(encodePacket(0x15, COMMANDS.runSound.request(3)))).toBe(EX.sound3);
  });
  it("builds example 9, sound threshold 30 in both bytes (docs/protocol.md §3.5)", () => {
    expect(toHex(encodePacket(0x17, COMMANDS.subscribeSound.request(30)))).toBe(EX.soundThreshold30);
  });
  it("builds example 13, write standard zeros", () => {
    const zeros = [125, 202, 162, 66, 108, 124, 48, 88, 184, 142, 90, 40, 125, 161, 210, 127];
    expect(toHex(encodePacket(0x0e, COMMANDS.writeZeros.request(zeros)))).toBe(EX.writeStandardZeros);
  });
  it("builds example 15, reset motion pointer", () => {
    expect(toHex(encodePacket(0x1f, COMMANDS.resetMemoryPointer.request("motion")))).toBe(
      EX.resetMotionPointer,
    );
  });
  it("builds replies with the robot's platform byte (example 2, 16)", () => {
    expect(toHex(encodePacket(0x12, Uint8Array.of(2, 0x17), 1))).toBe(EX.version223);
    expect(toHex(encodePacket(0x11, Uint8Array.of(0xff, 1), 1))).toBe(EX.errorNone);
  });
  it("builds the Hi.rbm download first part (docs/protocol.md §6.3)", () => {
    expect(toHex(encodeDownloadStart(0x01, 538))).toBe("FF FF AA 55 AA 55 37 BA 01 00 00 00 02 1A");
  });
  it("refuses out-of-range types, platforms and oversize contents", () => {
    expect(() => encodePacket(256, Uint8Array.of(1))).toThrow(/type/);
    expect(() => encodePacket(1, Uint8Array.of(1), -1)).toThrow(
      expect.objectContaining({
        code: "bad-platform",
        facts: { field: "platform", value: -1, min: 0, max: 255 },
      }),
    );
    expect(() => encodePacket(1, new Uint8Array(4097))).toThrow(/4096/);
  });
});

describe("command table request builders", () => {
  it("refuses motion numbers outside 0-63 and sounds outside 1-25", () => {
    expect(() => COMMANDS.runMotion.request(64)).toThrow(/0-63/);
    expect(() => COMMANDS.runMotion.request(-1)).toThrow();
    expect(() => COMMANDS.runMotion.request(1.5)).toThrow();
    expect(() => COMMANDS.runSound.request(0)).toThrow(/1-25/);
    expect(() => COMMANDS.runSound.request(26)).toThrow(/1-25/);
  });
  it("asks the action area with 02", () => {
    expect(Array.from(COMMANDS.readAvailableMemory.request("action"))).toEqual([2]);
    expect(Array.from(COMMANDS.resetMemoryPointer.request("action"))).toEqual([2]);
  });
  it("names packet types for the log", () => {
    expect(commandName(0x12)).toBe("Read firmware version");
    expect(commandName(0x01)).toBe("Write motion");
    expect(commandName(0x07)).toBe("Unknown 0x07");
  });
});

describe("reply decoders (docs/protocol.md §8 replies)", () => {
  const contents = (hex: string) => {
    const b = fromHex(hex);
    return b.subarray(14, b.length - 1);
  };
  it("decodes version 2.23", () => {
    expect(COMMANDS.readFirmwareVersion.decode(contents(EX.version223))).toEqual({ major: 2, minor: 0x17 });
  });
  it("decodes the serial number", () => {
    expect(COMMANDS.readSerialNumber.decode(contents(EX.serial))).toBe("8958899989309");
  });
  it("decodes distance 10 cm", () => {
    expect(COMMANDS.readDistance.decode(contents(EX.distance10))).toBe(10);
  });
  it("decodes button PF2", () => {
    expect(COMMANDS.subscribeButtons.decode(contents(EX.buttonPf2))).toBe(2);
  });
  it("decodes the accelerometer as signed little-endian", () => {
    expect(COMMANDS.readAccelerometer.decode(contents(EX.accel))).toEqual({ x: 4, y: 3, z: -6 });
  });
  it("decodes factory zeros", () => {
    expect(COMMANDS.readZeros.decode(contents(EX.factoryZeros))).toEqual([
      124, 202, 162, 65, 108, 125, 46, 88, 184, 142, 90, 40, 125, 161, 210, 126,
    ]);
  });
  it("decodes free memory 24,576 (big-endian)", () => {
    expect(COMMANDS.readAvailableMemory.decode(contents(EX.freeMotion))).toBe(24576);
    expect(COMMANDS.readAvailableMemory.decode(Uint8Array.of(0, 0, 0x5d, 0xc0))).toBe(24000);
  });
  it("decodes error code none with platform", () => {
    expect(COMMANDS.readErrorCode.decode(contents(EX.errorNone))).toEqual({ code: 0xff, platform: 1 });
  });
  it("rejects replies of the wrong length with a bad-reply error", () => {
    expect(() => COMMANDS.readFirmwareVersion.decode(Uint8Array.of(2))).toThrow(
      expect.objectContaining({ code: "bad-reply" }),
    );
    const caught = (f: () => unknown) => {
      try {
        f();
      } catch (e) {
        return e;
      }
      throw new Error("no error");
    };
    const short = caught(() => COMMANDS.readZeros.decode(new Uint8Array(15)));
    expect(short).toMatchObject({
      code: "bad-reply",
      facts: { command: "Read zero positions", expected: 16, got: 15 },
    });
    expect(errorText(short, "en")).toBe(
      'The robot\'s reply to "Read zero positions" was not understood: expected 16 bytes, got 15.',
    );
    const garbled = caught(() => COMMANDS.readSerialNumber.decode(new Uint8Array(13)));
    expect(garbled).toMatchObject({ facts: { problem: "not-printable" } });
    expect(errorText(garbled, "en")).toBe(
      'The robot\'s reply to "Read serial number" was not understood: the serial number is not printable text.',
    );
    expect(errorText(garbled, "ko")).toBe(
      '로봇이 "Read serial number" 요청에 보낸 응답을 이해하지 못했어요. 시리얼 번호가 읽을 수 있는 문자가 아니에요.',
    );
  });
});
