#!/usr/bin/env bash
# Makes sure the programs the test suite drives are installed: Debian's Chromium (browser tests; Playwright
# cannot download its own browser here), socat (a PTY pair for the serial-port tests) and a Korean font (the
# browser tests measure Korean labels in their buttons; without a Hangul font Chromium draws boxes).
# Installs them with apt-get when running as root; otherwise says what to install and fails.
# Also Debian's Chromium headless shell when it can: the browser tests run on it when it is there, at half the
# CPU time a page costs the full Chromium (tests/support/chromium.ts); without it they run on the full one.
set -euo pipefail
missing=()
command -v chromium >/dev/null 2>&1 || [ -x /usr/bin/chromium ] || missing+=(chromium)
command -v socat >/dev/null 2>&1 || missing+=(socat)
[ -d /usr/share/fonts/truetype/nanum ] || missing+=(fonts-nanum)
can_install=false
[ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1 && can_install=true
shell_missing=false
[ -x /usr/bin/chromium-headless-shell ] || shell_missing=true
if [ ${#missing[@]} -eq 0 ] && { [ "$shell_missing" = false ] || [ "$can_install" = false ]; }; then
  exit 0
fi
if [ "$can_install" = true ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq >/dev/null
  if [ ${#missing[@]} -gt 0 ]; then
    echo "Installing ${missing[*]} (needed by the tests)..." >&2
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  fi
  if [ "$shell_missing" = true ]; then
    apt-get install -y -qq --no-install-recommends chromium-headless-shell >/dev/null 2>&1 ||
      echo "chromium-headless-shell is not available here: the browser tests run on the full Chromium (slower)." >&2
  fi
  exit 0
fi
echo "The tests need: ${missing[*]}. Install them, e.g. 'sudo apt-get install ${missing[*]}', then run npm test again." >&2
exit 1
