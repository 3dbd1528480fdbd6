#!/usr/bin/env bash
# The template of every string springlab shows (gettext POT) on standard output: xgettext over the
# code (the strings passed to tr() or marked N_(), springlab/text.hpp) and data_strings.py over the
# lessons and scenes. Translators update a catalog from it with
#   scripts/i18n/extract.sh > /tmp/springlab.pot && msgmerge -U assets/locale/zh-CN.po /tmp/springlab.pot
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mapfile -t sources < <(find core app -name '*.cpp' -o -name '*.hpp' | sort)
xgettext --language=C++ --from-code=UTF-8 --keyword=tr --keyword=N_ --sort-by-file --no-wrap \
  --package-name=springlab -o "$tmp/code.pot" "${sources[@]}"
python3 scripts/i18n/data_strings.py "$root" > "$tmp/data.pot"
msgcat --no-wrap --use-first "$tmp/code.pot" "$tmp/data.pot"
