#!/usr/bin/env bash
# Runs a Node script of the browser tests or benchmarks with puppeteer-core at hand: installs it
# (npm, into build-wasm/node: nothing outside the clone; it downloads no browser) the first
# time. Usage: tests/web/node.sh SCRIPT [ARGS]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
node_dir="$root/build-wasm/node"
if [[ ! -d "$node_dir/node_modules/puppeteer-core" || ! -d "$node_dir/node_modules/axe-core" ]]; then
  mkdir -p "$node_dir"
  npm install --prefix "$node_dir" --no-audit --no-fund --loglevel=error puppeteer-core@22 axe-core@4 >/dev/null
fi
NODE_PATH="$node_dir/node_modules" exec node "$@"
