"""Blender Smart UV Project as a peer of `uvtk map --projector atlas`.

Run (Blender 3.4, Debian 12's `blender` package):

    blender -b --factory-startup --python bench/atlas_peers/blender_smart_project.py -- \
        IN.obj OUT.obj --angle-limit 66 --margin-texels 4 --texture-size 1024

Imports IN.obj (triangles), selects every face in edit mode, runs

    bpy.ops.uv.smart_project(angle_limit=radians(angle), island_margin=margin_texels / texture_size,
                             area_weight=0, correct_aspect=True, scale_to_bounds=False)

(margin_method is Blender's default, SCALED, unless --margin-method says otherwise), times only
that call, and exports OUT.obj with per-corner UVs (no normals, no materials, no triangulation,
same axes as the import so positions are unchanged). It then re-reads both files and checks that
the face count, every face's corner count and every corner's position (to 1e-6 by default, see
--position-tolerance) match the input; it exits 1 if not.

Prints one JSON line on stdout, beginning with {"seconds": ...}.
"""
import argparse
import json
import math
import sys
import time

import bpy


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="blender_smart_project.py")
    p.add_argument("input")
    p.add_argument("output")
    p.add_argument("--angle-limit", type=float, default=66.0, help="degrees")
    p.add_argument("--margin-texels", type=float, default=4.0)
    p.add_argument("--texture-size", type=float, default=1024.0)
    p.add_argument("--margin-method", default=None, choices=["SCALED", "ADD", "FRACTION"],
                   help="Blender's margin_method (default: Blender's own default, SCALED)")
    p.add_argument("--position-tolerance", type=float, default=1e-6)
    return p.parse_args(argv)


def read_obj(path):
    """Positions (list of 3-tuples) and faces (lists of 0-based position indices)."""
    verts, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                verts.append(tuple(float(t) for t in line.split()[1:4]))
            elif line.startswith("f "):
                idx = []
                for tok in line.split()[1:]:
                    i = int(tok.split("/")[0])
                    idx.append(i - 1 if i > 0 else len(verts) + i)
                faces.append(idx)
    return verts, faces


def main():
    args = parse_args()
    in_verts, in_faces = read_obj(args.input)

    # Empty scene; import with identical axes on both sides, so the round trip is the identity.
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.wm.obj_import(filepath=args.input, forward_axis="NEGATIVE_Z", up_axis="Y",
                          validate_meshes=False)
    objs = [o for o in bpy.context.scene.objects if o.type == "MESH"]
    if len(objs) != 1:
        print("expected one mesh object, got %d" % len(objs), file=sys.stderr)
        sys.exit(1)
    obj = objs[0]
    bpy.context.view_layer.objects.active = obj
    obj.select_set(True)
    n_faces = len(obj.data.polygons)

    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.mesh.select_mode(type="FACE")
    bpy.ops.mesh.select_all(action="SELECT")
    kwargs = dict(angle_limit=math.radians(args.angle_limit),
                  island_margin=args.margin_texels / args.texture_size,
                  area_weight=0.0, correct_aspect=True, scale_to_bounds=False)
    if args.margin_method:
        kwargs["margin_method"] = args.margin_method
    t0 = time.perf_counter()
    result = bpy.ops.uv.smart_project(**kwargs)
    seconds = time.perf_counter() - t0
    bpy.ops.object.mode_set(mode="OBJECT")
    if "FINISHED" not in result:
        print("smart_project returned %s" % result, file=sys.stderr)
        sys.exit(1)

    bpy.ops.wm.obj_export(filepath=args.output, check_existing=False, export_selected_objects=False,
                          forward_axis="NEGATIVE_Z", up_axis="Y", global_scale=1.0,
                          apply_modifiers=False, export_uv=True, export_normals=False,
                          export_materials=False, export_triangulated_mesh=False,
                          export_smooth_groups=False, export_object_groups=False,
                          export_material_groups=False, export_vertex_groups=False)

    # Verify: same faces, same corner positions, in the same order.
    out_verts, out_faces = read_obj(args.output)
    problems = []
    if len(out_faces) != len(in_faces):
        problems.append("face count %d != input %d" % (len(out_faces), len(in_faces)))
    max_err = 0.0
    for fi, (a, b) in enumerate(zip(in_faces, out_faces)):
        if len(a) != len(b):
            problems.append("face %d has %d corners, input %d" % (fi, len(b), len(a)))
            break
        for ia, ib in zip(a, b):
            pa, pb = in_verts[ia], out_verts[ib]
            max_err = max(max_err, abs(pa[0] - pb[0]), abs(pa[1] - pb[1]), abs(pa[2] - pb[2]))
    if max_err > args.position_tolerance:
        problems.append("corner position differs by %.3g > %.3g" % (max_err, args.position_tolerance))
    report = {
        "seconds": seconds,
        "faces": n_faces,
        "input_faces": len(in_faces),
        "output_faces": len(out_faces),
        "max_position_error": max_err,
        "blender": bpy.app.version_string,
        "angle_limit_deg": args.angle_limit,
        "island_margin": args.margin_texels / args.texture_size,
        "margin_method": args.margin_method or "SCALED (default)",
        "ok": not problems,
    }
    print(json.dumps(report), flush=True)
    if problems:
        for p in problems:
            print("verify: " + p, file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
