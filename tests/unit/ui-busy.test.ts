import { describe, expect, it } from "vitest";
import { answerBusyQueries, busySentence, whatIsBusy } from "../../src/ui/busy.ts";

/** What a reload would interrupt: asked by the update prompt, answered by the app (src/ui/busy.ts). */
describe("busy queries", () => {
  it("says nothing runs until the app answers, then what it answers, until it stops answering", () => {
    const page = new EventTarget();
    expect(whatIsBusy(page)).toBe(undefined);
    let running: string[] = ["Uploading wave.rbm"];
    const stop = answerBusyQueries(() => busySentence(running), page);
    expect(whatIsBusy(page)).toBe("Still running: Uploading wave.rbm.");
    running = [];
    expect(whatIsBusy(page)).toBe(undefined);
    running = ["Writing zeros", "Playing sound 7"];
    expect(whatIsBusy(page)).toBe("Still running: Writing zeros, Playing sound 7.");
    stop();
    expect(whatIsBusy(page)).toBe(undefined);
  });
});
