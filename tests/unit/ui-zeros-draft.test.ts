import { describe, expect, it } from "vitest";
import { FACTORY_ZEROS } from "../../src/protocol/zeros.ts";
import {
  type DraftPlace,
  forgetZerosDraft,
  keepZerosDraft,
  readZerosDraft,
  robotKey,
  ZEROS_DRAFT_PREFIX,
} from "../../src/ui/features/zeros/draft-store.ts";
import { toDraft, unwrittenIds } from "../../src/ui/features/zeros/editor.ts";

/** Unwritten zero changes kept in this browser, one record per robot (issue 33 item 7). */

function mapPlace(map = new Map<string, string>()): DraftPlace & { map: Map<string, string> } {
  return {
    map,
    getItem: (key) => map.get(key) ?? null,
    setItem: (key, value) => {
      map.set(key, value);
    },
    removeItem: (key) => {
      map.delete(key);
    },
  };
}

describe("unwrittenIds", () => {
  it("lists the servos whose field differs from the robot's zero, an empty or invalid field included", () => {
    const draft = toDraft(FACTORY_ZEROS);
    draft[0] = String((FACTORY_ZEROS[0] ?? 0) + 3);
    draft[5] = "";
    draft[9] = ` ${FACTORY_ZEROS[9]} `;
    expect(unwrittenIds(FACTORY_ZEROS, draft)).toEqual([0, 5]);
  });

  it("is empty before the zeros are read", () => {
    expect(unwrittenIds(undefined, toDraft(FACTORY_ZEROS))).toEqual([]);
    expect(unwrittenIds(FACTORY_ZEROS, [])).toEqual([]);
  });
});

describe("the kept draft", () => {
  it("is kept and read back for its own robot only", () => {
    const place = mapPlace();
    const draft = toDraft(FACTORY_ZEROS);
    draft[3] = "70";
    keepZerosDraft(place, "8958899989309", draft, 1_000);
    expect(readZerosDraft(place, "8958899989309")).toEqual({
      version: 1,
      robot: "8958899989309",
      savedAt: 1_000,
      draft,
    });
    expect(readZerosDraft(place, "1111111111111")).toBeUndefined();
    forgetZerosDraft(place, "8958899989309");
    expect(readZerosDraft(place, "8958899989309")).toBeUndefined();
  });

  it("names a robot without a serial number 'unknown'", () => {
    expect(robotKey(undefined)).toBe("unknown");
    expect(robotKey("")).toBe("unknown");
    expect(robotKey("42")).toBe("42");
  });

  it("ignores a damaged or foreign record, and a storage that throws", () => {
    const place = mapPlace();
    place.map.set(`${ZEROS_DRAFT_PREFIX}x`, "{ no");
    expect(readZerosDraft(place, "x")).toBeUndefined();
    place.map.set(
      `${ZEROS_DRAFT_PREFIX}x`,
      JSON.stringify({ version: 1, robot: "y", savedAt: 1, draft: [] }),
    );
    expect(readZerosDraft(place, "x")).toBeUndefined();
    const throwing: DraftPlace = {
      getItem: () => {
        throw new Error("denied");
      },
      setItem: () => {
        throw new Error("full");
      },
      removeItem: () => {
        throw new Error("denied");
      },
    };
    expect(readZerosDraft(throwing, "x")).toBeUndefined();
    expect(() => keepZerosDraft(throwing, "x", toDraft(FACTORY_ZEROS), 1)).not.toThrow();
    expect(() => forgetZerosDraft(throwing, "x")).not.toThrow();
    expect(readZerosDraft(undefined, "x")).toBeUndefined();
  });
});
