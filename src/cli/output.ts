/**
 * Where the CLI writes. stdout carries the command's result: text for people, or exactly one JSON document
 * (or JSON lines for streams) with `--json`. stderr carries everything else: notices, warnings, progress, the
 * packet trace and the one-line reason of a failure.
 */
export interface OutputStreams {
  stdout: NodeJS.WritableStream & { isTTY?: boolean };
  stderr: NodeJS.WritableStream & { isTTY?: boolean; columns?: number };
}

export class Output {
  constructor(
    readonly json: boolean,
    readonly streams: OutputStreams = { stdout: process.stdout, stderr: process.stderr },
  ) {}

  /** Result text for people (nothing in `--json` mode, where `result` carries the data). */
  line(text = ""): void {
    if (!this.json) this.streams.stdout.write(`${text}\n`);
  }

  /** The machine-readable result (only in `--json` mode). */
  result(data: unknown): void {
    if (this.json) this.streams.stdout.write(`${JSON.stringify(data, null, 2)}\n`);
  }

  /** One JSON document per line, for streams such as `sensors` (only in `--json` mode). */
  jsonLine(data: unknown): void {
    if (this.json) this.streams.stdout.write(`${JSON.stringify(data)}\n`);
  }

  /** A notice or warning for people, on stderr in both modes. */
  note(text: string): void {
    this.streams.stderr.write(`${text}\n`);
  }

  /** Raw stderr text (progress bar, packet trace). */
  err(text: string): void {
    this.streams.stderr.write(text);
  }

  get stderrIsTty(): boolean {
    return this.streams.stderr.isTTY === true;
  }

  get stderrColumns(): number {
    return this.streams.stderr.columns ?? 80;
  }
}
