/**
 * The Class view as the rest of the panel uses it (docs/architecture.md, "Features"): what a class robot is doing,
 * for the question before leaving the page. The view itself loads lazily through the router.
 */
export { robotTask } from "./robot-task.ts";
