import { describe, expect, it } from "vitest";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import { BootloaderDialogue, BootloaderError } from "../../src/protocol/bootloader.ts";
import { fromHex, toHex } from "../../src/protocol/bytes.ts";
import { parseIntelHex } from "../../src/protocol/intel-hex.ts";

/**
 * Literal-byte transcripts of the bootloader dialogue (docs/protocol.md §11). The small file is two data records
 * and the end-of-file record; the PC→RBC bytes below are those lines' ASCII with CR LF, written out by hand.
 */
const FILE = [":0400000001020304F2", ":04000400AABBCCDDEA", ":00000001FF"].join("\r\n");
const ENTRY = "40 26 24";
const L1 = "3A 30 34 30 30 30 30 30 30 30 31 30 32 30 33 30 34 46 32 0D 0A";
const L2 = "3A 30 34 30 30 30 34 30 30 41 41 42 42 43 43 44 44 45 41 0D 0A";
const L3 = "3A 30 30 30 30 30 30 30 31 46 46 0D 0A";

type Turn = ["RBC" | "PC" | "timeout", string];

function dialogue() {
  return new BootloaderDialogue(parseIntelHex(FILE).records);
}

/**
 * Plays the robot's side (`RBC` turns, each one chunk, and `timeout` turns) and records what the host writes
 * after each, as `PC` turns; returns the whole transcript for an exact comparison.
 */
function play(d: BootloaderDialogue, script: Array<string | { timeout: true }>): Turn[] {
  const turns: Turn[] = [];
  for (const step of script) {
    let out: Uint8Array[];
    if (typeof step === "string") {
      turns.push(["RBC", step]);
      out = d.receive(fromHex(step));
    } else {
      turns.push(["timeout", ""]);
      out = d.timeout(1000);
    }
    for (const bytes of out) turns.push(["PC", toHex(bytes)]);
  }
  return turns;
}

describe("bootloader dialogue transcripts", () => {
  it("enters, resends a line answered '-', pauses on XOFF, resumes on XON and completes on '@'", () => {
    const d = dialogue();
    expect(d.wait?.for).toBe("bootloader");
    const turns = play(d, ["5E", "3F", "2D", "7E 13", "11", "13", "11", "7E", "40"]);
    expect(turns).toEqual([
      ["RBC", "5E"], // ^ bootloader active
      ["PC", ENTRY],
      ["RBC", "3F"], // ? ready
      ["PC", L1],
      ["RBC", "2D"], // - checksum error: line 1 again
      ["PC", L1],
      ["RBC", "7E 13"], // ~ line done, XOFF in the same chunk: line 2 waits
      ["RBC", "11"], // XON
      ["PC", L2],
      ["RBC", "13"], // XOFF while a line is outstanding: not a status
      ["RBC", "11"], // XON: still waiting for line 2's status, nothing sent
      ["RBC", "7E"], // ~
      ["PC", L3],
      ["RBC", "40"], // @ file complete
    ]);
    expect(d.phase).toBe("complete");
    expect(d.holds).toBe("new-firmware");
    expect(d.error).toBeUndefined();
    expect(d.progress).toMatchObject({
      linesDone: 3,
      lines: 3,
      resends: 1,
      bytesDone: 21 + 21 + 13,
      bytes: 55,
    });
    expect(d.wait).toBeUndefined();
  });

  it("takes '~' for the end-of-file line and still waits for '@'", () => {
    const d = dialogue();
    const turns = play(d, ["5E", "3F", "7E", "7E", "7E"]);
    expect(turns.filter(([who]) => who === "PC").map(([, b]) => b)).toEqual([ENTRY, L1, L2, L3]);
    expect(d.phase).toBe("sending");
    expect(d.wait?.for).toBe("status");
    expect(d.progress.linesDone).toBe(3);
    play(d, ["40"]);
    expect(d.phase).toBe("complete");
    expect(d.progress.linesDone).toBe(3);
  });

  it("stops on '%' (page error) and sends nothing more", () => {
    const d = dialogue();
    expect(play(d, ["5E", "3F", "7E", "25"])).toEqual([
      ["RBC", "5E"],
      ["PC", ENTRY],
      ["RBC", "3F"],
      ["PC", L1],
      ["RBC", "7E"],
      ["PC", L2],
      ["RBC", "25"], // % page error
    ]);
    expect(d.error).toBeInstanceOf(BootloaderError);
    expect(d.error).toMatchObject({ code: "page-error", holds: "incomplete-firmware", line: 2 });
    expect(errorText(d.error, "en")).toMatch(/could not write a flash page \(line 2 of the file\)/);
    expect(errorText(d.error, "en")).toMatch(
      /bootloader is never overwritten: switch the robot off and on and run the update again/,
    );
    expect(play(d, ["7E", "11"])).toEqual([
      ["RBC", "7E"],
      ["RBC", "11"],
    ]);
  });

  it("stops on '#' (complete with errors)", () => {
    const d = dialogue();
    const turns = play(d, ["5E", "3F", "7E", "7E", "23"]);
    expect(turns.at(-1)).toEqual(["RBC", "23"]);
    expect(turns.filter(([who]) => who === "PC")).toHaveLength(4);
    expect(d.error).toMatchObject({ code: "completed-with-errors", holds: "incomplete-firmware" });
  });

  it("sends a line answered '-' again 3 times, then gives up", () => {
    const d = dialogue();
    expect(play(d, ["5E", "3F", "2D", "2D", "2D", "2D"])).toEqual([
      ["RBC", "5E"],
      ["PC", ENTRY],
      ["RBC", "3F"],
      ["PC", L1],
      ["RBC", "2D"],
      ["PC", L1],
      ["RBC", "2D"],
      ["PC", L1],
      ["RBC", "2D"],
      ["PC", L1],
      ["RBC", "2D"],
    ]);
    expect(d.error).toMatchObject({ code: "checksum", line: 1, holds: "incomplete-firmware" });
    expect(d.progress.resends).toBe(3);
  });

  it("fails on '@' before the last line", () => {
    const d = dialogue();
    play(d, ["5E", "3F", "40"]);
    expect(d.error).toMatchObject({ code: "early-complete", line: 1 });
  });

  it("fails when the robot restarts ('^') in the middle of the file", () => {
    const d = dialogue();
    const turns = play(d, ["5E", "3F", "7E", "5E"]);
    expect(turns.at(-1)).toEqual(["RBC", "5E"]);
    expect(d.error).toMatchObject({ code: "restarted", line: 2, holds: "incomplete-firmware" });
  });

  it("ignores what the running application sends before '^', and a '^' inside its packets", () => {
    const d = dialogue();
    // A sound-level event (0x5E = 94) arrives just before the robot is switched off: the host answers the
    // stray 5E, then the packet's next bytes show it was not the bootloader.
    const turns = play(d, ["FF FF AA 55 AA 55 37 BA 17 01 00 00 00 02 5E", "00 5C", "5E", "3F"]);
    expect(turns).toEqual([
      ["RBC", "FF FF AA 55 AA 55 37 BA 17 01 00 00 00 02 5E"],
      ["PC", ENTRY],
      ["RBC", "00 5C"],
      ["RBC", "5E"],
      ["PC", ENTRY],
      ["RBC", "3F"],
      ["PC", L1],
    ]);
    expect(d.strayBytes).toBe(1);
  });
});

describe("bootloader dialogue timeouts and aborts", () => {
  it("no '^': nothing was written", () => {
    const d = dialogue();
    expect(play(d, [{ timeout: true }])).toEqual([["timeout", ""]]);
    expect(d.error).toMatchObject({ code: "no-bootloader", holds: "previous-firmware" });
    expect(errorText(d.error, "en")).toMatch(
      /Nothing was written: the robot still holds its previous firmware/,
    );
    expect(errorText(d.error, "en")).toMatch(/Switch the robot off, then on again while the update waits/);
  });

  it("no '?': waits for another '^', answering at most 3, then fails with nothing written", () => {
    const d = dialogue();
    const turns = play(d, ["5E", { timeout: true }, "5E", { timeout: true }, "5E", { timeout: true }]);
    expect(turns.filter(([who]) => who === "PC").map(([, b]) => b)).toEqual([ENTRY, ENTRY, ENTRY]);
    expect(d.error).toMatchObject({ code: "not-ready", holds: "previous-firmware" });
  });

  it("no status for a line, and XOFF without XON, each fail naming the line", () => {
    const quiet = dialogue();
    play(quiet, ["5E", "3F", "7E", { timeout: true }]);
    expect(quiet.error).toMatchObject({ code: "no-status", line: 2, holds: "incomplete-firmware" });
    expect(errorText(quiet.error, "en")).toMatch(/did not answer a line \(line 2 of the file\) within 1 s/);

    const stalled = dialogue();
    const turns = play(stalled, ["5E", "3F", "7E 13", { timeout: true }]);
    expect(turns.filter(([who]) => who === "PC")).toHaveLength(2);
    expect(stalled.error).toMatchObject({ code: "stalled", line: 2 });
  });

  it("starts a new wait (new seq) for each line and each pause", () => {
    const d = dialogue();
    const seqs: Array<[string | undefined, number | undefined]> = [];
    const note = () => seqs.push([d.wait?.for, d.wait?.seq]);
    note();
    for (const step of ["5E", "3F", "7E 13", "11"]) {
      d.receive(fromHex(step));
      note();
    }
    expect(seqs.map(([kind]) => kind)).toEqual(["bootloader", "ready", "status", "xon", "status"]);
    const numbers = seqs.map(([, seq]) => seq!);
    expect(new Set(numbers).size).toBe(numbers.length);
  });

  it("Cancel says what the robot holds: before a line, nothing; after one, maybe incomplete", () => {
    const early = dialogue();
    play(early, ["5E"]);
    expect(early.abort("cancelled")).toMatchObject({ code: "cancelled", holds: "previous-firmware" });
    const late = dialogue();
    play(late, ["5E", "3F"]);
    const e = late.abort("disconnected");
    expect(e).toMatchObject({ code: "disconnected", holds: "incomplete-firmware" });
    expect(errorText(e, "en")).toMatch(
      /may now be incomplete.*never overwritten: switch the robot off and on/,
    );
    expect(late.receive(fromHex("7E"))).toEqual([]);
  });
});

describe("status characters against the wire and the line's overall deadline (§11 [decision])", () => {
  /** A dialogue on a clock the test sets: `at(ms, "RBC bytes")` receives at that time. */
  function timed(wireTimed?: boolean) {
    let time = 0;
    const d = new BootloaderDialogue(parseIntelHex(FILE).records, { now: () => time, wireTimed });
    const at = (ms: number, hex: string) => {
      time = ms;
      return d.receive(fromHex(hex)).map(toHex);
    };
    const timeoutAt = (ms: number) => {
      time = ms;
      return d.timeout(ms);
    };
    return { d, at, timeoutAt };
  }
  // Lines 1 and 2 are 21 bytes each: 21 × 86.8 µs = 1.823 ms on the wire.

  it("a '~' sooner than line 1's 21 bytes take on the wire is not its answer: the update fails", () => {
    const { d, at } = timed();
    expect(at(0, "5E")).toEqual([ENTRY]);
    expect(at(0.5, "3F")).toEqual([L1]);
    expect(at(2.32, "7E")).toEqual([]); // 1.82 ms after line 1 went out: too soon
    expect(d.error).toMatchObject({ code: "early-status", line: 1, holds: "incomplete-firmware" });
  });

  it("the same on line 2, after line 1 was answered in time", () => {
    const { d, at } = timed();
    at(0, "5E");
    at(0.5, "3F");
    expect(at(2.4, "7E")).toEqual([L2]);
    expect(at(4.22, "7E")).toEqual([]); // 1.82 ms after line 2 went out
    expect(d.error).toMatchObject({ code: "early-status", line: 2, holds: "incomplete-firmware" });
    expect(errorText(d.error, "en")).toMatch(
      /sooner than the line could have reached the robot at 115200 baud/,
    );
  });

  it("a '~' after its line's wire time is its answer", () => {
    const { d, at } = timed();
    at(0, "5E");
    at(0.5, "3F");
    expect(at(2.4, "7E")).toEqual([L2]);
    expect(at(4.23, "7E")).toEqual([L3]); // 1.83 ms after line 2: possible
    expect(d.error).toBeUndefined();
  });

  it("on a link that is not wire-timed (a simulator without baud pacing), timing is not judged", () => {
    const { d, at } = timed(false);
    at(0, "5E");
    expect(at(0.1, "3F")).toEqual([L1]);
    expect(at(0.1, "7E")).toEqual([L2]);
    expect(at(0.1, "7E")).toEqual([L3]);
    expect(d.error).toBeUndefined();
  });

  it("a status while no line waits for one (the next line held back by XOFF) ends the update", () => {
    const { d, at } = timed();
    at(0, "5E");
    at(0.5, "3F");
    expect(at(5, "7E 13")).toEqual([]); // line 1 done; line 2 waits for XON
    expect(at(6, "7E")).toEqual([]);
    expect(d.error).toMatchObject({ code: "extra-status", line: 2 });
  });

  it("XOFF/XON never extend a line's deadline: 10 s from its last byte, whatever toggles", () => {
    const { d, at, timeoutAt } = timed();
    at(0, "5E");
    at(0.5, "3F"); // line 1 out at 0.5 ms; its last byte at 2.323 ms
    const deadline = 0.5 + (21 * 10_000) / 115_200 + 10_000;
    for (let t = 100; t < 10_000; t += 100) {
      at(t, t % 200 === 0 ? "11" : "13");
      expect(d.wait?.deadline).toBeCloseTo(deadline, 6);
    }
    expect(d.done).toBe(false);
    timeoutAt(deadline);
    expect(d.error).toMatchObject({ code: "line-deadline", line: 1 });
    expect(errorText(d.error, "en")).toMatch(
      /did not finish a line \(line 1 of the file\) within 10 s after its last byte/,
    );
  });
});
