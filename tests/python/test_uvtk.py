# The Python module uvtk against hand-computed values, its own contract (shapes, dtypes, views,
# errors), and the `uvtk` program: the same UVs bit for bit.
import gc
import json
import pickle
import math
import struct
import threading
import time
import zlib

import numpy as np
import pytest

import uvtk

# ---- meshes built here, and OBJ text ----


def octahedron():
    """The unit octahedron, counter-clockwise from outside."""
    positions = np.array([[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
    triangles = np.array([[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4], [1, 0, 5], [2, 1, 5], [3, 2, 5], [0, 3, 5]])
    return positions, triangles


def uv_sphere(rings=9, segments=13, center=(0.3, -0.2, 0.5), radii=(1.0, 1.3, 0.8)):
    """A latitude-longitude ellipsoid with single-vertex poles (so pole corners exist)."""
    points = [(0.0, 0.0, 1.0)]
    for i in range(1, rings):
        theta = math.pi * i / rings
        for j in range(segments):
            phi = 2 * math.pi * j / segments + 0.1
            points.append((math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta)))
    points.append((0.0, 0.0, -1.0))
    ring = lambda i, j: 1 + (i - 1) * segments + j % segments
    bottom = len(points) - 1
    faces = [(0, ring(1, j), ring(1, j + 1)) for j in range(segments)]
    for i in range(1, rings - 1):
        for j in range(segments):
            a, b, c, d = ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)
            faces += [(a, b, c), (a, c, d)]
    faces += [(bottom, ring(rings - 1, j + 1), ring(rings - 1, j)) for j in range(segments)]
    return np.array(points) * radii + center, np.array(faces)


def torus(major=16, minor=9, radius=1.0, tube=0.35):
    u = np.repeat(2 * np.pi * np.arange(major) / major, minor)
    v = np.tile(2 * np.pi * np.arange(minor) / minor + 0.2, major)
    positions = np.stack([(radius + tube * np.cos(v)) * np.cos(u), (radius + tube * np.cos(v)) * np.sin(u),
                          tube * np.sin(v)], axis=1)
    index = lambda i, j: (i % major) * minor + j % minor
    faces = []
    for i in range(major):
        for j in range(minor):
            a, b, c, d = index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)
            faces += [(a, b, c), (a, c, d)]
    return positions, np.array(faces)


def capped_cylinder(segments=12, rows=3, radius=0.7, height=2.0):
    """An open tube of `rows` bands closed by two fans about centre vertices."""
    phi = 2 * np.pi * np.arange(segments) / segments + 0.05
    points = [(radius * math.cos(p), radius * math.sin(p), height * r / rows) for r in range(rows + 1) for p in phi]
    ring = lambda r, j: r * segments + j % segments
    faces = []
    for r in range(rows):
        for j in range(segments):
            a, b, c, d = ring(r, j), ring(r, j + 1), ring(r + 1, j + 1), ring(r + 1, j)
            faces += [(a, b, c), (a, c, d)]
    top, bottom = len(points), len(points) + 1
    points += [(0.0, 0.0, height), (0.0, 0.0, 0.0)]
    faces += [(top, ring(rows, j), ring(rows, j + 1)) for j in range(segments)]
    faces += [(bottom, ring(0, j + 1), ring(0, j)) for j in range(segments)]
    return np.array(points), np.array(faces)


def unit_square():
    return np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float), np.array([[0, 1, 2], [0, 2, 3]])


def write_obj(path, positions, triangles):
    with open(path, "w") as f:
        f.writelines(f"v {x!r} {y!r} {z!r}\n" for x, y, z in positions.tolist())
        f.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in triangles.tolist())
    return path


def read_obj(path):
    """positions (V, 3), triangles (F, 3), per-corner texture coordinates (F, 3, K) of an OBJ."""
    positions, texcoords, triangles, corners = [], [], [], []
    for line in open(path):
        words = line.split()
        if not words or words[0].startswith("#"):
            continue
        if words[0] == "v":
            positions.append([float(x) for x in words[1:4]])
        elif words[0] == "vt":
            texcoords.append([float(x) for x in words[1:]])
        elif words[0] == "f":
            refs = [w.split("/") for w in words[1:]]
            assert len(refs) == 3, line
            triangles.append([int(r[0]) - 1 for r in refs])
            corners.append([int(r[1]) - 1 for r in refs])
    texcoords = np.array(texcoords)
    return np.array(positions), np.array(triangles), texcoords[np.array(corners)]


MESHES = {"sphere": uv_sphere, "torus": torus, "cylinder": capped_cylinder}


@pytest.fixture(params=sorted(MESHES))
def mesh_file(request, tmp_path):
    return write_obj(tmp_path / f"{request.param}.obj", *MESHES[request.param]())


def words(**options):
    """The command line the `uvtk` program is given for these keywords (an independent spelling)."""
    out = []
    for key, value in options.items():
        name = "--" + key.replace("_", "-")
        if value is True:
            out.append(name)
        elif isinstance(value, (tuple, list)):
            out.append(name + "=" + ",".join(repr(x) for x in value))
        else:
            out += [name, str(value)]
    return out


# ---- version ----


def test_version_is_the_programs(cli):
    assert uvtk.__version__ == uvtk.version()
    assert uvtk.__version__.count(".") == 2
    assert uvtk.__version__ in cli("--version").stdout


# ---- meshes ----


def test_mesh_from_numpy_has_read_only_views_of_its_arrays():
    positions, triangles = octahedron()
    mesh = uvtk.Mesh(positions, triangles.astype(np.int16))
    assert (mesh.vertex_count, mesh.face_count) == (6, 8)
    assert mesh.positions.dtype == np.float64 and mesh.positions.shape == (6, 3)
    assert mesh.triangles.dtype == np.int32 and mesh.triangles.shape == (8, 3)
    np.testing.assert_array_equal(mesh.positions, positions)
    np.testing.assert_array_equal(mesh.triangles, triangles)
    assert mesh.uv is None and mesh.normals is None
    for array in (mesh.positions, mesh.triangles):
        assert not array.flags.writeable and not array.flags.owndata
    assert np.shares_memory(mesh.positions, mesh.positions)
    with pytest.raises(ValueError, match="read-only"):
        mesh.positions[0, 0] = 5.0
    assert "6 vertices, 8 faces" in repr(mesh)


def test_mesh_accepts_any_integer_dtype():
    positions, triangles = octahedron()
    for dtype in (np.uint8, np.int32, np.int64, np.uint64):
        np.testing.assert_array_equal(uvtk.Mesh(positions, triangles.astype(dtype)).triangles, triangles)
    np.testing.assert_array_equal(uvtk.Mesh(positions.tolist(), triangles.tolist()).triangles, triangles)


def test_mesh_per_corner_uv_and_normals_round_trip():
    positions, triangles = unit_square()
    uv = positions[:, :2][triangles].copy()
    uv[1, 2] = np.nan  # corner 2 of face 1 has none
    normals = np.tile([0.0, 0.0, 1.0], (4, 1))
    mesh = uvtk.Mesh(positions, triangles, uv=uv, normals=normals)
    np.testing.assert_array_equal(mesh.uv, uv)  # NaN where NaN
    assert mesh.uv.shape == (2, 3, 2) and mesh.normals.shape == (2, 3, 3)
    np.testing.assert_array_equal(mesh.normals, np.broadcast_to([0.0, 0.0, 1.0], (2, 3, 3)))
    assert "uv" in repr(mesh)


def test_bad_meshes_are_value_errors():
    positions, triangles = octahedron()
    with pytest.raises(ValueError, match="7"):
        uvtk.Mesh(positions, [[0, 1, 7]])
    with pytest.raises(ValueError, match="-1"):
        uvtk.Mesh(positions, [[0, 1, -1]])
    with pytest.raises(ValueError, match="beyond int32"):
        uvtk.Mesh(positions, [[0, 1, 2**40]])
    with pytest.raises(ValueError, match=r"positions: expected an array of shape \(N, 3\), got \(6, 2\)"):
        uvtk.Mesh(positions[:, :2], triangles)
    with pytest.raises(ValueError, match=r"\(F, 3\)"):
        uvtk.Mesh(positions, triangles.reshape(-1))
    with pytest.raises(ValueError, match=r"uv: .*\(F, 3, 2\)"):
        uvtk.Mesh(positions, triangles, uv=np.zeros((8, 3)))
    with pytest.raises(TypeError, match="integer"):
        uvtk.Mesh(positions, triangles.astype(float))
    bad = positions.copy()
    bad[2, 1] = np.inf
    with pytest.raises(ValueError):
        uvtk.Mesh(bad, triangles)


def test_read_mesh_reads_what_was_written(tmp_path):
    positions, triangles = uv_sphere()
    mesh = uvtk.read_mesh(write_obj(tmp_path / "s.obj", positions, triangles))
    np.testing.assert_array_equal(mesh.positions, positions)  # repr() text reads back exactly
    np.testing.assert_array_equal(mesh.triangles, triangles)
    mesh, warnings = uvtk.read_mesh(str(tmp_path / "s.obj"), with_warnings=True)
    assert warnings["degenerate_faces"] == 0 and warnings["unreferenced_vertices"] == 0
    assert uvtk.check_mesh(mesh)["degenerate_faces"] == 0


def test_read_mesh_of_the_repositorys_meshes(meshes_dir):
    mesh = uvtk.read_mesh(meshes_dir / "cube.obj")
    assert mesh.face_count >= 12 and mesh.positions.shape[1] == 3


def test_missing_file_is_an_input_error_naming_it(tmp_path, cli):
    path = tmp_path / "nowhere.off"
    with pytest.raises(uvtk.InputError) as error:
        uvtk.read_mesh(path)
    assert str(path) in str(error.value)
    assert not isinstance(error.value, ValueError)
    run = cli("map", path, "-o", tmp_path / "out.obj")
    assert run.returncode == 3 and str(error.value) in run.stderr


def test_malformed_file_is_an_input_error_with_its_line(tmp_path):
    path = tmp_path / "bad.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    with pytest.raises(uvtk.InputError, match=f"{path}:4: error:"):
        uvtk.read_mesh(path)


def test_formats_by_extension_keep_the_uvs(tmp_path):
    """A sphere mapping written as PLY (doubles: every bit), binary and ASCII, and as GLB (float32,
    v stored as 1 - v); each read back per corner; a glTF's broken file names its JSON pointer."""
    positions, triangles = uv_sphere()
    m = uvtk.map(uvtk.Mesh(positions, triangles), projector="sphere")
    uvtk.write_mesh(tmp_path / "s.ply", m)
    uvtk.write_mesh(tmp_path / "t.ply", m, ascii=True)
    uvtk.write_mesh(tmp_path / "s.glb", m)
    for name in ("s.ply", "t.ply"):
        np.testing.assert_array_equal(uvtk.read_mesh(tmp_path / name).uv, m.uv)
    glb = uvtk.read_mesh(tmp_path / "s.glb")
    np.testing.assert_array_equal(glb.uv[..., 0], m.uv[..., 0].astype(np.float32))
    np.testing.assert_array_equal(glb.uv[..., 1], 1 - (1 - m.uv[..., 1]).astype(np.float32).astype(np.float64))
    assert (tmp_path / "t.ply").read_bytes().startswith(b"ply\nformat ascii 1.0\n")
    broken = tmp_path / "broken.gltf"
    broken.write_text('{"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"attributes": {}}]}]}')
    with pytest.raises(uvtk.InputError, match=f"{broken}: /meshes/0/primitives/0"):
        uvtk.read_mesh(broken)



def test_every_format_gives_back_the_corners_a_map_left_without_a_uv(tmp_path):
    """Normal rays from a torus's inner side miss the cylinder; every writer lists those faces, and
    every reader gives their corners back as NaN (no UV) rather than the (0, 0) the file holds."""
    positions, triangles = torus()
    m = uvtk.map(uvtk.Mesh(positions, triangles), projector="cylinder", omap="normal")
    invalid = np.asarray(m.invalid_reason) != 0
    assert 0 < invalid.any(axis=1).sum() < len(triangles)
    for name in ("t.obj", "t.ply", "t.glb"):
        uvtk.write_mesh(tmp_path / name, m)
        mesh, warnings = uvtk.read_mesh(tmp_path / name, with_warnings=True)
        assert warnings["listed_invalid_uv_faces"] == invalid.any(axis=1).sum(), name
        np.testing.assert_array_equal(np.isnan(mesh.uv).any(axis=2), invalid, err_msg=name)


# ---- mappings: hand-computed values ----


def test_plane_on_the_unit_square_gives_x_and_y():
    positions, triangles = unit_square()
    m = uvtk.map(uvtk.Mesh(positions, triangles), projector="plane")
    np.testing.assert_array_equal(m.uv, positions[:, :2][triangles])
    stretched = positions * [2, 4, 1] + [0, 0, 3]  # the box fit scales back to the unit square
    m = uvtk.map(uvtk.Mesh(stretched, triangles), projector="plane", fit="bbox")
    np.testing.assert_array_equal(m.uv, positions[:, :2][triangles])
    assert m.verdict == {"status": "pass", "reasons": []}
    assert (m.state == uvtk.OK).all() and (m.face_flags == 0).all()
    assert m.source == "projector" and m.w is None and m.q is None


def test_sphere_on_the_octahedron_follows_the_atan2_convention():
    mesh = uvtk.Mesh(*octahedron())
    m = uvtk.map(mesh, projector="sphere", fit="none", seam="none", pole="none")
    # u = atan2(y, x) / 2 pi in [0, 1): +x 0, +y 1/4, -x 1/2, -y 3/4; v = 1 - phi/pi; poles u = 0
    u_of = {0: 0.0, 1: 0.25, 2: 0.5, 3: 0.75, 4: 0.0, 5: 0.0}
    v_of = {0: 0.5, 1: 0.5, 2: 0.5, 3: 0.5, 4: 1.0, 5: 0.0}
    triangles = mesh.triangles
    expected = np.array([[[u_of[i], v_of[i]] for i in face] for face in triangles.tolist()])
    np.testing.assert_allclose(m.uv, expected, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(m.state, np.where(triangles >= 4, uvtk.POLE, uvtk.OK))
    assert m.state.dtype == np.uint8 and m.state.shape == (8, 3)
    assert (m.face_flags & uvtk.FACE_POLE).all()
    assert (m.face_flags & uvtk.FACE_SEAM_STRADDLE).astype(bool).tolist() == [0, 0, 0, 1, 0, 0, 0, 1]

    # shift: in the faces spanning -y (3/4) and +x (0), +x becomes 1; fan poles take their face's mean u
    m = uvtk.map(mesh, projector="sphere", fit="none", seam="shift", pole="fan")
    np.testing.assert_allclose(m.uv[3], [[0.75, 0.5], [1.0, 0.5], [0.875, 1.0]], rtol=0, atol=1e-15)
    np.testing.assert_allclose(m.uv[7], [[1.0, 0.5], [0.75, 0.5], [0.875, 0.0]], rtol=0, atol=1e-15)
    np.testing.assert_allclose(m.uv[0], [[0.0, 0.5], [0.25, 0.5], [0.125, 1.0]], rtol=0, atol=1e-15)


def test_a_corner_at_the_spheres_centre_is_invalid_with_its_reason():
    positions = np.array([[0, 0, 0], [1, 0, 0.1], [0, 1, 0.1]], dtype=float)
    m = uvtk.map(uvtk.Mesh(positions, [[0, 1, 2]]), projector="sphere", fit="none")
    assert m.state.tolist() == [[uvtk.INVALID, uvtk.OK, uvtk.OK]]
    assert m.invalid_reason[0, 0] != 0 and m.invalid_reason[0, 1:].tolist() == [0, 0]
    assert uvtk.INVALID_REASONS[m.invalid_reason[0, 0]] in ("miss", "not_finite")
    assert m.uv[0, 0].tolist() == [0.0, 0.0]
    assert m.face_flags[0] & uvtk.FACE_INVALID
    assert m.verdict["status"] == "fail" and m.verdict["reasons"][0]["rule"] == "invalid_corners"


def test_triplanar_the_camera_and_density_are_keywords():
    positions, triangles = unit_square()
    mesh = uvtk.Mesh(positions * 3, triangles)  # in z = 0, facing +z: the z projection (x, y) T
    m = uvtk.map(mesh, projector="triplanar", tile=0.5, triplanar_preset="godot")
    np.testing.assert_array_equal(m.uv, (positions[:, :2] * [1.5, -1.5])[triangles])  # Godot's z: (x, -y) T
    options = uvtk.MapOptions()
    options.projector, options.eye, options.fovy = "camera", (0.0, 0.0, 5.0), 90.0
    assert options.command_line() == "--projector camera --eye 0,0,5 --fovy 90"
    m = uvtk.map(mesh, options)
    np.testing.assert_allclose(m.uv, (0.5 + positions[:, :2] * 3 / 10)[triangles], rtol=0, atol=1e-15)
    # Texel density: the plane maps the square isometrically (1024 texels per unit); 512 halves the UVs.
    m = uvtk.map(mesh, projector="plane", fit="none", density=512, texture_size=(1024, 1024))
    np.testing.assert_array_equal(m.uv, (positions[:, :2] * 1.5)[triangles])


def test_keywords_reach_every_option():
    mesh = uvtk.Mesh(*octahedron())
    m = uvtk.map(mesh, fit="none", fail_on=["pole_area=0.5"], warn_on=["stretch_p99=100"])
    assert m.verdict["status"] == "fail"
    reason = m.verdict["reasons"][0]
    assert (reason["rule"], reason["severity"], reason["threshold"]) == ("pole_area", "fail", 0.5)
    assert reason["value"] > 0.5 and reason["faces"] == 8 and reason["text"].startswith("pole_area")
    # a negative vector, a float, a flag, None (not given, where that is allowed) and numpy values
    shifted = uvtk.map(mesh, projector="sphere", center=np.array([-0.0, 0.0, -0.0]), scale=np.float64(1.0),
                       flip_v=np.True_, seam="none", pole="none", density=None)
    plain = uvtk.map(mesh, projector="sphere", fit="none", seam="none", pole="none")
    np.testing.assert_array_equal(shifted.uv[..., 1], 1 - plain.uv[..., 1])
    np.testing.assert_array_equal(shifted.uv[..., 0], plain.uv[..., 0])
    moved = uvtk.map(mesh, fit="none", center=(-1, 0, 0), seam="none", pole="none")
    assert moved.uv[0, 0].tolist() == [0.0, 0.5]  # +x seen from (-1, 0, 0) is still at u = 0


def test_options_object_gives_the_same_mapping():
    mesh = uvtk.Mesh(*torus())
    options = uvtk.MapOptions()
    options.projector, options.caps, options.cap_angle = "cylinder", True, 30.0
    assert options.command_line() == "--projector cylinder --caps --cap-angle 30"
    np.testing.assert_array_equal(uvtk.map(mesh, options=options).uv,
                                  uvtk.map(mesh, projector="cylinder", caps=True, cap_angle=30).uv)
    assert uvtk.MapOptions.parse("--projector cube --uv-scale 2,1").uv_scale == [2.0, 1.0]
    with pytest.raises(TypeError, match="not both"):
        uvtk.map(mesh, options=options, projector="sphere")
    assert uvtk.TexgenOptions.parse("--s object_linear:1,0,0,0").s == "object_linear:1,0,0,0"


def test_bad_options_are_value_errors_with_the_programs_message(tmp_path, cli):
    path = write_obj(tmp_path / "o.obj", *octahedron())
    mesh = uvtk.read_mesh(path)
    with pytest.raises(ValueError) as error:
        uvtk.map(mesh, projector="bogus")
    message = str(error.value)  # the program's words, naming the keyword rather than the option
    assert message.startswith("projector: 'bogus' is not one of: plane, ")
    run = cli("map", path, "-o", tmp_path / "out.obj", "--projector", "bogus")
    assert run.returncode == 2 and "--" + message in run.stderr
    with pytest.raises(ValueError, match="^no_such_option: not a parameter here"):
        uvtk.map(mesh, no_such_option=1)
    with pytest.raises(ValueError, match="cap_angel: not a parameter here; did you mean cap_angle[?]"):
        uvtk.map(mesh, projector="cylinder", cap_angel=30)
    with pytest.raises(TypeError, match="^cap_angle: expected a number, got 'steep'"):
        uvtk.map(mesh, projector="cylinder", caps=True, cap_angle="steep")
    with pytest.raises(ValueError):
        uvtk.MapOptions.parse("--seam sideways")
    with pytest.raises(ValueError):
        uvtk.texgen(mesh, s="object_linear:1,0")
    with pytest.raises(TypeError):
        uvtk.map(octahedron()[0])


# ---- views, not copies ----


def test_mapping_arrays_are_read_only_views_that_keep_the_mapping_alive():
    mesh = uvtk.Mesh(*uv_sphere())
    m = uvtk.map(mesh, projector="cube")
    first, second = m.uv, m.uv
    assert first.shape == (mesh.face_count, 3, 2) and first.dtype == np.float64
    assert first.base is not None and not first.flags.owndata and not first.flags.writeable
    assert np.shares_memory(first, second)
    assert first.__array_interface__["data"][0] == second.__array_interface__["data"][0]
    with pytest.raises(ValueError):
        first[0, 0, 0] = 2.0
    for name in ("w", "state", "invalid_reason", "face_flags"):
        array = getattr(m, name)
        assert not array.flags.writeable and np.shares_memory(array, getattr(m, name)), name
    assert m.w.shape == (mesh.face_count, 3) and set(np.unique(m.w)) <= set(range(6))  # the cube face ids
    expected = first.copy()
    uv = uvtk.map(mesh, projector="cube").uv  # the only reference to its mapping
    del m, first, second
    gc.collect()
    junk = [np.full(uv.shape, 7.0) for _ in range(20)]
    np.testing.assert_array_equal(uv, expected)
    assert junk


def test_the_mappings_mesh_is_its_own_and_cut_along_the_seam():
    mesh = uvtk.Mesh(*uv_sphere())
    m = uvtk.map(mesh, seam="cut")
    assert m.mesh.face_count > mesh.face_count and m.uv.shape == (m.mesh.face_count, 3, 2)
    assert m.uv.min() >= 0 and m.uv.max() <= 1
    assert m.summary["added_faces"] == m.mesh.face_count - mesh.face_count > 0
    assert m.summary["added_vertices"] == m.mesh.vertex_count - mesh.vertex_count > 0
    positions = m.mesh.positions
    del m
    gc.collect()
    assert positions.shape[1] == 3 and np.isfinite(positions).all()


def programs_record(cli, tmp_path, mesh_file, options):
    run = cli("map", mesh_file, "-o", tmp_path / "cli.obj", "--json", tmp_path / "cli.json", *words(**options))
    assert run.returncode == 0, run.stderr
    return json.loads((tmp_path / "cli.json").read_text())


@pytest.mark.parametrize("options", [dict(projector="sphere"), dict(projector="cylinder", seam="cut", caps=True)])
def test_summary_is_the_programs_record(options, cli, tmp_path):
    path = write_obj(tmp_path / "s.obj", *uv_sphere())
    theirs = programs_record(cli, tmp_path, path, options)
    m = uvtk.map(uvtk.read_mesh(path), **options)
    ours = m.summary
    for record in (ours, theirs):  # times, the output's name and the input record (below) aside
        for key in ("milliseconds", "output", "input"):
            record.pop(key, None)
    assert ours == theirs
    assert m.verdict["status"] in repr(m) and m.verdict["status"] == theirs["judgement"]["verdict"]


def test_summary_input_is_the_inputs(cli, tmp_path):
    path = write_obj(tmp_path / "s.obj", *uv_sphere())
    theirs = programs_record(cli, tmp_path, path, dict(seam="cut"))["input"]
    ours = uvtk.map(uvtk.read_mesh(path), seam="cut").summary["input"]
    theirs.pop("path")
    assert ours == theirs


def test_work_releases_the_gil():
    mesh = uvtk.Mesh(*torus(major=400, minor=200))
    span = {}

    def work():
        span["start"] = time.perf_counter()
        uvtk.map(mesh, projector="sphere", overlap_resolution=2048)
        span["end"] = time.perf_counter()

    worker = threading.Thread(target=work)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
    worker.join()
    start, end = span["start"], span["end"]
    middle = [t for t in ticks if start + 0.25 * (end - start) < t < end - 0.25 * (end - start)]
    assert end - start > 0.02 and middle, "the main thread did not run while map() worked"


# ---- the program's UVs, bit for bit ----

MAP_OPTIONS = [
    dict(projector="sphere", fit="bbox", seam="shift"),
    dict(projector="sphere", seam="cut"),
    dict(projector="sphere", seam="none", pole="none", sphere_preset="glu"),
    dict(projector="sphere", seam_place="auto", uv_rotate=30, uv_scale=(2, 1)),
    dict(projector="cylinder", caps=True, cap_angle=30),
    dict(projector="cylinder", seam="cut", fit="pca"),
    dict(projector="cube"),
    dict(projector="cube", cube_layout="cross", flip_u=True),
    dict(projector="plane", fit="obb"),
    dict(projector="sphere", omap="normal", fit="none", center=(-0.1, 0.2, 0.3)),
    dict(projector="two-plane", plane_u=(1, 0, 0, 0.5), plane_v=(0, 0.6, 0.8, -1)),
]


@pytest.mark.parametrize("options", MAP_OPTIONS, ids=lambda o: " ".join(words(**o)))
def test_map_equals_the_programs_uvs_bit_for_bit(options, mesh_file, cli, tmp_path):
    out = tmp_path / "cli.obj"
    run = cli("map", mesh_file, "-o", out, *words(**options))
    assert run.returncode == 0, run.stderr
    positions, triangles, corner_uv = read_obj(out)

    mesh = uvtk.read_mesh(mesh_file)
    m = uvtk.map(mesh, **options)
    np.testing.assert_array_equal(m.mesh.positions, positions)
    np.testing.assert_array_equal(m.mesh.triangles, triangles)
    np.testing.assert_array_equal(m.uv, corner_uv)
    # a mesh from numpy arrays maps the same, and write_mesh writes what the program writes
    same = uvtk.map(uvtk.Mesh(mesh.positions.copy(), mesh.triangles.copy()), **options)
    np.testing.assert_array_equal(same.uv, m.uv)
    uvtk.write_mesh(tmp_path / "py.obj", mesh, m)
    for ours, theirs in zip(read_obj(tmp_path / "py.obj"), (positions, triangles, corner_uv)):
        np.testing.assert_array_equal(ours, theirs)


TEXGEN_OPTIONS = [
    dict(s="object_linear:1,0,0,0", t="eye_linear:0,1,0,0"),
    dict(s="object_linear:0.5,0,0,0.5", t="object_linear:0,0.5,0,0.5", r="object_linear:0,0,1,0"),
    dict(mode="sphere_map", eye=(0, 0, 5), center=(0, 0, 0)),
    dict(mode="normal_map", eye=(3, -2, 4), center=(0, 0, 0), up=(0, 0, 1)),
    dict(s="eye_linear:1,0,0,0", t="eye_linear:0,1,0,0", eye=(1, 2, 6), center=(0, 0, 0), no_normalize=True),
]


@pytest.mark.parametrize("options", TEXGEN_OPTIONS, ids=lambda o: " ".join(words(**o)))
def test_texgen_equals_the_programs_bit_for_bit(options, mesh_file, cli, tmp_path):
    out = tmp_path / "cli.obj"
    run = cli("texgen", mesh_file, "-o", out, *words(**options))
    assert run.returncode == 0, run.stderr
    _, _, corner_stp = read_obj(out)

    m = uvtk.texgen(uvtk.read_mesh(mesh_file), **options)
    assert m.source == "texgen" and (m.q == 1).all()
    np.testing.assert_array_equal(m.uv, corner_stp[..., :2])
    # r: written when generated, else 0; q: 1 unless generated
    np.testing.assert_array_equal(m.w, corner_stp[..., 2] if corner_stp.shape[-1] == 3 else 0.0)


def test_texgen_keywords_are_typed_and_threads_judge(mesh_file, cli, tmp_path):
    mesh = uvtk.read_mesh(mesh_file)
    normalized = uvtk.texgen(mesh, mode="normal_map", eye=(3, -2, 4), center=(0, 0, 0))
    raw = uvtk.texgen(mesh, mode="normal_map", eye=(3, -2, 4), center=(0, 0, 0), no_normalize=True)
    assert not np.array_equal(normalized.uv, raw.uv)  # the flag matters here
    np.testing.assert_array_equal(uvtk.texgen(mesh, mode="normal_map", eye=(3, -2, 4), center=(0, 0, 0),
                                              no_normalize=0).uv, normalized.uv)  # 0 is False
    with pytest.raises(TypeError, match=r"^no_normalize: expected True or False, got 'yes'$"):
        uvtk.texgen(mesh, no_normalize="yes")
    with pytest.raises(ValueError, match=r"^mdoe: not a parameter here; did you mean mode\?$"):
        uvtk.texgen(mesh, mdoe="sphere_map")
    with pytest.raises(ValueError, match=r"^threads: expected 0 to 1024"):
        uvtk.texgen(mesh, threads=5000)
    one, two = uvtk.texgen(mesh, mode="sphere_map", threads=1), uvtk.texgen(mesh, mode="sphere_map", threads=2)
    np.testing.assert_array_equal(one.uv, two.uv)
    assert one.verdict == two.verdict
    # the options object and the keywords are one path
    options = uvtk.TexgenOptions.parse("--mode sphere_map --threads 2")
    np.testing.assert_array_equal(uvtk.texgen(mesh, options).uv, one.uv)
    # the program's --threads: the same bytes
    for threads in ("1", "2"):
        run = cli("texgen", mesh_file, "-o", tmp_path / f"t{threads}.obj", "--mode", "sphere_map", "--threads", threads)
        assert run.returncode == 0, run.stderr
    assert (tmp_path / "t1.obj").read_bytes() == (tmp_path / "t2.obj").read_bytes()


def test_file_uvs_are_the_meshs_own():
    positions, triangles = unit_square()
    uv = positions[:, :2][triangles] * 0.5
    m = uvtk.file_uvs(uvtk.Mesh(positions, triangles, uv=uv))
    assert m.source == "file"
    np.testing.assert_array_equal(m.uv, uv)
    with pytest.raises(ValueError):
        uvtk.file_uvs(uvtk.Mesh(positions, triangles))



def test_a_written_map_read_back_keeps_its_pole_and_turned_away_faces(tmp_path):
    # The writer lists them as it lists invalid faces; read back, report judges the file as map did
    # (before, the plane's back faces read as flipped and failed the file).
    mesh = uvtk.Mesh(*uv_sphere())
    for projector, flag in (("sphere", uvtk.FACE_POLE), ("plane", uvtk.FACE_TURNED_AWAY)):
        m = uvtk.map(mesh, projector=projector)
        assert (m.face_flags & flag).any(), projector
        for ext in ("obj", "ply", "glb"):
            path = tmp_path / f"m.{ext}"
            uvtk.write_mesh(path, m)
            read = uvtk.read_mesh(path)
            again = uvtk.file_uvs(read)
            listed = uvtk.FACE_POLE | uvtk.FACE_TURNED_AWAY
            np.testing.assert_array_equal(again.face_flags & listed, m.face_flags & listed)
            rep = uvtk.report(read, again)
            assert rep["verdict"] == m.verdict["status"], (projector, ext)
            assert [r["code"] for r in rep["reasons"]] == [r["rule"] for r in m.verdict["reasons"]], (projector, ext)
            np.testing.assert_array_equal(uvtk.file_uvs(pickle.loads(pickle.dumps(read))).face_flags, again.face_flags)


# ---- writing ----


def test_write_mesh_writes_the_mesh_or_the_mapping(tmp_path):
    positions, triangles = unit_square()
    uv = positions[:, :2][triangles]
    uvtk.write_mesh(tmp_path / "own.obj", uvtk.Mesh(positions, triangles, uv=uv))
    np.testing.assert_array_equal(uvtk.read_mesh(tmp_path / "own.obj").uv, uv)
    mesh = uvtk.Mesh(*uv_sphere())
    m = uvtk.map(mesh, projector="cube")
    uvtk.write_mesh(tmp_path / "w.obj", mesh, m, write_w=True)
    _, _, corner = read_obj(tmp_path / "w.obj")
    np.testing.assert_array_equal(corner[..., :2], m.uv)
    np.testing.assert_array_equal(corner[..., 2], m.w)
    uvtk.write_mesh(tmp_path / "f.obj", m, uv_digits="float")  # the mapping alone
    np.testing.assert_allclose(read_obj(tmp_path / "f.obj")[2], m.uv, rtol=1e-7, atol=1e-7)
    with pytest.raises(ValueError, match="uvDigits"):
        uvtk.write_mesh(tmp_path / "x.obj", mesh, m, uv_digits="half")


def test_the_mesh_given_with_a_mapping_must_be_its_own(tmp_path):
    mesh = uvtk.Mesh(*uv_sphere())
    cut = uvtk.map(mesh, seam="cut")
    uvtk.write_mesh(tmp_path / "a.obj", mesh, cut)  # the input, although the cut mesh has more faces
    uvtk.write_mesh(tmp_path / "b.obj", cut.mesh, cut)
    uvtk.write_mesh(tmp_path / "c.obj", uvtk.Mesh(mesh.positions, mesh.triangles), uvtk.map(mesh))
    with pytest.raises(ValueError, match="pass the mesh the mapping was made from"):
        uvtk.write_mesh(tmp_path / "d.obj", uvtk.Mesh(*octahedron()), cut)


def test_unwritable_path_is_an_output_error(tmp_path):
    mesh = uvtk.Mesh(*octahedron())
    path = tmp_path / "no" / "such" / "folder.obj"
    with pytest.raises(uvtk.OutputError, match="cannot write") as error:
        uvtk.write_mesh(path, mesh, uvtk.map(mesh))
    assert isinstance(error.value, OSError) and str(path) in str(error.value)
    assert not path.exists()


# ---- single points ----


def test_eval_sphere_follows_the_convention():
    points = np.array([[1, 0, 0], [0, 2, 0], [-3, 0, 0], [0, -1, 0], [1, 1, math.sqrt(2)], [0, 0, 2], [0, 0, 0]])
    r = uvtk.eval(points, projector="sphere")
    np.testing.assert_allclose(r.u[:5], [0, 0.25, 0.5, 0.75, 0.125], rtol=0, atol=1e-15)
    np.testing.assert_allclose(r.v[:5], [0.5, 0.5, 0.5, 0.5, 0.75], rtol=0, atol=1e-15)
    assert r.status.dtype == np.uint8
    # +x is on the seam (u = 0 and u = 1 are the same point there)
    assert r.status.tolist() == [uvtk.POINT_ON_SEAM] + [uvtk.POINT_OK] * 4 + [uvtk.POINT_POLE, uvtk.POINT_INVALID]
    assert r.v[5] == 1.0 and (r.u[6], r.v[6]) == (0.0, 0.0)
    assert r.reason[1:5] == [""] * 4 and r.reason[0] and r.reason[5] and r.reason[6]
    assert (r.w == 0).all() and (r.q == 1).all()
    assert r["u"] is r.u and set(dict(r)) == {"u", "v", "w", "q", "status", "reason"}
    assert uvtk.POINT_STATUS_NAMES[r.status[5]] == "pole"


def test_eval_triplanar_gives_the_three_projections_and_their_weights():
    r = uvtk.eval([[1, 2, 3], [1, 2, 3]], normals=[[1, 2, 3], [0, 0, -5]], projector="triplanar", tile=2)
    np.testing.assert_array_equal(r.triplanar_uv, [[[6, 4], [2, 6], [2, 4]]] * 2)  # Unity: zy, xz, xy times 2
    np.testing.assert_allclose(r.triplanar_weights, [[1 / 6, 2 / 6, 3 / 6], [0, 0, 1]], rtol=0, atol=1e-15)
    assert r.u.tolist() == [2, 2] and r.v.tolist() == [4, 4]  # the dominant z projection
    assert set(dict(r)) == {"u", "v", "w", "q", "status", "reason", "triplanar_uv", "triplanar_weights"}
    np.testing.assert_array_equal(dict(r)["triplanar_weights"], r.triplanar_weights)
    sphere = uvtk.eval([1, 2, 3], projector="sphere")
    assert sphere.triplanar_weights is None
    assert "triplanar_uv" not in dict(sphere)


def test_eval_cylinder_with_caps_reads_the_normals():
    points = np.array([[0, 2, 0.5], [-1, 0, 0.25], [0.5, 0, 1]])
    side = uvtk.eval(points[:2], projector="cylinder")
    np.testing.assert_allclose(np.stack([side.u, side.v], 1), [[0.25, 0.5], [0.5, 0.25]], rtol=0, atol=1e-15)
    # the top cap maps (x, y) to ((x + 1) / 2, (y + 1) / 2) stacked, to ((x + 1) / 4, 1/2 + (y + 1) / 4)
    # beside (the default: its square is [0, 1/2] x [1/2, 1]); one normal serves every point
    top = uvtk.eval(points[2], normals=[0, 0, 1], projector="cylinder", caps=True, cap_layout="stacked")
    assert top.u.shape == () and (float(top.u), float(top.v)) == (0.75, 0.5)
    top = uvtk.eval(points[2], normals=[0, 0, 1], projector="cylinder", caps=True)
    assert (float(top.u), float(top.v)) == (0.375, 0.75)
    per_point = uvtk.eval(points, normals=np.tile([0, 0, 1.0], (3, 1)), projector="cylinder", caps=True)
    assert (per_point.u[2], per_point.v[2]) == (0.375, 0.75)
    # beside, a point whose normal is not a cap's lies on the side band, v / 2
    side = uvtk.eval(points[:2], normals=[[0, 1, 0], [-1, 0, 0]], projector="cylinder", caps=True)
    np.testing.assert_allclose(np.stack([side.u, side.v], 1), [[0.25, 0.25], [0.5, 0.125]], rtol=0, atol=1e-15)


def test_eval_keeps_the_points_shape():
    grid = np.random.default_rng(1).normal(size=(4, 5, 3))
    r = uvtk.eval(grid, projector="cube")
    assert r.u.shape == r.status.shape == (4, 5) and len(r.reason) == 20
    flat = uvtk.eval(grid.reshape(-1, 3), projector="cube")
    np.testing.assert_array_equal(r.u.reshape(-1), flat.u)


def test_eval_equals_map_before_seam_and_pole_repair():
    mesh = uvtk.Mesh(*uv_sphere())
    m = uvtk.map(mesh, projector="sphere", fit="bbox", seam="none", pole="none")
    r = uvtk.eval(mesh.positions, mesh=mesh, projector="sphere", fit="bbox")
    corners = mesh.triangles
    ok = m.state == uvtk.OK
    np.testing.assert_array_equal(m.uv[..., 0][ok], r.u[corners][ok])
    np.testing.assert_array_equal(m.uv[..., 1][ok], r.v[corners][ok])
    assert (r.status[corners][~ok] == uvtk.POINT_POLE).all()


def test_eval_equals_the_program(cli):
    points = [(0.3, -0.7, 0.2), (-1.5, 0.25, 2.0)]
    args = [f"--point={x!r},{y!r},{z!r}" for x, y, z in points]
    run = cli("eval", *args, "--projector", "cylinder", "--uv-rotate", "17")
    assert run.returncode == 0, run.stderr
    rows = [line.split(",") for line in run.stdout.splitlines()]
    header = rows[0]
    r = uvtk.eval(np.array(points), projector="cylinder", uv_rotate=17)
    assert len(rows) == 1 + len(points)
    for i, row in enumerate(rows[1:]):
        assert float(row[header.index("u")]) == r.u[i] and float(row[header.index("v")]) == r.v[i]


def test_eval_bad_options_are_value_errors():
    with pytest.raises(ValueError, match="omap"):
        uvtk.eval([[1, 0, 0]], projector="sphere", omap="reflection")
    with pytest.raises(ValueError, match=r"\(\.\.\., 3\)"):
        uvtk.eval([[1, 0]])
    with pytest.raises(ValueError, match="normals"):
        uvtk.eval([[1, 0, 0], [0, 1, 0]], normals=[[0, 0, 1]] * 3)



def test_eval_keywords_are_typed_as_maps_are():
    side, up = [[0.6, 0.8, 0.95]], [0, 0, 1]  # a point on a cap face of the cylinder
    off = uvtk.eval(side, normals=up, projector="cylinder").u[0]
    on = uvtk.eval(side, normals=up, projector="cylinder", caps=True).u[0]
    assert off != on
    assert uvtk.eval(side, normals=up, projector="cylinder", caps=False).u[0] == off
    assert uvtk.eval(side, normals=up, projector="cylinder", caps=0).u[0] == off  # 0 is False, not a flag given
    with pytest.raises(TypeError, match=r"caps: expected True or False, got 'no'"):
        uvtk.eval(side, projector="cylinder", caps="no")
    with pytest.raises(ValueError, match=r"projecter: not a parameter here; did you mean projector\?"):
        uvtk.eval(side, projecter="cylinder")
    with pytest.raises(ValueError, match="threads: expected 0 to 1024"):
        uvtk.eval(side, threads=-1)
    # threads spread the points; the numbers are the same
    points = np.random.default_rng(7).normal(size=(20000, 3))
    one, two = uvtk.eval(points, projector="sphere", threads=1), uvtk.eval(points, projector="sphere", threads=2)
    assert np.array_equal(one.u, two.u) and np.array_equal(one.v, two.v) and np.array_equal(one.status, two.status)


def test_eval_has_a_signature_of_every_keyword_it_takes():
    import inspect
    parameters = inspect.signature(uvtk.eval).parameters
    assert list(parameters)[:3] == ["points", "normals", "mesh"]
    for keyword in ("projector", "omap", "caps", "cap_angle", "texgen", "s", "texmatrix", "model", "threads"):
        assert parameters[keyword].kind is inspect.Parameter.KEYWORD_ONLY, keyword
    assert parameters["fit"].default == "none"  # points have no mesh to fit to unless one is given
    assert "object_linear" in str(parameters["texgen"].annotation)
    assert "cap_angle: float = 45.0" in uvtk.eval.__doc__
    # every keyword of the signature is one eval takes (a name it does not read would be refused)
    names = {o["keyword"] for o in uvtk.EVAL_OPTIONS}
    assert names == {n.replace("-", "_") for n in uvtk._uvtk._eval_parameter_names()} | {"threads"}


def test_reading_and_writing_have_signatures_and_threads(tmp_path, meshes_dir):
    import inspect
    assert list(inspect.signature(uvtk.read_mesh).parameters) == ["path", "with_warnings", "threads"]
    assert list(inspect.signature(uvtk.write_mesh).parameters) == [
        "path", "mesh", "m", "uv_digits", "write_w", "ascii", "header", "threads"]
    one, two = uvtk.read_mesh(meshes_dir / "torus.obj", threads=1), uvtk.read_mesh(meshes_dir / "torus.obj", threads=2)
    np.testing.assert_array_equal(one.positions, two.positions)
    np.testing.assert_array_equal(one.triangles, two.triangles)
    with pytest.raises(ValueError, match="threads: expected 0 to 1024, got 2000"):
        uvtk.read_mesh(meshes_dir / "torus.obj", threads=2000)
    m = uvtk.map(one, projector="sphere")
    uvtk.write_mesh(tmp_path / "a.obj", one, m, threads=1)
    uvtk.write_mesh(tmp_path / "b.obj", one, m, threads=2)
    assert (tmp_path / "a.obj").read_bytes() == (tmp_path / "b.obj").read_bytes()


# ---- report, render, compare ----

def test_report_and_compare_keywords_are_typed(tmp_path):
    mesh = uvtk.Mesh(*uv_sphere())
    m = uvtk.map(mesh, projector="sphere")
    # size as (W, H), "WxH" or N; views as a list or a comma list: the same page
    uvtk.report(mesh, m, html=tmp_path / "a.html", size=(48, 32), views=["checker", "seams"])
    uvtk.report(mesh, m, html=tmp_path / "b.html", size="48x32", views="checker,seams")
    assert (tmp_path / "a.html").read_text().count("<img") == (tmp_path / "b.html").read_text().count("<img") > 0
    with pytest.raises(TypeError, match=r"^threads: expected an integer, got '2'$"):
        uvtk.report(mesh, m, threads="2")
    with pytest.raises(ValueError, match=r"^size: expected W, H with 1 <= W, H <= 16384$"):
        uvtk.report(mesh, m, size=(0, 10))
    with pytest.raises(ValueError, match=r"^top: expected at least 1, got 0$"):
        uvtk.compare(mesh, top=0, no_baselines=True)
    with pytest.raises(TypeError, match=r"^no_baselines: expected True or False, got 'yes'$"):
        uvtk.compare(mesh, no_baselines="yes")
    with pytest.raises(ValueError, match=r"^by: 'angel' is not one of: .*did you mean 'angle'\?$"):
        uvtk.compare(mesh, by="angel", no_baselines=True)
    ranked = uvtk.compare(mesh, by="angle", top=2, no_baselines=1)  # 1 is True
    assert ranked["json"]["rank_by"] == "angle"
    assert not any(row["name"] in ("lscm", "arap") for row in ranked["json"]["ranking"])


def test_report_is_the_programs_json(tmp_path, cli):
    path = write_obj(tmp_path / "s.obj", *uv_sphere())
    mesh = uvtk.read_mesh(path)
    m = uvtk.map(mesh, projector="sphere", fail_on=["stretch_p99=1.01"])
    rep = uvtk.report(mesh, m, json=tmp_path / "py.json")
    assert rep["verdict"] == m.verdict["status"] == "fail"
    assert rep["reasons"][0]["code"] == m.verdict["reasons"][0]["rule"] == "stretch_p99"
    assert json.loads((tmp_path / "py.json").read_text()) == rep
    run = cli("report", path, "--projector", "sphere", "--fail-on", "stretch_p99=1.01", "--json", tmp_path / "cli.json")
    assert run.returncode != 0 or "fail" in run.stdout + run.stderr
    theirs = json.loads((tmp_path / "cli.json").read_text())
    # the program also records times, and the input file's path and checksum
    theirs.pop("milliseconds")
    assert {k: theirs["input"][k] for k in rep["input"]} == rep["input"]
    assert {k: v for k, v in rep.items() if k != "input"} == {k: v for k, v in theirs.items() if k != "input"}
    with pytest.raises(ValueError, match="pass the mesh the mapping was made from"):
        uvtk.report(uvtk.Mesh(*octahedron()), m)
    with pytest.raises(ValueError, match="^size: expected WxH"):
        uvtk.report(mesh, m, size="big")
    # The page of a mesh made in memory (no path): it raised nlohmann's out_of_range 'path' before.
    uvtk.report(mesh, m, html=tmp_path / "py.html")
    page = (tmp_path / "py.html").read_text()
    assert page.startswith("<!DOCTYPE html>") and "uvtk report: a mesh in memory" in page


def read_png(path):
    """An 8-bit, non-interlaced PNG (what `uvtk render` writes) as (H, W, C) uint8."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    at, chunks, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            chunks += body
        at += 12 + length
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and interlace == 0
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
    raw = zlib.decompress(chunks)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = previous[i], previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        previous = line
    return np.frombuffer(b"".join(rows), dtype=np.uint8).reshape(height, width, channels)


@pytest.mark.parametrize("view", ["checker", "stretch", "seams,layout"])
def test_render_is_the_programs_png(view, tmp_path, cli):
    path = write_obj(tmp_path / "s.obj", *uv_sphere())
    run = cli("render", path, "--projector", "cylinder", "--view", view, "--size", "64x48", "-o", tmp_path / "r.png")
    assert run.returncode == 0, run.stderr
    mesh = uvtk.read_mesh(path)
    img = uvtk.render(mesh, uvtk.map(mesh, projector="cylinder"), view=view, size=(64, 48))
    np.testing.assert_array_equal(img, read_png(tmp_path / "r.png"))


def test_render_takes_a_gpus_quad_derivatives_and_the_seam_fixes(tmp_path, cli):
    path = write_obj(tmp_path / "s.obj", *uv_sphere())
    scene = dict(uv="per-pixel", view_dir=(1, 0.3, 0.2), texture="checker:64:8", filter="linear_mipmap_linear",
                 size=(64, 48))
    run = cli("render", path, "--projector", "sphere", "--uv", "per-pixel", "--view-dir", "1,0.3,0.2", "--texture",
              "checker:64:8", "--filter", "linear_mipmap_linear", "--size", "64x48", "--derivatives", "quad-coarse",
              "-o", tmp_path / "r.png")
    assert run.returncode == 0, run.stderr
    mesh = uvtk.read_mesh(path)
    m = uvtk.map(mesh, projector="sphere")
    gpu = uvtk.render(mesh, m, derivatives="quad-coarse", **scene)
    np.testing.assert_array_equal(gpu, read_png(tmp_path / "r.png"))
    exact = uvtk.render(mesh, m, **scene)
    assert (gpu != exact).any()  # the quad's lambda is not the exact one
    np.testing.assert_array_equal(uvtk.render(mesh, m, derivatives="quad-fine", seam_fix="grad", **scene), exact)
    with pytest.raises(ValueError):
        uvtk.render(mesh, m, derivatives="quad", **scene)


def test_render_takes_the_programs_texture_and_lighting_options(tmp_path, cli):
    # The picture's own options reach it: the texture's environment and two-sided lighting, as the
    # program draws them; view="" is the textured picture; an option with no place in memory is refused.
    path = write_obj(tmp_path / "s.obj", *uv_sphere())
    options = ["--env", "modulate", "--two-sided", "--cull", "front", "--size", "64x48"]
    run = cli("render", path, "--projector", "cylinder", *options, "-o", tmp_path / "r.png")
    assert run.returncode == 0, run.stderr
    mesh = uvtk.read_mesh(path)
    m = uvtk.map(mesh, projector="cylinder")
    lit = uvtk.render(mesh, m, view="", env="modulate", two_sided=True, cull="front", size=(64, 48))
    np.testing.assert_array_equal(lit, read_png(tmp_path / "r.png"))
    one_sided = uvtk.render(mesh, m, view="", env="modulate", cull="front", size=(64, 48))
    assert (lit != one_sided).any()  # the back faces, lit one-sided, keep only the ambient term
    with pytest.raises(ValueError, match="^aov: not a parameter here"):
        uvtk.render(mesh, m, aov="uv")


def test_render_gives_height_width_channels():
    mesh = uvtk.Mesh(*uv_sphere())
    m = uvtk.map(mesh)
    img = uvtk.render(mesh, m, view="checker", size=(64, 48))
    assert img.dtype == np.uint8 and img.shape[:2] == (48, 64) and img.shape[2] in (3, 4)
    assert img.base is not None and img.min() < img.max()
    pixels = uvtk.render(mesh, m, view="checker", size=(64, 48), dtype="float32")
    assert pixels.dtype == np.float32 and pixels.shape == img.shape
    np.testing.assert_array_equal(img, np.round(np.clip(np.nan_to_num(pixels), 0, 1) * 255).astype(np.uint8))
    with pytest.raises(ValueError):
        uvtk.render(mesh, m, view="nonsense")


def test_compare_ranks_the_projectors():
    result = uvtk.compare(uvtk.Mesh(*uv_sphere()), no_baselines=True, top=3)
    assert set(result) == {"json", "table", "best"}
    assert result["best"] and result["best"] in result["table"] and isinstance(result["json"], dict)


def test_keywords_are_typed_as_python_users_expect():
    # Each of these behaved otherwise when the keywords became a command line: caps=0 turned the
    # caps on, fit=None was the default fit, threads was refused, and the library took
    # overlap_resolution from 16 to 8192 where the command line takes 1 to 16384.
    mesh = uvtk.Mesh(*torus())
    off = uvtk.map(mesh, projector="cylinder")
    on = uvtk.map(mesh, projector="cylinder", caps=True)
    assert not np.array_equal(on.uv, off.uv)
    np.testing.assert_array_equal(uvtk.map(mesh, projector="cylinder", caps=0).uv, off.uv)
    np.testing.assert_array_equal(uvtk.map(mesh, projector="cylinder", caps=1).uv, on.uv)
    np.testing.assert_array_equal(uvtk.map(mesh, projector="cylinder", caps=np.bool_(True)).uv, on.uv)
    for wrong in ("no", "false", 2, 0.0):
        with pytest.raises(TypeError, match="^caps: expected True or False, got "):
            uvtk.map(mesh, projector="cylinder", caps=wrong)
    with pytest.raises(TypeError, match="^fit: expected one of 'none', 'bbox', 'center', 'pca', 'obb', got None"):
        uvtk.map(mesh, fit=None)
    np.testing.assert_array_equal(uvtk.map(mesh, threads=1).uv, uvtk.map(mesh).uv)
    coarse = uvtk.map(mesh, overlap_resolution=8)
    assert coarse.summary["judgement"]["overlap"]["resolution"] == 8
    with pytest.raises(ValueError, match="^overlap_resolution: expected 0 to 16384, got 16385"):
        uvtk.map(mesh, overlap_resolution=16385)
    with pytest.raises(ValueError, match="^seam_place: only the wrapping projectors"):
        uvtk.map(mesh, projector="plane", seam_place=90)
    np.testing.assert_array_equal(uvtk.map(mesh, texture_size=512).summary["judgement"]["texel_density"]["texture_size"],
                                  [512, 512])


def test_the_direction_maps_work_on_every_face():
    # Octahedral: p = d / |d|_1, the lower half folded out; shrink wrap: one singular point at -z.
    r = uvtk.eval([[1, 2, -1], [0, 0, 1], [0, 0, -1]], projector="octahedral")
    assert r.u.tolist() == [0.75, 0.5, 1.0] and r.v.tolist() == [0.875, 0.5, 1.0]
    assert r.status.tolist() == [uvtk.POINT_OK] * 3
    s = uvtk.eval([[0, 1, -1], [0, 0, 3], [0, 0, -1]], projector="shrink-wrap")
    np.testing.assert_allclose(s.u, [0.5, 0.5, 1.0], rtol=0, atol=1e-15)
    np.testing.assert_allclose(s.v, [0.875, 0.5, 0.5], rtol=0, atol=1e-15)
    assert s.status.tolist() == [uvtk.POINT_OK, uvtk.POINT_OK, uvtk.POINT_POLE]
    # map: the octahedron's own vertices, and the south pole's faces flagged for the shrink wrap
    mesh = uvtk.Mesh(*octahedron())
    m = uvtk.map(mesh, projector="octahedral", fit="none")
    assert m.uv[0].tolist() == [[1.0, 0.5], [0.5, 1.0], [0.5, 0.5]]  # +x, +y, +z
    assert m.uv[4].tolist() == [[0.5, 1.0], [1.0, 0.5], [1.0, 1.0]]  # +y, +x, -z folded to the corner
    w = uvtk.map(mesh, projector="shrink-wrap", fit="none")
    assert w.summary["pole_faces"] == 4 and w.summary["pole_vertex_list"] == [5]
    with pytest.raises(ValueError, match="^seam_place: only the wrapping projectors"):
        uvtk.map(mesh, projector="octahedral", seam_place=90)
