#!/usr/bin/env bash
# The browser tests (tests/web/browser_test.cjs) on the site scripts/web.sh built into build-web/:
# installs puppeteer-core (npm, into build-web/_build/node: nothing outside the clone; it
# downloads no browser) and drives Debian's Chromium with it. About a minute and a half.
# Usage: tests/web/run.sh [check name filter]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
node_dir="$root/build-web/_build/node"
if [[ ! -f "$root/build-web/springlab.wasm" ]]; then
  echo "tests/web/run.sh: build-web/ has no site: scripts/web.sh builds it" >&2
  exit 2
fi
if [[ ! -d "$node_dir/node_modules/puppeteer-core" ]]; then
  mkdir -p "$node_dir"
  npm install --prefix "$node_dir" --no-audit --no-fund --loglevel=error puppeteer-core@22 >/dev/null
fi
NODE_PATH="$node_dir/node_modules" exec node "$root/tests/web/browser_test.cjs" "$@"
