#!/usr/bin/env bash
# Makes sure the programs the test suite drives are installed: Debian's Chromium (browser tests; Playwright
# cannot download its own browser here), socat (a PTY pair for the serial-port tests) and a Korean font (the
# browser tests measure Korean labels in their buttons; without a Hangul font Chromium draws boxes).
# Installs them with apt-get when running as root; otherwise says what to install and fails.
set -euo pipefail
missing=()
command -v chromium >/dev/null 2>&1 || [ -x /usr/bin/chromium ] || missing+=(chromium)
command -v socat >/dev/null 2>&1 || missing+=(socat)
[ -d /usr/share/fonts/truetype/nanum ] || missing+=(fonts-nanum)
[ ${#missing[@]} -eq 0 ] && exit 0
if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "Installing ${missing[*]} (needed by the tests)..." >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq >/dev/null
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  exit 0
fi
echo "The tests need: ${missing[*]}. Install them, e.g. 'sudo apt-get install ${missing[*]}', then run npm test again." >&2
exit 1
