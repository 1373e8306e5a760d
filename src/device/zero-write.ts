import { zerosNotWrittenText } from "../i18n/outcomes/zero-words.ts";
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
    throw new RbcInvalidArgumentError(zerosNotWrittenText(problems, "en"));
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
        throw new RbcError(
          "timeout",
          "The robot did not confirm the zero write and did not answer a read either; its stored zeros are unknown. Check the connection, then read them again before anything else.",
        );
      }
      throw new RbcRejectedError(
        "The robot did not confirm the zero write, and reading them back shows the new values were not stored (the robot refuses a table it considers out of range).",
      );
    }
    if (echo.some((v, i) => v !== written[i])) {
      throw new RbcBadReplyError(
        `The robot echoed different zeros (${echo.join(",")}); read them back to check.`,
      );
    }
    const readBack = await c.request(COMMANDS.readZeros, undefined);
    if (readBack.some((v, i) => v !== written[i])) {
      throw new RbcVerifyError(
        `Zeros were sent, but the robot reads back ${readBack.join(",")} instead of ${written.join(",")}.`,
        written,
        readBack,
      );
    }
    return { written, readBack };
  });
}
