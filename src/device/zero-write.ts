import { COMMANDS } from "../protocol/commands.ts";
import { zeroProblems } from "../protocol/zeros.ts";
import {
  RbcBadReplyError,
  RbcError,
  RbcInvalidArgumentError,
  RbcRejectedError,
  RbcTimeoutError,
  RbcVerifyError,
} from "./errors.ts";
import type { RbcConnection } from "./rbc-connection.ts";
import type { ZeroWriteResult } from "./types.ts";

/**
 * A plain array of what `zeros` holds at indexes 0-15, each index read exactly once (holes read as undefined,
 * which the zero rules refuse). A table of another length keeps its length so that the rules report it.
 */
function copyZeroTable(zeros: readonly number[]): number[] {
  const length = Array.isArray(zeros) ? zeros.length : 0;
  const copy: number[] = [];
  for (let i = 0; i < length; i++) copy.push(zeros[i] as number);
  return copy;
}

/**
 * Validates the table (refusing what the RBC would silently drop), writes it, checks the echo, reads the
 * table back and verifies it.
 */
export async function writeZeros(c: RbcConnection, zeros: readonly number[]): Promise<ZeroWriteResult> {
  // Copied once into a fresh table, and only the copy is checked and sent: a sparse array, a getter or a
  // Proxy cannot change a value between the check and the write.
  const written = copyZeroTable(zeros);
  const problems = zeroProblems(written);
  if (problems.length > 0) {
    throw new RbcInvalidArgumentError(undefined, { kind: "zeros-not-written", problems });
  }
  return c.exclusive(async () => {
    let echo: number[];
    try {
      echo = await c.request(COMMANDS.writeZeros, written);
    } catch (e) {
      if (!(e instanceof RbcTimeoutError)) throw e;
      // No echo (lost, garbled or late): the table read back tells whether the write happened.
      const stored = await c.request(COMMANDS.readZeros, undefined).catch(() => undefined);
      if (stored?.every((v, i) => v === written[i])) return { written, readBack: stored };
      if (!stored) {
        throw new RbcError("timeout", undefined, { situation: { kind: "zeros-write-unknown" } });
      }
      throw new RbcRejectedError(undefined, undefined, { kind: "zeros-write-refused" });
    }
    if (echo.some((v, i) => v !== written[i])) {
      throw new RbcBadReplyError(undefined, undefined, { kind: "zeros-echo-differs", echo });
    }
    const readBack = await c.request(COMMANDS.readZeros, undefined);
    if (readBack.some((v, i) => v !== written[i])) {
      throw new RbcVerifyError(
        `zeros read back ${readBack.join(",")} instead of ${written.join(",")}`,
        written,
        readBack,
      );
    }
    return { written, readBack };
  });
}
