/**
 * Where the CLI writes. stdout carries the command's result: text for people, or exactly one JSON document
 * (or JSON lines for streams) with `--json`. stderr carries everything else: notices, warnings, progress, the
 * packet trace and the one-line reason of a failure.
 */
export interface OutputStreams {
  stdout: NodeJS.WritableStream & { isTTY?: boolean };
  stderr: NodeJS.WritableStream & { isTTY?: boolean; columns?: number };
}

export type StreamName = "stdout" | "stderr";

export class Output {
  /**
   * Set for streaming commands (`sensors`, `sim`): with `--json` their stdout is JSON lines, so their final
   * document (a failure) is one compact line too, not a pretty-printed document.
   */
  private jsonLines = false;
  /** A stream whose reader went away (EPIPE): nothing more is written to it. */
  private readonly broken = new Set<StreamName>();
  private readonly brokenListeners: Array<(which: StreamName) => void> = [];

  constructor(
    readonly json: boolean,
    readonly streams: OutputStreams = { stdout: process.stdout, stderr: process.stderr },
  ) {}

  /** Switches `result` to one compact line (see `jsonLines`). */
  streaming(): void {
    this.jsonLines = true;
  }

  get isStreaming(): boolean {
    return this.jsonLines;
  }

  /**
   * Stops all writing to `which` (its reader went away) and tells the `onBroken` listeners, once. Called by
   * main on the stream's 'error' event.
   */
  markBroken(which: StreamName): void {
    if (this.broken.has(which)) return;
    this.broken.add(which);
    for (const fn of this.brokenListeners) fn(which);
  }

  onBroken(fn: (which: StreamName) => void): void {
    this.brokenListeners.push(fn);
  }

  isBroken(which: StreamName): boolean {
    return this.broken.has(which);
  }

  private write(which: StreamName, text: string): void {
    if (this.broken.has(which)) return;
    this.streams[which].write(text);
  }

  /**
   * Lets a failed write surface before the command's next step: Node reports EPIPE (`rbc run 7 4 | head -1`)
   * on the next ticks, not when `write` returns, and e.g. the next motion must not start after the reader left.
   */
  settle(): Promise<void> {
    return new Promise((resolve) => setImmediate(resolve));
  }

  /** Result text for people (nothing in `--json` mode, where `result` carries the data). */
  line(text = ""): void {
    if (!this.json) this.write("stdout", `${text}\n`);
  }

  /**
   * The machine-readable result (only in `--json` mode): one pretty-printed document, or one compact line for
   * a streaming command.
   */
  result(data: unknown): void {
    if (this.json) this.write("stdout", `${JSON.stringify(data, null, this.jsonLines ? 0 : 2)}\n`);
  }

  /** One JSON document per line, for streams such as `sensors` (only in `--json` mode). */
  jsonLine(data: unknown): void {
    this.jsonLines = true;
    if (this.json) this.write("stdout", `${JSON.stringify(data)}\n`);
  }

  /** Help text (written in both modes). */
  text(text: string): void {
    this.write("stdout", text);
  }

  /** A notice or warning for people, on stderr in both modes. */
  note(text: string): void {
    this.write("stderr", `${text}\n`);
  }

  /** Raw stderr text (progress bar, packet trace). */
  err(text: string): void {
    this.write("stderr", text);
  }

  get stderrIsTty(): boolean {
    return this.streams.stderr.isTTY === true;
  }

  get stderrColumns(): number {
    return this.streams.stderr.columns ?? 80;
  }
}
