#!/usr/bin/env bash
# The browser test (docs/robustness.md, "The browser test"): the pages `uvtk report --html` and
# `uvtk run` write, opened in Debian's headless Chromium by check_pages.mjs.
# Usage: tests/browser/run.sh UVTK_BIN MESHGEN_BIN WORK_DIR
#   UVTK_BROWSER_TEST_DIR: the folder scripts/setup.sh --validator npm ci's this folder into
#   (default: build/browser-test of the source tree); UVTK_CHROMIUM: the browser (default /usr/bin/chromium).
# Exit 0 pass, 1 fail, 77 skipped (no Chromium).
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: $0 UVTK_BIN MESHGEN_BIN WORK_DIR" >&2; exit 2; }
uvtk=$(realpath "$1")
meshgen=$(realpath "$2")
work=$(realpath -m "$3")
here=$(cd "$(dirname "$0")" && pwd)
source_dir=$(cd "$here/../.." && pwd)
modules=${UVTK_BROWSER_TEST_DIR:-$source_dir/build/browser-test}
chromium=${UVTK_CHROMIUM:-/usr/bin/chromium}

if [ ! -x "$chromium" ]; then
  echo "browser test skipped: $chromium not installed (scripts/setup.sh --validator installs it)"
  exit 77
fi
command -v node > /dev/null || { echo "browser test: node is not installed (scripts/setup.sh --validator installs it)" >&2; exit 1; }
if [ ! -d "$modules/node_modules/puppeteer-core" ]; then
  echo "browser test: $modules/node_modules/puppeteer-core is missing (scripts/setup.sh --validator installs it)" >&2
  exit 1
fi

rm -rf "$work"
mkdir -p "$work"
started=$(date +%s)
# A 40,000-face sphere for the checks, a 99,856-face one for the page's size.
"$meshgen" --sphere 200 101 "$work/sphere40k.obj" 2> /dev/null
"$meshgen" --sphere 316 159 "$work/sphere100k.obj" 2> /dev/null
"$uvtk" report "$work/sphere40k.obj" --projector sphere --html "$work/report.html" -q
"$uvtk" report "$work/sphere100k.obj" --projector sphere --html "$work/report100k.html" -q
(cd "$source_dir" && "$uvtk" run meshes/demo.json --output-dir "$work/demo" -q)

status=0
for page in "$work/report.html" "$work/report100k.html" "$work/demo/index.html"; do
  echo "browser test: $(basename "$page"): $(stat -c %s "$page") bytes"
done
limit=$((5 * 1024 * 1024))
if [ "$(stat -c %s "$work/report100k.html")" -gt "$limit" ]; then
  echo "browser test: report100k.html: the report of a 99,856-face mesh is over 5 MB ($limit bytes)" >&2
  status=1
fi
UVTK_CHROMIUM="$chromium" node "$here/check_pages.mjs" --modules "$modules" --screenshot "$work/report.png" \
  --report "$work/report.html" --report "$work/report100k.html" "$work/demo/index.html" || status=1
echo "browser test: $(( $(date +%s) - started )) s; first screen of report.html in $work/report.png"
exit $status
