/**
 * The outcome catalogue (src/i18n/outcomes, issue #19 item 1): every device outcome is worded once, in English
 * and Korean, from its code and facts. The device's errors carry those (their `message` is a technical line),
 * and `errorText`, the CLI and the panel show the catalogue's words. Literal sentences, so a change to a word shows here.
 */
import { describe, expect, it } from "vitest";
import { RbcInBootloaderError } from "../../src/device/bootloader-prompt.ts";
import {
  RbcDisconnectedError,
  RbcNotConnectedError,
  RbcPortError,
  RbcTimeoutError,
  RbcVerifyError,
  ZeroBackupError,
  ZeroWriteFailedError,
} from "../../src/device/errors.ts";
import { FirmwareUpdateError } from "../../src/device/firmware-update.ts";
import {
  inBootloaderRecoverText,
  inBootloaderText,
  UPLOAD_NOTICES,
  uploadNoticeText,
} from "../../src/i18n/outcomes/device.ts";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import {
  FIRMWARE_NOTICES,
  firmwareFailureText,
  firmwareFileSummary,
  firmwareNoticeText,
  firmwareResultSentence,
  firmwareResultText,
  firmwareSummaryText,
} from "../../src/i18n/outcomes/firmware/firmware-words.ts";
import { LinkError } from "../../src/link/transport.ts";
import { bootloaderError } from "../../src/protocol/bootloader.ts";

describe("a failed firmware update", () => {
  it("says what went wrong with its facts, what the robot holds and what to do, in both languages", () => {
    const e = new FirmwareUpdateError({
      failure: "no-bootloader",
      holds: "previous-firmware",
      waitedMs: 60_000,
    });
    expect(e.code).toBe("timeout");
    expect(e.waitedMs).toBe(60_000);
    expect(errorText(e, "en")).toBe(
      "The robot's bootloader did not announce itself within 60 s after the robot was to be switched off and on. " +
        "Nothing was written: the robot still holds its previous firmware. " +
        "Switch the robot off, then on again while the update waits for it, and run the update again; keep the cable plugged in.",
    );
    expect(firmwareFailureText(e, "ko")).toBe(
      "로봇을 껐다가 다시 켜 달라고 한 뒤 60초 안에 로봇의 부트로더가 신호를 보내지 않았어요. " +
        "아무것도 쓰지 않았어요. 로봇에는 이전 펌웨어가 그대로 있어요. " +
        "업데이트가 기다리는 동안 로봇을 껐다가 다시 켜고, 업데이트를 다시 해 주세요. 케이블은 꽂아 두세요.",
    );
    expect(errorText(e, "ko")).toBe(firmwareFailureText(e, "ko"));
  });

  it("names the file's line and the time waited, and a half-written flash", () => {
    const facts = { failure: "no-status", holds: "incomplete-firmware", line: 1025, waitedMs: 1500 } as const;
    expect(firmwareFailureText(facts, "en")).toBe(
      "The bootloader did not answer a line (line 1025 of the file) within 1.5 s. " +
        "The robot's firmware may now be incomplete, and the robot may not work until an update succeeds. " +
        "The bootloader is never overwritten: switch the robot off and on and run the update again.",
    );
    expect(firmwareFailureText(facts, "ko")).toBe(
      "부트로더가 파일의 1025번째 줄에 1.5초 안에 응답하지 않았어요. " +
        "로봇의 펌웨어가 불완전할 수 있고, 업데이트가 성공할 때까지 로봇이 작동하지 않을 수 있어요. " +
        "부트로더는 절대 덮어쓰지 않아요. 로봇을 껐다가 다시 켜고 업데이트를 다시 해 주세요.",
    );
  });

  it("is the same sentence whether the protocol's dialogue or the device says it", () => {
    const fromDialogue = bootloaderError("checksum", "incomplete-firmware", { line: 3 });
    expect(fromDialogue.tries).toBe(4);
    expect(errorText(fromDialogue, "en")).toBe(
      "The bootloader reported a checksum error on a line (line 3 of the file) 4 times in a row; the link is garbling data. " +
        "The robot's firmware may now be incomplete, and the robot may not work until an update succeeds. " +
        "The bootloader is never overwritten: switch the robot off and on and run the update again.",
    );
    const device = new FirmwareUpdateError({
      failure: "checksum",
      holds: "incomplete-firmware",
      line: 3,
      tries: 4,
    });
    expect(errorText(device, "en")).toBe(errorText(fromDialogue, "en"));
    expect(device.code).toBe("upload-failed");
  });

  it("after @ with a silent robot: the new firmware is written, the advice is a trusted file", () => {
    const e = new FirmwareUpdateError({ failure: "no-answer", holds: "new-firmware", waitedMs: 900 });
    expect(e).toMatchObject({ failure: "no-answer", holds: "new-firmware", waitedMs: 900 });
    expect(errorText(e, "en")).toBe(
      "The robot does not answer after the update within 900 ms. " +
        "The bootloader reported the new firmware written without errors. " +
        "Switch the robot off and on; if it still does not answer, run the update again with a firmware file you trust (the bootloader is never overwritten).",
    );
  });
});

describe("the firmware update's holes (issue 20 item 8)", () => {
  it("a status sooner than its line's wire time, one with no line waiting, a line past its deadline", () => {
    const early = bootloaderError("early-status", "incomplete-firmware", { line: 7 });
    expect(errorText(early, "en")).toBe(
      "A status character arrived for a line (line 7 of the file) sooner than the line could have reached the robot at 115200 baud, so it cannot be that line's answer; the update stopped rather than run ahead of the bootloader. " +
        "The robot's firmware may now be incomplete, and the robot may not work until an update succeeds. " +
        "The bootloader is never overwritten: switch the robot off and on and run the update again.",
    );
    expect(
      firmwareFailureText({ failure: "early-status", holds: "incomplete-firmware", line: 7 }, "ko"),
    ).toBe(
      "파일의 7번째 줄이 115200 baud로 로봇에 닿기도 전에 상태 문자가 왔어요. 그 줄의 응답일 수 없어서, 부트로더보다 앞서 나가지 않도록 업데이트를 멈췄어요. " +
        "로봇의 펌웨어가 불완전할 수 있고, 업데이트가 성공할 때까지 로봇이 작동하지 않을 수 있어요. " +
        "부트로더는 절대 덮어쓰지 않아요. 로봇을 껐다가 다시 켜고 업데이트를 다시 해 주세요.",
    );
    const extra = { failure: "extra-status", holds: "incomplete-firmware", line: 3 } as const;
    expect(firmwareFailureText(extra, "en")).toMatch(
      /^The bootloader sent a status character \(line 3 of the file\) when no line was waiting for one; /,
    );
    expect(firmwareFailureText(extra, "ko")).toMatch(
      /^기다리는 줄이 없는데 부트로더가 상태 문자를 보냈어요 \(파일의 3번째 줄\)\./,
    );
    const deadline = new FirmwareUpdateError({
      failure: "line-deadline",
      holds: "incomplete-firmware",
      line: 12,
      waitedMs: 10_000,
    });
    expect(deadline.code).toBe("timeout");
    expect(errorText(deadline, "en")).toMatch(
      /^The bootloader did not finish a line \(line 12 of the file\) within 10 s after its last byte; it only paused and resumed the sending\. /,
    );
    expect(firmwareFailureText(deadline, "ko")).toMatch(
      /^부트로더가 파일의 12번째 줄을 마지막 바이트 뒤 10초 안에 끝내지 않았어요\. 보내기를 멈췄다가 다시 하라고만 했어요\. /,
    );
  });
});

describe("a robot waiting in its bootloader (issue 20 item 11)", () => {
  it("is said from its facts in both languages, with the recovery to run", () => {
    const e = new RbcInBootloaderError({ prompts: 3, overMs: 600 });
    expect(e.code).toBe("in-bootloader");
    expect(e.facts).toEqual({ prompts: 3, overMs: 600 });
    expect(errorText(e, "en")).toBe(
      "The robot is waiting in its bootloader: it sent the bootloader's prompt (^) 3 times and answered no request. " +
        "Its firmware is probably missing or incomplete (an interrupted firmware update, say). " +
        "Run the firmware update again, in recovery mode, to give it a firmware; the bootloader is never overwritten.",
    );
    expect(errorText(e, "ko")).toBe(
      "로봇이 부트로더에서 기다리고 있어요. 부트로더 신호(^)를 3번 보냈고 어떤 요청에도 응답하지 않았어요. " +
        "펌웨어가 없거나 불완전할 수 있어요(예: 펌웨어 업데이트가 중간에 끊긴 경우). " +
        "복구 모드로 펌웨어 업데이트를 다시 해서 펌웨어를 넣어 주세요. 부트로더는 덮어쓰지 않아요.",
    );
    expect(inBootloaderText(3, "en")).not.toContain("recovery mode");
    expect(inBootloaderRecoverText("ko")).toBe(
      "복구 모드로 펌웨어 업데이트를 다시 해서 펌웨어를 넣어 주세요. 부트로더는 덮어쓰지 않아요.",
    );
  });
});

describe("a firmware update's other words", () => {
  const result = (sendingMs: number, resends: number) => ({
    firmware: { major: 2, minor: 50 },
    lines: 4097,
    bytes: 184_333,
    resends,
    sendingMs,
    bytesPerSecond: 0,
    linesPerSecond: 0,
  });

  it("say the result with the version the robot reports, in both languages", () => {
    expect(firmwareResultSentence(result(83_400, 0), { major: 2, minor: 23 })).toBe(
      "Firmware updated: the robot now reports 2.50 (was 2.23). 4,097 lines in 83 s.",
    );
    expect(firmwareResultSentence(result(9_960, 2), undefined)).toBe(
      "Firmware updated: the robot now reports 2.50. 4,097 lines in 10.0 s. 2 resent after a checksum error.",
    );
    expect(firmwareResultText(result(4_060, 2), { major: 2, minor: 23 }, "ko")).toBe(
      "펌웨어를 업데이트했어요. 로봇이 알려 준 버전: 2.50 (이전: 2.23). 4.1초 동안 4,097줄을 썼어요. 체크섬 오류로 2줄을 다시 보냈어요.",
    );
    expect(firmwareResultText(result(12_500, 0), undefined, "ko")).toBe(
      "펌웨어를 업데이트했어요. 로봇이 알려 준 버전: 2.50. 13초 동안 4,097줄을 썼어요.",
    );
  });

  it("say the file's summary, one page or many", () => {
    const summary = {
      bytes: 16_384,
      firstAddress: 0,
      lastAddress: 0x3fff,
      pages: 64,
      lines: 1025,
      wireBytes: 46_137,
      reordered: false,
    };
    expect(firmwareFileSummary(summary)).toBe(
      "16,384 bytes at 0x00000-0x03FFF: 64 flash pages, 1,025 lines (46,137 bytes to send)",
    );
    expect(firmwareSummaryText({ ...summary, pages: 1 }, "en")).toContain(": 1 flash page, ");
    expect(firmwareSummaryText(summary, "ko")).toBe(
      "16,384바이트, 주소 0x00000-0x03FFF: 플래시 페이지 64개, 1,025줄 (보낼 데이터 46,137바이트)",
    );
  });

  it("keep the device's notices as the catalogue's English", () => {
    expect(FIRMWARE_NOTICES.askPowerCycle).toBe(
      "Switch the robot off and on now; the update waits for its bootloader.",
    );
    expect(firmwareNoticeText("askPowerCycle", "ko")).toBe(
      "지금 로봇을 껐다가 다시 켜 주세요. 업데이트는 부트로더를 기다려요.",
    );
    expect(UPLOAD_NOTICES.holdAdvice).toBe(
      "Run the uploaded motion first with the robot held or lying down, so that a wrong movement cannot make it fall.",
    );
    expect(uploadNoticeText("action", "ko")).toBe(
      "액션 파일의 형식은 알려져 있지 않아요. 파일의 바이트를 확인 없이 그대로 보내고, 로봇에서의 결과도 확인하지 않아요.",
    );
  });
});

describe("the device's errors", () => {
  it("are said from their code and facts by the catalogue, in English and in Korean", () => {
    expect(new RbcNotConnectedError().code).toBe("not-connected");
    expect(errorText(new RbcNotConnectedError(), "en")).toBe(
      "No robot is connected. Connect the robot (or the demo robot) first.",
    );
    const timeout = new RbcTimeoutError("Read zeros", 1000);
    expect([timeout.command, timeout.waitedMs]).toEqual(["Read zeros", 1000]);
    expect(timeout.message).toBe("no reply to Read zeros within 1000 ms");
    expect(errorText(timeout, "en")).toBe(
      'The robot did not answer "Read zeros" within 1,000 ms. Check that it is switched on and the cable is plugged in; the RBC also stays silent when it refuses a request.',
    );
    const failed = new ZeroWriteFailedError(timeout, "zeros-backup-A1.json");
    expect(failed.code).toBe("timeout");
    expect(failed.backupName).toBe("zeros-backup-A1.json");
    expect(errorText(failed, "en")).toBe(
      `${errorText(timeout, "en")} The zeros the robot held before are saved in zeros-backup-A1.json.`,
    );
    expect(errorText(failed, "ko")).toBe(
      '로봇이 1,000ms 안에 "Read zeros"에 응답하지 않았어요. 로봇이 켜져 있는지, 케이블이 꽂혀 있는지 확인해 주세요. RBC는 요청을 거부할 때도 응답하지 않아요. ' +
        "로봇에 있던 이전 영점은 zeros-backup-A1.json에 저장해 두었어요.",
    );
    const backup = new ZeroBackupError(new Error("disk full"));
    expect(backup.code).toBe("backup-failed");
    expect(errorText(backup, "en")).toBe(
      "Nothing was written: the backup of the current zeros could not be saved (disk full).",
    );
    expect(errorText(backup, "ko")).toBe("현재 영점의 백업을 저장하지 못해서 아무것도 쓰지 않았어요.");
  });

  it("word a situation from its facts: a lost link's own report stays English, and in the technical detail", () => {
    const lost = new RbcDisconnectedError(undefined, undefined, {
      kind: "link-lost",
      reported: "The serial device was unplugged.",
      advice: "check-cable",
    });
    expect(lost.message).toBe(
      "disconnected: link-lost reported=The serial device was unplugged. advice=check-cable",
    );
    expect(errorText(lost, "en")).toBe(
      "The serial device was unplugged. Check the cable, then connect again.",
    );
    expect(errorText(lost, "ko")).toBe("로봇과의 연결이 끊겼어요. 케이블을 확인한 뒤 다시 연결해 주세요.");
    // With the link's facts (as the connection gives them), the catalogue words the link's reason.
    const unplugged = new RbcDisconnectedError(undefined, undefined, {
      kind: "link-lost",
      reported: "link: lost (device-unplugged, /dev/ttyUSB0)",
      cause: { reason: "device-unplugged", path: "/dev/ttyUSB0" },
      advice: "connect-again",
    });
    expect(errorText(unplugged, "en")).toBe("The serial device was unplugged. Connect again.");
    expect(errorText(unplugged, "ko")).toBe("시리얼 장치가 뽑혔어요. 다시 연결해 주세요.");
    // A port the link could not open: the device's error keeps the link's error as its cause, worded from it.
    const busy = RbcPortError.fromLink(
      new LinkError("port-busy", "link: port-busy (busy-or-denied, /dev/ttyUSB0: Resource busy)", {
        facts: { reason: "busy-or-denied", path: "/dev/ttyUSB0", detail: "Resource busy" },
      }),
    );
    expect(busy.code).toBe("port-busy");
    expect(errorText(busy, "en")).toBe(
      "/dev/ttyUSB0 is busy or not permitted (Resource busy). Close other programs using it; on Linux add yourself to the dialout group.",
    );
    expect(errorText(busy, "ko")).toMatch(/^\/dev\/ttyUSB0을\(를\) 다른 프로그램이 쓰고 있거나/);
    const verify = new RbcVerifyError("zeros read back 1,2 instead of 1,3", [1, 3], [1, 2]);
    expect(errorText(verify, "en")).toBe("Zeros were sent, but the robot reads back 1,2 instead of 1,3.");
    expect(errorText(verify, "ko")).toBe("영점을 보냈지만, 로봇에서 다시 읽으니 1,3 대신 1,2 값이 나와요.");
  });

  it("are recognised by their class, not by their name", () => {
    const reason = new RbcTimeoutError("Write zeros", 400);
    const impostor = Object.assign(new RbcTimeoutError("Write zeros", 400), {
      name: "ZeroWriteFailedError",
      reason,
      backupName: "x.json",
    });
    expect(errorText(impostor, "ko")).not.toContain("x.json");
  });
});
