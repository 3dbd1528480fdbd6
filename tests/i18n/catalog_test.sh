#!/usr/bin/env bash
# Every string the app shows has its Simplified Chinese translation, found from the code and the
# data, never from a list kept by hand:
#   1. every string literal passed to a call that shows text goes through tr() (shown_literals.py);
#   2. xgettext extracts the tr() and N_() strings, data_strings.py the lessons' and scenes' texts,
#      and msgcmp checks each has a translation in assets/locale/zh-CN.po that is neither empty
#      nor fuzzy;
#   3. msgfmt -c checks the catalog's form and that each translation keeps its English's printf
#      placeholders (in any order, as %1$s), so numbers and units keep their format.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
shown=(app/ui/*.cpp app/platform/interactive_app.cpp app/web/web_main.cpp)
for f in app/chart/*.cpp; do [[ "$f" == app/chart/svg.cpp ]] || shown+=("$f"); done  # (svg.cpp: markup)
python3 scripts/i18n/shown_literals.py "${shown[@]}"
scripts/i18n/extract.sh > "$tmp/springlab.pot"
count=$(grep -c '^msgid "[^"]' "$tmp/springlab.pot" || true)
echo "catalog_test: $count strings extracted from the code and the data"
[[ "$count" -gt 300 ]] || { echo "catalog_test: only $count strings extracted: is xgettext finding tr()?" >&2; exit 1; }
for po in assets/locale/*.po; do
  msgfmt -c --check-format -o /dev/null "$po"
  msgcmp "$po" "$tmp/springlab.pot"
  echo "catalog_test: $po translates all $count"
done
