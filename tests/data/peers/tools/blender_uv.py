# Ground truth for bpy.ops.uv.sphere_project / cylinder_project (Blender 3.4.1, Debian).
# Run: blender -b --factory-startup --python-exit-code 1 --python gt.py
import bpy, bmesh, os, sys, struct, math, json

MESHES = ["icosphere", "cylinder_capped", "offcentre"]
MDIR = os.environ.get("MESH_DIR", ".")  # offcentre.obj and the bundled meshes
ODIR = os.environ.get("OUT_DIR", "out")
os.makedirs(ODIR, exist_ok=True)
f32 = lambda x: struct.unpack("f", struct.pack("f", x))[0]
log = {}

def read_obj(path):
    vs, fs = [], []
    for line in open(path):
        p = line.split()
        if not p: continue
        if p[0] == "v": vs.append(tuple(float(c) for c in p[1:4]))
        elif p[0] == "f": fs.append(tuple(int(c.split("/")[0]) - 1 for c in p[1:]))
    return vs, fs

def clear():
    if bpy.context.object and bpy.context.object.mode != "OBJECT":
        bpy.ops.object.mode_set(mode="OBJECT")
    for ob in list(bpy.data.objects):
        bpy.data.objects.remove(ob, do_unlink=True)
    for me in list(bpy.data.meshes):
        bpy.data.meshes.remove(me)

def find_view3d():
    for win in bpy.context.window_manager.windows:
        for area in win.screen.areas:
            if area.type == "VIEW_3D":
                for region in area.regions:
                    if region.type == "WINDOW":
                        return win, area, region
    return None

def run(name, op, mode):
    clear()
    path = os.path.join(MDIR, name + ".obj")
    bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z")
    ob = bpy.context.selected_objects[0]
    bpy.context.view_layer.objects.active = ob
    me = ob.data
    vs, fs = read_obj(path)
    # checks: coordinates unchanged (float32 of the file's values), same vertex and face order
    assert len(me.vertices) == len(vs) and len(me.polygons) == len(fs)
    maxdiff = max(abs(me.vertices[i].co[k] - f32(vs[i][k])) for i in range(len(vs)) for k in range(3))
    order_ok = all(tuple(p.vertices) == fs[i] for i, p in enumerate(me.polygons))
    mw_identity = all(abs(ob.matrix_world[r][c] - (1.0 if r == c else 0.0)) == 0 for r in range(4) for c in range(4))
    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.mesh.select_all(action="SELECT")
    ts = bpy.context.scene.tool_settings
    kw = dict(direction="ALIGN_TO_OBJECT", align="POLAR_ZX")
    fn = bpy.ops.uv.sphere_project if op == "sphere" else bpy.ops.uv.cylinder_project
    if mode == "bg":
        res = fn(**kw)
    else:
        pivot = mode.split("-", 1)[1]
        ts.transform_pivot_point = pivot
        v = find_view3d()
        assert v, "no VIEW_3D area"
        win, area, region = v
        with bpy.context.temp_override(window=win, area=area, region=region):
            assert bpy.context.space_data.type == "VIEW_3D"
            res = fn(**kw)
        ts.transform_pivot_point = "MEDIAN_POINT"
    bpy.ops.object.mode_set(mode="OBJECT")
    uvl = me.uv_layers.active.data
    tag = "%s_%s_%s" % (name, op, mode)
    with open(os.path.join(ODIR, tag + ".csv"), "w") as f:
        f.write("face,corner,vertex,x,y,z,u,v\n")
        for p in me.polygons:
            for c, li in enumerate(p.loop_indices):
                vi = me.loops[li].vertex_index
                co = me.vertices[vi].co
                uv = uvl[li].uv
                f.write("%d,%d,%d,%r,%r,%r,%r,%r\n" % (p.index, c, vi, co[0], co[1], co[2], uv[0], uv[1]))
    bpy.ops.object.select_all(action="DESELECT")
    ob.select_set(True)
    bpy.ops.wm.obj_export(filepath=os.path.join(ODIR, tag + ".obj"), export_selected_objects=True,
                          forward_axis="Y", up_axis="Z", export_normals=False, export_uv=True,
                          export_materials=False, apply_modifiers=False)
    log[tag] = dict(result=list(res), coord_maxdiff=maxdiff, face_order_same=order_ok,
                    matrix_world_identity=mw_identity, pivot_default=None)
    print("DONE", tag, res, "maxdiff", maxdiff, "order", order_ok, "mw_identity", mw_identity)

print("VERSION", bpy.app.version_string, "default pivot", bpy.context.scene.tool_settings.transform_pivot_point,
      "cursor", tuple(bpy.context.scene.cursor.location), "windows", len(bpy.context.window_manager.windows),
      "view3d", find_view3d() is not None)
for name in MESHES:
    for op in ("sphere", "cylinder"):
        for mode in ("bg", "view3d-MEDIAN_POINT", "view3d-BOUNDING_BOX_CENTER"):
            run(name, op, mode)
# radius / align variations on the offcentre mesh (background)
def variant(name, op, **kw):
    clear()
    bpy.ops.wm.obj_import(filepath=os.path.join(MDIR, name + ".obj"), forward_axis="Y", up_axis="Z")
    ob = bpy.context.selected_objects[0]; bpy.context.view_layer.objects.active = ob
    bpy.ops.object.mode_set(mode="EDIT"); bpy.ops.mesh.select_all(action="SELECT")
    (bpy.ops.uv.sphere_project if op == "sphere" else bpy.ops.uv.cylinder_project)(**kw)
    bpy.ops.object.mode_set(mode="OBJECT")
    me = ob.data; uvl = me.uv_layers.active.data
    return [tuple(uvl[i].uv) for i in range(len(me.loops))]
base_c = variant("offcentre", "cylinder", direction="ALIGN_TO_OBJECT", align="POLAR_ZX")
zy_c = variant("offcentre", "cylinder", direction="ALIGN_TO_OBJECT", align="POLAR_ZY")
r3_c = variant("offcentre", "cylinder", direction="ALIGN_TO_OBJECT", align="POLAR_ZX", radius=3.0)
base_s = variant("offcentre", "sphere", direction="ALIGN_TO_OBJECT", align="POLAR_ZX")
zy_s = variant("offcentre", "sphere", direction="ALIGN_TO_OBJECT", align="POLAR_ZY")
print("VARIANT cylinder ZY==ZX", zy_c == base_c, "radius3==radius1", r3_c == base_c, "sphere ZY==ZX", zy_s == base_s)
# operator property defaults as seen from RNA
for opn in ("sphere_project", "cylinder_project"):
    rna = getattr(bpy.ops.uv, opn).get_rna_type()
    print("PROPS", opn, {p.identifier: getattr(p, "default", None) for p in rna.properties if p.identifier != "rna_type"})
json.dump(log, open(os.path.join(ODIR, "log.json"), "w"), indent=1)
