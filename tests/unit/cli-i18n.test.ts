import { mkdtemp, readFile, rm, writeFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { PassThrough } from "node:stream";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { Cleanups } from "../../src/cli/cleanups.ts";
import type { RunEnv } from "../../src/cli/command.ts";
import { limpCommand } from "../../src/cli/commands/limp.ts";
import { confirm } from "../../src/cli/confirm.ts";
import { errorLine } from "../../src/cli/errors.ts";
import { cliLocale, langArgument, localeFromEnv } from "../../src/cli/locale.ts";
import { Output } from "../../src/cli/output.ts";
import { RbcError, RbcTimeoutError } from "../../src/device/errors.ts";
import type { Locale } from "../../src/i18n/locale.ts";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { type InProcessOptions, runInProcess } from "../cli/in-process.ts";
import { CliScope, EXAMPLES, REPO } from "../cli/spawn-cli.ts";
import { driveClock } from "../support/drive-clock.ts";

/**
 * `rbc` in Korean (issue #14 item 1): `--lang en|ko`, else LC_ALL / LC_MESSAGES / LANG, else English. What rbc
 * prints for people is Korean; `--json` stays the same, the device's English sentence comes with `--log`, and
 * without the switch (or with an English locale) every line is the English it was. The commands run in this
 * process with the demo robot on a virtual clock (tests/cli/in-process.ts); the one test of main's own
 * refusal of a wrong --lang spawns the built CLI (dist-cli/). The question answered 예 runs the command on a
 * fake terminal.
 */

/** For rbc in this process: robot time is virtual, only the CPU work takes real time. */
const T = 30_000;
/** For a spawned rbc: process start-up on a loaded 2-core machine takes seconds. */
const SPAWNED = 60_000;
/** An environment without a Korean locale, whatever the machine running the tests has. */
const ENGLISH_ENV = { LANG: "C.UTF-8", LC_ALL: "", LC_MESSAGES: "" } as const;
const KOREAN_ENV = { LANG: "ko_KR.UTF-8", LC_ALL: "", LC_MESSAGES: "" } as const;
/** A catalogue key printed in place of its text (cli.*, cmd.*, cliHelp.*, error.*). */
const RAW_KEY = /\b(cli|cmd|cliHelp|error)\.[a-z][A-Za-z0-9]*(\.[a-zA-Z0-9]+)*\b/;

let dir: string;
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), "rbc-cli-i18n-"));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

/** `rbc ARGS` in this process, the demo robot on a virtual clock, in an English environment unless told. */
const runCli = (args: readonly string[], options: InProcessOptions = {}) =>
  runInProcess([...args], { ...options, env: { ...ENGLISH_ENV, ...options.env } });

describe("the language rbc speaks", () => {
  it("is --lang when given (last one wins, before any --), else LC_ALL, LC_MESSAGES, LANG in that order", () => {
    expect(langArgument(["info", "--lang", "ko"])).toBe("ko");
    expect(langArgument(["--lang=en", "info", "--lang", "ko"])).toBe("ko");
    expect(langArgument(["info", "--", "--lang", "ko"])).toBeUndefined();
    expect(localeFromEnv({ LANG: "ko_KR.UTF-8" })).toBe("ko");
    expect(localeFromEnv({ LANG: "ko" })).toBe("ko");
    expect(localeFromEnv({ LC_MESSAGES: "ko_KR", LANG: "en_US.UTF-8" })).toBe("ko");
    expect(localeFromEnv({ LC_ALL: "C", LANG: "ko_KR.UTF-8" })).toBe("en"); // LC_ALL wins, as in POSIX
    expect(localeFromEnv({ LC_ALL: "", LANG: "ko_KR.UTF-8" })).toBe("ko"); // empty is unset
    expect(localeFromEnv({ LANG: "kok_IN" })).toBe("en");
    expect(localeFromEnv({})).toBe("en");
    expect(cliLocale(["info", "--lang", "en"], { LANG: "ko_KR.UTF-8" })).toEqual({
      locale: "en",
      invalid: undefined,
    });
    expect(cliLocale(["info", "--lang", "KO"], {})).toEqual({ locale: "ko", invalid: undefined });
    expect(cliLocale(["info", "--lang", "fr"], { LANG: "ko_KR.UTF-8" })).toEqual({
      locale: "ko",
      invalid: "fr",
    });
  });
});

describe("the device's errors on the command line", () => {
  it("keep their English sentence in English and are said from their code in Korean, pointing to --log", () => {
    const timeout = new RbcTimeoutError("Read error code", 400);
    expect(errorLine(timeout)).toBe(
      'The robot did not answer "Read error code" within 400 ms. Check that it is switched on and the cable is plugged in; the RBC also stays silent when it refuses a request.',
    );
    expect(errorLine(timeout, "ko")).toBe(
      '로봇이 400ms 안에 "Read error code"에 응답하지 않았어요. 로봇이 켜져 있는지, 케이블이 꽂혀 있는지 확인해 주세요. RBC는 요청을 거부할 때도 응답하지 않아요.',
    );
    const rejected = new RbcError("rejected", "The robot refused 0x0D.");
    expect(errorLine(rejected, "ko")).toBe(
      "로봇이 요청을 거부했어요. 자세한 내용은 --log를 붙여 다시 실행하면 기술 정보로 볼 수 있어요.",
    );
    expect(errorLine(rejected, "ko", { detailShown: true })).toBe(
      "로봇이 요청을 거부했어요. 자세한 내용은 아래 기술 정보에 있어요.",
    );
    // The panel's wording of the same code is unchanged (the catalogue moved to src/device/messages.ts).
    expect(errorText(rejected, "ko")).toBe("로봇이 요청을 거부했어요. 자세한 내용은 기술 정보에 있어요.");
    const noRobot = new RbcError("no-robot", "The port opened but no robot answered.");
    expect(errorLine(noRobot)).toBe(
      "The port opened but no robot answered; or the robot is busy playing a motion or a sound: wait until it ends and try again.",
    );
    expect(errorLine(noRobot, "ko")).toMatch(
      /^포트는 열렸지만 로봇이 응답하지 않았어요\. .* 로봇이 모션이나 소리를 재생하는 중일 수도 있어요\./,
    );
  });
});

describe.concurrent("rbc in Korean", () => {
  it("rbc info --demo --lang ko: the robot's facts in Korean; --json is the same in both languages", {
    timeout: T,
  }, async () => {
    const [ko, en, koJson, enJson] = await Promise.all([
      runCli(["info", "--demo", "--lang", "ko"]),
      runCli(["info", "--demo"]),
      runCli(["info", "--demo", "--json", "--lang", "ko"]),
      runCli(["info", "--demo", "--json"]),
    ]);
    expect(ko.code, ko.stderr).toBe(0);
    expect(ko.stdout.split("\n")).toEqual([
      "데모 로봇 (가상)",
      "  펌웨어         2.23",
      "  시리얼 번호    8958899989309",
      "  플랫폼         HUNO (1)",
      "  오류 코드      오류 없음",
      "  남은 메모리    모션 24,576바이트 중 24,576바이트, 액션 8,192바이트 중 8,192바이트",
      "",
    ]);
    expect(ko.stdout).not.toMatch(RAW_KEY);
    // Without the switch, in an English environment: the English lines, as they always were.
    expect(en.stdout).toContain("The demo robot (simulated)\n  Firmware       2.23\n");
    expect(en.stdout).toContain(
      "  Free memory    motion 24,576 of 24,576 bytes, action 8,192 of 8,192 bytes\n",
    );
    expect(en.stdout).not.toMatch(/\p{Script=Hangul}/u);
    expect(JSON.parse(koJson.stdout)).toEqual(JSON.parse(enJson.stdout));
    expect(koJson.stdout).not.toMatch(/\p{Script=Hangul}/u);
  });

  it("rbc zeros read --demo with LANG=ko_KR.UTF-8: the table in Korean, its columns lined up", {
    timeout: T,
  }, async () => {
    const [ko, english] = await Promise.all([
      runCli(["zeros", "read", "--demo"], { env: KOREAN_ENV }),
      runCli(["zeros", "read", "--demo", "--lang", "en"], { env: KOREAN_ENV }),
    ]);
    expect(ko.code, ko.stderr).toBe(0);
    const lines = ko.stdout.split("\n");
    expect(lines[0]).toBe("로봇 8958899989309의 영점 위치 (데모 로봇):");
    expect(lines[1]).toBe("  서보  관절                영점  기준  차이  허용 범위  공장");
    // Servo 0 is the robot's own left hip (tests/unit/cli-zeros-table.test.ts: "Left hip roll").
    expect(lines[2]).toBe("     0  왼쪽 엉덩이 좌우     124   125    -1    110-140   124");
    expect(lines[7]).toBe("     5  오른쪽 엉덩이 좌우   125   124    +1    109-139   125");
    expect(lines[17]).toBe("    15  오른쪽 팔꿈치        126   127    -1    112-142   126");
    expect(ko.stdout).toContain("기준: RBC가 쓰기를 할 때마다 비교하는 표예요.");
    expect(ko.stdout).toContain("목록으로: 124,202,162,65,108,125,46,88,184,142,90,40,125,161,210,126");
    expect(ko.stdout).not.toMatch(RAW_KEY);
    // --lang wins over the environment.
    expect(english.stdout).toMatch(/^Zero positions of robot 8958899989309 \(the demo robot\):\n/);
    expect(english.stdout).not.toMatch(/\p{Script=Hangul}/u);
  });

  it("rbc --help --lang ko: the overview, a command's help and the language switch in Korean", {
    timeout: T,
  }, async () => {
    const [global, upload, english] = await Promise.all([
      runCli(["--help", "--lang", "ko"]),
      runCli(["upload", "--help"], { env: KOREAN_ENV }),
      runCli(["--help"]),
    ]);
    expect(global.code).toBe(0);
    expect(global.stdout).toMatch(
      /^rbc — 명령줄에서 로보빌더 RBC 로봇 컨트롤러를 다뤄요\n\n사용법: rbc COMMAND \[options\]/,
    );
    expect(global.stdout).toMatch(/\n {2}zeros {4}서보 영점 위치를 읽기, 쓰기, 백업, 복원하기\n/);
    expect(global.stdout).toMatch(/\n {2}limp {5}모든 서보의 힘 빼기/);
    expect(global.stdout).toContain("--lang en|ko  안내 문구의 언어: en(영어), ko(한국어).");
    expect(global.stdout).toContain("종료 코드: 0 완료, 1 실패");
    expect(global.stdout).toContain('{"ok":false,"error":{"code":…,"message":…}}');
    expect(global.stdout).not.toMatch(RAW_KEY);
    expect(upload.stdout).toContain(
      "사용법: rbc upload FILE.rbm [--reset] [--action] [--yes] (--port PATH | --demo)",
    );
    expect(upload.stdout).toContain("실제 로봇(--demo가 아닐 때)에 업로드하는 기능은 실험 단계예요.");
    expect(upload.stdout).toContain("  --reset          먼저 메모리 포인터를 초기화해요.");
    // The English help documents the switch, and is otherwise the help it was.
    expect(english.stdout).toContain(
      "  --lang en|ko  Messages in en (English) or ko (Korean); default from LC_ALL, LC_MESSAGES or LANG.",
    );
    expect(english.stdout).toContain("Options of every command:\n  --json        Print the result as JSON");
    expect(english.stdout).toContain("Run `rbc COMMAND --help` for details of one command.");
    expect(english.stdout).not.toMatch(/\p{Script=Hangul}/u);
  });

  it("a corrupt motion file: the refusal in Korean, the English in --json and after --log", {
    timeout: T,
  }, async () => {
    const wave = await readFile(join(REPO, EXAMPLES.wave), "utf8");
    const file = join(dir, "wave-cut.rbm");
    await writeFile(file, wave.slice(0, Math.floor(wave.length / 2)));
    const [ko, log, json, en] = await Promise.all([
      runCli(["upload", file, "--demo", "--lang", "ko"]),
      runCli(["upload", file, "--demo", "--lang", "ko", "--log"]),
      runCli(["upload", file, "--demo", "--lang", "ko", "--json"]),
      runCli(["upload", file, "--demo"]),
    ]);
    expect(ko.code).toBe(1);
    expect(ko.stdout).toBe("");
    // The catalogue's sentence with the file's facts (the panel's words), not a general one.
    expect(ko.stderr).toMatch(
      /^rbc: wave-cut\.rbm: 파일(의 필드가 [\d,]+개인데|은 ":" 문자로 끝나야 하는데).*(잘렸거나 손상됐어요).*아무것도 보내지 않았어요\.\n$/,
    );
    expect(ko.stderr).not.toMatch(/[A-Za-z]{4,} [a-z]{3,}/); // no English sentence in it
    // --log: the same line, then the English as the technical detail.
    const [line, detail] = log.stderr.split("\n").filter((l) => l.startsWith("rbc: "));
    expect(line).toBe(ko.stderr.trim());
    expect(detail).toMatch(/^rbc: 기술 정보: CliError: wave-cut\.rbm: .*\. Nothing was sent\.$/);
    // --json: the machine's document is the English one.
    expect(JSON.parse(json.stdout).error).toMatchObject({ code: "rbm-invalid" });
    expect(JSON.parse(json.stdout).error.message).toBe(en.stderr.replace(/^rbc: /, "").trim());
    expect(en.stderr).toMatch(/^rbc: wave-cut\.rbm: .*\. Nothing was sent\.\n$/);
  });

  it("a motion file with a problem: rbc upload in Korean says the panel's sentence with the scene and the ms", {
    timeout: T,
  }, async () => {
    // wave.rbm's scene 0 (20 frames) given 200 ms: frames 10 ms apart, the RBC needs 20 (docs/protocol.md §7);
    // then also servo 3's zero position (field 36) 300, past 254: two errors, listed one a line.
    const fields = (await readFile(join(REPO, EXAMPLES.wave), "latin1")).split(":");
    fields[13 + 6 * 16 + 4] = "200";
    const fast = join(dir, "wave-fast.rbm");
    await writeFile(fast, fields.join(":"), "latin1");
    fields[13 + 6 * 3 + 5] = "300";
    const twice = join(dir, "wave-fast-zero.rbm");
    await writeFile(twice, fields.join(":"), "latin1");
    const [ko, log, two] = await Promise.all([
      runCli(["upload", fast, "--demo", "--lang", "ko"]),
      runCli(["upload", fast, "--demo", "--lang", "ko", "--log"]),
      runCli(["upload", twice, "--demo", "--lang", "ko"]),
    ]);
    const interval =
      "장면 0의 프레임 간격이 10ms예요 (200ms / 프레임 20개). RBC에는 20ms 이상이 필요해요. 프레임 수를 줄여 주세요";
    expect(ko.code).toBe(1);
    expect(ko.stderr).toBe(`rbc: wave-fast.rbm: ${interval}. 아무것도 보내지 않았어요.\n`);
    // --log: the same line, then the protocol's English sentence as the technical detail.
    expect(log.stderr.split("\n")).toEqual([
      ko.stderr.trim(),
      "rbc: 기술 정보: CliError: wave-fast.rbm: Scene 0 has frames 10 ms apart (200 ms / 20 frames); the RBC needs at least 20 ms. Use fewer frames. Nothing was sent.",
      "",
    ]);
    expect(two.code).toBe(1);
    expect(two.stdout.split("\n")).toEqual(
      expect.arrayContaining([
        "  오류: (서보 3번) 서보 3번(왼쪽 발목 앞뒤)의 영점 위치 값이 300인데, 위치는 0부터 254까지예요.",
        `  오류: (장면 0) ${interval}.`,
      ]),
    );
    expect(two.stdout + two.stderr).not.toMatch(/[A-Za-z]{4,} [a-z]{3,}/); // no English sentence in it
  });

  it("a --lang rbc does not speak is a usage error, in the environment's language (spawned: main's own)", {
    timeout: SPAWNED,
  }, async ({ onTestFinished }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const badLang = await scope.run(["info", "--demo", "--lang", "fr"], {
      env: KOREAN_ENV,
      timeoutMs: SPAWNED,
    });
    expect(badLang.code).toBe(2);
    expect(badLang.stderr).toBe(
      'rbc: --lang에는 en(영어)이나 ko(한국어)를 써 주세요. 받은 값: "fr".\n사용법은 "rbc --help"로 볼 수 있어요.\n',
    );
  });

  it("results, progress and failures of other commands in Korean", { timeout: T }, async () => {
    const [run, ignored, upload, usage] = await Promise.all([
      runCli(["run", "7", "--demo", "--lang", "ko"]),
      runCli(["run", "4", "--demo", "--lang", "ko"]),
      runCli(["upload", EXAMPLES.wave, "--demo", "--lang", "ko"]),
      runCli(["sound", "30", "--demo", "--lang", "ko"]),
    ]);
    expect(run.code, run.stderr).toBe(0);
    expect(run.stdout).toMatch(
      /^7 \(기본 자세\) 보냄: 로봇이 재생하는지 확인하는 중…\n재생함: 7 \(기본 자세\)\. 로봇이 1\.\d초 뒤에 끝났다고 알려 줬어요\.\n$/,
    );
    expect(ignored.code).toBe(1);
    expect(ignored.stderr).toBe(
      // The facts in Korean (docs/protocol.md §3.1: no reply, the robot idle, no 7 yet), then the demo's hint.
      "rbc: 로봇이 3.6초 안에 모션 4이(가) 끝났다고 알리지 않았어요. 그래서 아마 무시했을 거예요. RBC는 켜진 뒤 기본 자세(7)를 한 번 실행하기 전까지 모든 모션을 무시해요. 먼저 모션 7을 실행해 주세요. 데모 로봇은 rbc 명령마다 새로 켜져요. 7을 먼저 넣어 주세요. 예: rbc run 7 4 --demo.\n",
    );
    expect(upload.code, upload.stderr).toBe(0);
    expect(upload.stdout).toContain("확인함: 오류 없음, 경고 없음.\n");
    expect(upload.stdout).toContain("남은 모션 메모리: 23,936바이트 (전에는 24,576바이트).\n");
    expect(upload.stdout).toContain("저장된 번호: 모션 12 (리모컨: 1번 키). 재생하려면: `rbc run 12`.\n");
    expect(upload.stderr).toMatch(/\[#{20}\] 624\/624바이트 100% +[\d,]+B\/s {2}완료\n/);
    expect(usage.code).toBe(2);
    expect(usage.stderr).toBe(
      'rbc: 소리 번호: 1부터 25까지의 정수여야 해요. 받은 값: "30".\n사용법은 "rbc sound --help"로 볼 수 있어요.\n',
    );
    for (const r of [run, ignored, upload, usage]) expect(r.stdout + r.stderr).not.toMatch(RAW_KEY);
  });
});

/** A fake terminal on stdin and an Output that collects what it writes. */
function terminal(locale: Locale | undefined, argv: string[] = []) {
  const stdin = Object.assign(new PassThrough(), { isTTY: true });
  const text = { stdout: "", stderr: "" };
  const stdout = new PassThrough();
  const stderr = new PassThrough();
  stdout.on("data", (d: Buffer) => {
    text.stdout += d.toString();
  });
  stderr.on("data", (d: Buffer) => {
    text.stderr += d.toString();
  });
  const cleanups = new Cleanups();
  /** The demo robot's clock, driven by the test (`driveClock`). */
  const clock = new VirtualClock();
  const env: RunEnv = {
    argv,
    signal: new AbortController().signal,
    onCleanup: (fn) => cleanups.add(fn),
    out: new Output(false, { stdout, stderr }),
    setExitNote: () => {},
    stdin: stdin as unknown as NodeJS.ReadStream,
    cwd: REPO,
    env: {},
    ...(locale ? { locale } : {}),
    demoClock: clock,
  };
  /** Types `keys` once the prompt has been written. */
  const answer = async (keys: string) => {
    while (!text.stderr.includes("[y/N] ")) await new Promise((r) => setTimeout(r, 5));
    stdin.write(keys);
  };
  return { env, text, answer, cleanups, clock };
}

describe("the y/N question in Korean", () => {
  it("takes 예 and 네 as yes in Korean (and y, yes), but not in English", async () => {
    const ask = async (locale: Locale | undefined, keys: string) => {
      const { env, answer } = terminal(locale);
      const [result] = await Promise.all([confirm(env, "업로드할까요?"), answer(keys)]);
      return result;
    };
    expect(await ask("ko", "예\r")).toBe("yes");
    expect(await ask("ko", "네\r")).toBe("yes");
    expect(await ask("ko", "y\r")).toBe("yes");
    expect(await ask("ko", "아니요\r")).toBe("no");
    expect(await ask("ko", "\r")).toBe("no");
    expect(await ask(undefined, "예\r")).toBe("no");
    expect(await ask("en", "yes\r")).toBe("yes");
  });

  it("rbc limp --demo --lang ko asks in Korean, takes 예, and says what the servos confirmed", async () => {
    const { env, text, answer, cleanups, clock } = terminal("ko", ["--demo", "--lang", "ko"]);
    let code: number;
    try {
      [code] = await Promise.all([driveClock(clock, limpCommand.run(env)), answer("예\r")]);
    } finally {
      await driveClock(clock, cleanups.run());
    }
    await new Promise((r) => setImmediate(r));
    expect(code).toBe(0);
    expect(text.stderr).toContain(
      "로봇을 잡아 주세요. 모든 서보의 힘이 빠져서, 아무도 잡고 있지 않으면 로봇이 넘어져요.\n",
    );
    expect(text.stderr).toContain("데모 로봇의 모든 서보의 힘을 뺄까요? [y/N] ");
    expect(text.stdout).toBe(
      "힘 빼기: 서보 16개 모두 힘이 빠졌다고 확인했어요. 로봇을 잡아 주세요. 이제 혼자 서 있을 수 없어요.\n",
    );
  });
});
