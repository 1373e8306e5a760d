/** How the editor writes the time a draft was saved (local time). */

/** "14:02" (local time) of an epoch ms. */
export function formatHourMinute(epochMs: number): string {
  const d = new Date(epochMs);
  return `${String(d.getHours()).padStart(2, "0")}:${String(d.getMinutes()).padStart(2, "0")}`;
}

/** "21 Nov 14:02" for a time not today, "14:02" for today. */
export function formatSavedAt(epochMs: number, now: number): string {
  const d = new Date(epochMs);
  const today = new Date(now);
  const sameDay =
    d.getFullYear() === today.getFullYear() &&
    d.getMonth() === today.getMonth() &&
    d.getDate() === today.getDate();
  if (sameDay) return formatHourMinute(epochMs);
  const month = d.toLocaleString("en-GB", { month: "short" });
  return `${d.getDate()} ${month} ${formatHourMinute(epochMs)}`;
}
