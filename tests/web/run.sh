#!/usr/bin/env bash
# The browser tests (tests/web/browser_test.cjs) on the site scripts/web.sh built into build-web/,
# in Debian's Chromium through puppeteer-core. About a minute and a half.
# Usage: tests/web/run.sh [check name filter]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
if [[ ! -f "$root/build-web/springlab.wasm" ]]; then
  echo "tests/web/run.sh: build-web/ has no site: scripts/web.sh builds it" >&2
  exit 2
fi
exec "$root/tests/web/node.sh" "$root/tests/web/browser_test.cjs" "$@"
