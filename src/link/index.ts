export * from "./transport.ts";
export * from "./web-serial-transport.ts";
