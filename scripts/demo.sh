#!/usr/bin/env bash
# The main job: set up, build, map a bundled mesh with every projector into out/, render it, report
# what is wrong with one mapping (out/report_sphere.html) and rank every mapping of the icosphere.
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
# Pictures: the UV grid on the sphere per vertex and per pixel (the pole fan shows the difference),
# and a texgen sphere map on the torus.
"$uvtk" render "$mesh" --projector sphere --texture uvgrid --filter linear_mipmap_linear --env modulate \
  --view-dir 0,-1,1 -o out/render_sphere_uvgrid.png
"$uvtk" render "$mesh" --projector sphere --uv per-pixel --texture uvgrid --filter linear_mipmap_linear \
  --env modulate --view-dir 0,-1,1 -o out/render_sphere_uvgrid_per_pixel.png
"$uvtk" render meshes/torus.obj --texgen sphere_map --texture uvgrid:512 --filter linear --view-dir 0,1,2 \
  -o out/render_torus_sphere_map.png
echo "demo: rendered $(ls out/*.png | wc -l) pictures into out/" >&2
# What is wrong with the sphere projector, and which mapping suits the icosphere best.
"$uvtk" report "$mesh" --projector sphere --json out/report_sphere.json --html out/report_sphere.html \
  --views checker,uvgrid,stretch,angle,area,seams,uverror,layout
"$uvtk" compare meshes/icosphere.obj --json out/compare_icosphere.json --markdown out/compare_icosphere.md \
  --sheet out/compare_icosphere.png >/dev/null
echo "demo: open out/report_sphere.html in a browser; the ranking for the icosphere is out/compare_icosphere.md" >&2
