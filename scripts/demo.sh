#!/usr/bin/env bash
# The main job: set up, build, and map a bundled mesh with every projector into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
mkdir -p out
mesh=meshes/sphere_latlong.obj
uvtk=build/apps/uvtk/uvtk
for projector in plane two-plane cylinder sphere cube; do
  for omap in isn centroid normal reflection; do
    extra=()
    [ "$omap" = reflection ] && extra=(--eye 0,-4,1)
    printf '%-10s %-11s ' "$projector" "$omap" >&2
    "$uvtk" map "$mesh" --projector "$projector" --omap "$omap" "${extra[@]}" \
      -o "out/sphere_${projector}_${omap}.obj" --json "out/sphere_${projector}_${omap}.json"
  done
done
printf '%-22s ' "sphere --seam cut" >&2
"$uvtk" map "$mesh" --projector sphere --seam cut -o out/sphere_sphere_cut.obj
printf '%-22s ' "cube --cube-layout cross" >&2
"$uvtk" map "$mesh" --projector cube --cube-layout cross -o out/sphere_cube_cross.obj
echo "demo: wrote $(ls out/*.obj | wc -l) OBJ files with UVs into out/" >&2
