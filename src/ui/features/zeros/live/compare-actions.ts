import type { AppContext } from "../../../context.ts";
import { focusSoon } from "../../../focus.ts";

/** Shows the comparison of the robot's zeros with kept backup `id` (undefined: closes it). Reading only. */
export function compareWith(ctx: AppContext, id: string | undefined): void {
  ctx.store.update((s) => ({ zeros: { ...s.zeros, compareWith: id } }));
  focusSoon(id === undefined ? "kept-title" : "compare-title");
}
