import { z } from "zod";

// The panel's Content-Security-Policy forbids eval. Zod would otherwise probe `new Function` on its first
// parse (a CSP violation report in the browser) to compile faster validators; the interpreted path is plenty
// for files a person opens. Every protocol module that uses zod imports it from here, so the setting is
// always in place before the first schema is built.
z.config({ jitless: true });

export { z };
