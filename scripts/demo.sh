#!/usr/bin/env bash
# The main job: set up, build, and run the demo scene (meshes/demo.json): the bundled meshes mapped
# by several projectors and texgen, rendered, measured and ranked, into out/ with a gallery page.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build --program
build/apps/uvtk/uvtk run meshes/demo.json --output-dir out --json out/run.json
echo "demo: open out/index.html in a browser (every picture, measure and ranking of the run)" >&2
echo "demo: the program is build/apps/uvtk/uvtk; to type uvtk as the docs do:" >&2
echo "  export PATH=\"$PWD/build/apps/uvtk:\$PATH\"" >&2
