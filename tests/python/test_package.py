# The package around the extension (issue 49): signatures and stubs from the one option table,
# pickling, the ecosystem's layouts, meshio, batches on Dask, and report(html=).
import inspect
import os
import pathlib
import pickle
import pydoc
import re
import subprocess
import sys
import typing

import numpy as np
import pytest

import uvtk

PACKAGE = pathlib.Path(uvtk.__file__).resolve().parent


def quad_with_seam(shared_uv=False):
    """Two triangles over the unit square, v2's corners given different UVs (a seam through v2);
    with shared_uv, v3's corner has v1's UV (two vertices, one texture vertex)."""
    positions = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
    triangles = np.array([[0, 1, 2], [0, 2, 3]])
    uv = np.array([[[0, 0], [1, 0], [1, 1]],
                   [[0, 0], [0.5, 1], [1, 0] if shared_uv else [0, 1]]], dtype=float)
    return positions, triangles, uv


def torus(n=24, m=12):
    u, v = np.meshgrid(np.arange(n) * 2 * np.pi / n, np.arange(m) * 2 * np.pi / m, indexing="ij")
    positions = np.stack([(2 + np.cos(v)) * np.cos(u), (2 + np.cos(v)) * np.sin(u), np.sin(v)], -1).reshape(-1, 3)
    faces = []
    for i in range(n):
        for j in range(m):
            a, b, c, d = i * m + j, ((i + 1) % n) * m + j, ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
            faces += [[a, b, c], [a, c, d]]
    return positions, np.array(faces)


# ---- signatures and stubs ----

# `uvtk map --help`'s options that are not map's keywords: the program's inputs and outputs.
MAP_OUTPUT_OPTIONS = {"help", "list", "output", "json", "jobs", "quiet", "write-w", "ascii", "format", "uv-digits"}


def help_options(text):
    """{name: the rest of its entry} of a CLI11 --help page (type, default and sentence, with the
    next line where the sentence is there)."""
    found = {}
    lines = text.splitlines() + [""]
    for i, line in enumerate(lines[:-1]):
        match = re.match(r"^  (?:-\w,)?--([\w-]+)(.*)$", line)
        if match:
            continued = lines[i + 1].startswith(" " * 20)
            found[match.group(1)] = match.group(2) + (" " + lines[i + 1].strip() if continued else "")
    return found


def test_map_signature_is_the_option_table(cli):
    signature = inspect.signature(uvtk.map)
    parameters = signature.parameters
    assert list(parameters)[:2] == ["mesh", "options"]
    assert signature.return_annotation is uvtk.Mapping
    keywords = {name: p for name, p in parameters.items() if p.kind is inspect.Parameter.KEYWORD_ONLY}
    # every option of `uvtk map` but its inputs and outputs, and no other
    shown = help_options(cli("map", "--help").stdout)
    assert set(keywords) == {name.replace("-", "_") for name in shown} - {
        name.replace("-", "_") for name in MAP_OUTPUT_OPTIONS}
    for option in uvtk.MAP_OPTIONS:
        assert option["help"] and option["help"] in shown[option["name"]], option["name"]
        assert f"={option['default']} " in shown[option["name"]] or not option["default"], option["name"]
    # types, defaults and choices as --help gives them
    assert keywords["cap_angle"].annotation is float and keywords["cap_angle"].default == 45.0
    assert keywords["caps"].annotation is bool and keywords["caps"].default is False
    assert keywords["threads"].annotation is int and keywords["threads"].default == 0
    assert keywords["overlap_resolution"].default == 0
    assert keywords["projector"].default == "sphere"
    # every surface of the one list, in its order: the first seven, any since, the charts last
    surfaces = typing.get_args(keywords["projector"].annotation)
    assert surfaces[:7] == ("plane", "two-plane", "cylinder", "sphere", "cube", "camera", "triplanar")
    assert surfaces[-3:] == ("atlas", "lscm", "arap") and len(set(surfaces)) == len(surfaces)
    assert typing.get_args(keywords["seam"].annotation) == ("none", "shift", "cut")
    assert keywords["axis_dir"].default == (0.0, 0.0, 1.0)
    assert keywords["center"].default is None and type(None) in typing.get_args(keywords["center"].annotation)
    assert keywords["fail_on"].default == ()
    assert keywords["texture_size"].default == 1024
    # help() shows each keyword with its type, default and meaning
    page = pydoc.render_doc(uvtk.map, renderer=pydoc.plaintext)
    assert "cap_angle: float = 45.0" in page
    assert "cylinder: degrees between a cap face's normal and the axis" in page
    assert "(one of: none, shift, cut)" in page


def test_texgen_signature_is_the_option_table(cli):
    keywords = {n: p for n, p in inspect.signature(uvtk.texgen).parameters.items()
                if p.kind is inspect.Parameter.KEYWORD_ONLY}
    shown = help_options(cli("texgen", "--help").stdout)
    assert set(keywords) == {n.replace("-", "_") for n in shown} - {"help", "output", "ascii", "json", "quiet"}
    assert keywords["no_normalize"].annotation is bool and keywords["no_normalize"].default is False
    assert keywords["eye"].default == (0.0, 0.0, 0.0) and keywords["center"].default == (0.0, 0.0, -1.0)


@pytest.mark.parametrize("command", ["report", "render", "compare"])
def test_report_render_and_compare_have_signatures_from_their_tables(cli, command):
    function = getattr(uvtk, command)
    table = getattr(uvtk, command.upper() + "_OPTIONS")
    keywords = {n: p for n, p in inspect.signature(function).parameters.items()
                if p.kind is inspect.Parameter.KEYWORD_ONLY}
    assert list(keywords) == [o["keyword"] for o in table] and "threads" in keywords
    shown = help_options(cli(command, "--help").stdout)
    for option in table:
        assert option["help"] and option["help"] in shown[option["name"]], (command, option["name"])
    page = pydoc.render_doc(function, renderer=pydoc.plaintext)
    assert "threads: int = 0" in page
    if command == "render":
        assert typing.get_args(keywords["cull"].annotation) == ("back", "front", "none")
        assert keywords["near"].default is None and keywords["fovy"].default == 45.0
        assert inspect.signature(function).return_annotation is np.ndarray


def test_each_default_given_explicitly_is_the_default():
    mesh = uvtk.Mesh(*torus())
    plain = uvtk.map(mesh)
    defaults = {name: p.default for name, p in inspect.signature(uvtk.map).parameters.items()
                if p.kind is inspect.Parameter.KEYWORD_ONLY}
    assert defaults["fit"] == "bbox"  # --help's (triplanar's is none)
    applied = 0
    for name, default in defaults.items():
        try:
            given = uvtk.map(mesh, **{name: default})
        except ValueError as error:  # a parameter of another projector, refused even at its default
            assert re.search(r"goes with|only", str(error)), (name, error)
            continue
        # the same UVs (axis_dir and ref_dir given go through the explicit frame's arithmetic: 1 ulp)
        np.testing.assert_allclose(given.uv, plain.uv, rtol=0, atol=1e-15, err_msg=name)
        assert given.verdict["status"] == plain.verdict["status"], name
        applied += 1
    assert applied >= 20


def test_threads_works_where_the_command_takes_it():
    mesh = uvtk.Mesh(*torus())
    m = uvtk.map(mesh, threads=1)
    np.testing.assert_array_equal(m.uv, uvtk.map(mesh, threads=2).uv)
    assert uvtk.report(mesh, m, threads=1)["verdict"] == uvtk.report(mesh, m, threads=2)["verdict"]
    np.testing.assert_array_equal(uvtk.render(mesh, m, size=(32, 32), threads=1),
                                  uvtk.render(mesh, m, size=(32, 32), threads=2))
    assert uvtk.compare(mesh, no_baselines=True, top=2, threads=1)["best"]
    with pytest.raises(ValueError, match="threads"):
        uvtk.map(mesh, threads=-1)


def test_the_stubs_are_generated_from_the_built_module():
    from uvtk import _stubgen

    stub = (PACKAGE / "__init__.pyi").read_text(encoding="utf-8")
    assert stub == _stubgen.stub_text()
    assert (PACKAGE / "py.typed").exists()
    assert "    cap_angle: float = 45.0," in stub
    assert "    projector: Literal['plane', 'two-plane', 'cylinder', 'sphere'," in stub


SAMPLE = '''
import pathlib
from typing import Any

import numpy as np
import numpy.typing as npt
import uvtk

mesh = uvtk.Mesh(np.zeros((3, 3)), np.array([[0, 1, 2]]))
m: uvtk.Mapping = uvtk.map(mesh, projector="cylinder", caps=True, cap_angle=30, center=(0, 0, 1),
                           seam_place="auto", fail_on=["overlap=0.1"], texture_size=(2048, 1024), threads=1)
uv: npt.NDArray[np.float64] = m.uv
status: str = m.verdict["status"]
vmapping, indices, uvs = m.split()
V, F, TC, FTC = m.to_arrays()
again: uvtk.Mesh = uvtk.Mesh.from_arrays(V, F, TC, FTC)
t = uvtk.texgen(mesh, s="object_linear:1,0,0,0", no_normalize=True)
rep: dict[str, object] = uvtk.report(mesh, m, html=pathlib.Path("r.html"), size=(64, 64), threads=1)
img: npt.NDArray[Any] = uvtk.render(mesh, m, view="checker", size=(32, 32), cull="none", near=0.1, threads=2)
ranked = uvtk.compare(mesh, by="angle", top=3, no_baselines=True, threads=1)
at = uvtk.eval(np.zeros((4, 3)), normals=(0, 0, 1), projector="cylinder", caps=True, eye=(0, 0, 5), threads=2)
gl = uvtk.eval([[0.0, 1.0, 0.0]], texgen="sphere_map", texmatrix=[1.0] * 16)
u: npt.NDArray[np.float64] = at.u
'''

WRONG = '''
import numpy as np
import uvtk

mesh = uvtk.Mesh(np.zeros((3, 3)), np.array([[0, 1, 2]]))
uvtk.map(mesh, projector="cylindre")
uvtk.map(mesh, caps="yes")
uvtk.map(mesh, cap_angel=30)
n: int = uvtk.map(mesh).uv
uvtk.render(mesh, uvtk.map(mesh), cull="sideways")
uvtk.report(mesh, uvtk.map(mesh), threads="2")
uvtk.eval([[0.0, 0.0, 1.0]], caps="yes")
uvtk.eval([[0.0, 0.0, 1.0]], texgen="cube_map")
'''


def test_mypy_checks_scripts_against_the_stubs(tmp_path):
    (tmp_path / "good.py").write_text(SAMPLE)
    (tmp_path / "bad.py").write_text(WRONG)
    env = dict(os.environ)
    parent = str(PACKAGE.parent)
    # Installed (site-packages), mypy finds the package through the interpreter; from the build
    # tree, through MYPYPATH (which must not name a site-packages).
    if os.path.basename(parent) in ("site-packages", "dist-packages"):
        env.pop("MYPYPATH", None)
    else:
        env["MYPYPATH"] = parent
    run = subprocess.run(["/usr/bin/mypy", "--python-executable", sys.executable, "--cache-dir", str(tmp_path / "cache"),
                          "--strict", "good.py", "bad.py"], capture_output=True, text=True, env=env, cwd=tmp_path)
    out = run.stdout
    assert run.returncode == 1, out + run.stderr
    assert "good.py" not in out and not re.search(r"__init__.pyi:\d+: error", out), out  # sample and stubs pass --strict
    assert 'bad.py:6: error: Argument "projector" to "map" has incompatible type' in out, out
    assert 'bad.py:7: error: Argument "caps" to "map" has incompatible type' in out, out
    assert 'bad.py:8: error: Unexpected keyword argument "cap_angel" for "map"' in out, out
    assert "bad.py:9: error: Incompatible types in assignment" in out, out
    assert 'bad.py:10: error: Argument "cull" to "render" has incompatible type' in out, out
    assert 'bad.py:11: error: Argument "threads" to "report" has incompatible type' in out, out
    assert 'bad.py:12: error: Argument "caps" to "eval" has incompatible type' in out, out
    assert 'bad.py:13: error: Argument "texgen" to "eval" has incompatible type' in out, out


def test_unknown_keywords_and_choices_are_errors_naming_them():
    mesh = uvtk.Mesh(*torus())
    with pytest.raises(ValueError, match="cap_angel: not a parameter here; did you mean cap_angle"):
        uvtk.map(mesh, cap_angel=30)
    with pytest.raises(ValueError, match="cylindre"):
        uvtk.map(mesh, projector="cylindre")
    m = uvtk.map(mesh)
    with pytest.raises(ValueError, match=r"^threadz: not a parameter here; did you mean threads\?$"):
        uvtk.report(mesh, m, threadz=1)
    with pytest.raises(ValueError, match=r"^tpo: not a parameter here; did you mean top\?$"):
        uvtk.compare(mesh, tpo=3)
    with pytest.raises(ValueError, match=r"^mdoe: not a parameter here; did you mean mode\?$"):
        uvtk.texgen(mesh, mdoe="sphere_map")
    with pytest.raises(ValueError, match=r"^cull: 'sideways' is not one of: back, front, none$"):
        uvtk.render(mesh, m, cull="sideways")
    with pytest.raises(ValueError, match=r"^wrpa: not a parameter here; did you mean wrap\?$"):
        uvtk.render(mesh, m, wrpa="repeat")
    with pytest.raises(TypeError, match=r"^spp: expected an integer"):
        uvtk.render(mesh, m, spp="4")


def test_without_numpy_import_says_so(tmp_path):
    # numpy is a dependency: under an interpreter without it, `import uvtk` fails at once (it
    # imported, and m.uv raised later)
    (tmp_path / "numpy").mkdir()
    (tmp_path / "numpy" / "__init__.py").write_text('raise ModuleNotFoundError("No module named \'numpy\'", name="numpy")')
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(tmp_path), str(PACKAGE.parent)]))
    env.pop("UVTK_STUBGEN", None)
    run = subprocess.run([sys.executable, "-c", "import uvtk"], capture_output=True, text=True, env=env)
    assert run.returncode == 1 and "ModuleNotFoundError: uvtk needs numpy" in run.stderr, run.stderr


def test_names_are_uvtks():
    assert uvtk.Mesh.__module__ == "uvtk" and uvtk.Mapping.__module__ == "uvtk"
    assert uvtk.InputError.__module__ == "uvtk" and uvtk.map.__module__ == "uvtk"
    with pytest.raises(TypeError, match=r"^map\(\): mesh: expected a uvtk.Mesh, found int"):
        uvtk.map(3)


# ---- pickling ----

def test_a_mesh_pickles_as_its_arrays():
    positions, triangles, uv = quad_with_seam()
    normals = np.tile([0.0, 0.0, 1.0], (2, 3, 1))
    mesh = uvtk.Mesh(positions, triangles, uv=uv, normals=normals)
    for protocol in (2, pickle.HIGHEST_PROTOCOL):
        back = pickle.loads(pickle.dumps(mesh, protocol))
        assert type(back) is uvtk.Mesh and back is not mesh
        np.testing.assert_array_equal(back.positions, positions)
        np.testing.assert_array_equal(back.triangles, triangles)
        np.testing.assert_array_equal(back.uv, uv)
        np.testing.assert_array_equal(back.normals, normals)
    plain = pickle.loads(pickle.dumps(uvtk.Mesh(positions, triangles)))
    assert plain.uv is None and plain.normals is None


def test_a_mapping_pickles_as_its_data_not_mapped_again():
    mesh = uvtk.Mesh(*torus())
    for keywords in ({"projector": "cylinder", "caps": True}, {"projector": "sphere", "seam": "cut"},
                     {"projector": "cube"}):
        m = uvtk.map(mesh, **keywords)
        back = pickle.loads(pickle.dumps(m))
        for name in ("uv", "w", "q", "state", "invalid_reason", "face_flags"):
            a, b = getattr(m, name), getattr(back, name)
            assert (a is None and b is None) or (a.dtype == b.dtype and np.array_equal(a, b)), name
        np.testing.assert_array_equal(back.mesh.positions, m.mesh.positions)
        np.testing.assert_array_equal(back.mesh.triangles, m.mesh.triangles)
        assert back.source == m.source and back.verdict == m.verdict and back.summary == m.summary
        assert repr(back) == repr(m)
        assert [a.tolist() for a in back.split()] == [a.tolist() for a in m.split()]
    # report and render read what the engine keeps of a mapping (the judgement's per-face
    # measures, a projector's per-pixel evaluation): it does not travel, and they say so
    for call in (lambda: uvtk.report(mesh, back), lambda: uvtk.render(mesh, back)):
        with pytest.raises(ValueError, match=r"the mapping was restored from its data \(unpickled\)"):
            call()
    t = uvtk.texgen(mesh, s="object_linear:1,0,0,0", t="eye_linear:0,1,0,0")
    back = pickle.loads(pickle.dumps(t))
    np.testing.assert_array_equal(back.q, t.q)
    assert back.source == "texgen"
    with pytest.raises(ValueError, match="a texgen mapping restored from its data"):
        uvtk.write_mesh(os.devnull + ".obj", mesh, back)


def test_an_unpickled_mapping_writes_the_same_bytes(tmp_path):
    # map in one process, write in another: write_mesh of the unpickled mapping is the original's
    mesh = uvtk.Mesh(*torus())
    positions, triangles, uv = quad_with_seam()
    cases = [(mesh, {"projector": "cylinder", "caps": True}), (mesh, {"projector": "sphere", "seam": "cut"}),
             (mesh, {"projector": "cube"}), (mesh, {"projector": "atlas"}),
             (mesh, {"projector": "camera", "eye": (0, 0, 9)})]
    for i, (source, keywords) in enumerate(cases):
        m = uvtk.map(source, **keywords)
        back = pickle.loads(pickle.dumps(m))
        for extension in ("obj", "ply", "glb"):
            uvtk.write_mesh(tmp_path / f"a{i}.{extension}", source, m, write_w=extension == "obj")
            uvtk.write_mesh(tmp_path / f"b{i}.{extension}", source, back, write_w=extension == "obj")
            assert (tmp_path / f"a{i}.{extension}").read_bytes() == (tmp_path / f"b{i}.{extension}").read_bytes(), \
                (keywords, extension)
    own = uvtk.file_uvs(uvtk.Mesh(positions, triangles, uv=uv))
    uvtk.write_mesh(tmp_path / "own.obj", None, own)
    uvtk.write_mesh(tmp_path / "own_back.obj", None, pickle.loads(pickle.dumps(own)))
    assert (tmp_path / "own.obj").read_bytes() == (tmp_path / "own_back.obj").read_bytes()


def test_the_options_objects_pickle():
    o = uvtk.MapOptions.parse("--projector cylinder --caps --center 1,2,3 --seam-place auto --fail-on overlap=0.1")
    back = pickle.loads(pickle.dumps(o))
    assert back == o and back.command_line() == o.command_line()
    assert back.center == [1.0, 2.0, 3.0] and back.caps and back.seam_place_auto
    t = uvtk.TexgenOptions.parse("--s object_linear:1,0,0,0 --no-normalize --eye 0,0,5")
    assert pickle.loads(pickle.dumps(t)).command_line() == t.command_line()
    mesh = uvtk.Mesh(*torus())
    np.testing.assert_array_equal(uvtk.map(mesh, options=back).uv, uvtk.map(mesh, options=o).uv)


# ---- the ecosystem's layouts ----

def test_split_gives_xatlas_layout_for_a_quad_with_a_seam():
    positions, triangles, uv = quad_with_seam()
    m = uvtk.file_uvs(uvtk.Mesh(positions, triangles, uv=uv))
    vmapping, indices, uvs = m.split()
    # v2 is split (its corners' UVs differ); v0 is shared by both faces with one UV
    assert vmapping.tolist() == [0, 1, 2, 2, 3]
    assert indices.tolist() == [[0, 1, 2], [0, 3, 4]]
    assert uvs.tolist() == [[0, 0], [1, 0], [1, 1], [0.5, 1], [0, 1]]
    assert vmapping.dtype == np.int64 and indices.dtype == np.int64 and uvs.dtype == np.float64


def test_to_arrays_gives_libigls_layout():
    positions, triangles, uv = quad_with_seam(shared_uv=True)
    mesh = uvtk.Mesh(positions, triangles, uv=uv)
    m = uvtk.file_uvs(mesh)
    V, F, TC, FTC = m.to_arrays()
    # v1 and v3 share the texture vertex (1, 0); v2 has two
    assert TC.tolist() == [[0, 0], [1, 0], [1, 1], [0.5, 1]]
    assert FTC.tolist() == [[0, 1, 2], [0, 3, 1]]
    assert F.tolist() == triangles.tolist() and V.tolist() == positions.tolist()
    assert not V.flags.owndata  # the positions are a view
    # split keeps v1 and v3 apart: they are different vertices
    vmapping, indices, uvs = m.split()
    assert vmapping.tolist() == [0, 1, 2, 2, 3] and uvs[4].tolist() == [1, 0]
    # and back: Mesh.from_arrays(V, F, TC, FTC) has the corners' UVs TC[FTC]
    again = uvtk.Mesh.from_arrays(V, F, TC, FTC)
    np.testing.assert_array_equal(again.uv, uv)
    np.testing.assert_array_equal(again.positions, positions)
    assert [a.tolist() for a in uvtk.file_uvs(again).to_arrays()] == [a.tolist() for a in (V, F, TC, FTC)]
    assert uvtk.Mesh.from_arrays(V, F).uv is None
    np.testing.assert_array_equal(uvtk.Mesh.from_arrays(V, F, TC[:4]).uv, TC[F])  # FTC defaults to F
    with pytest.raises(ValueError, match="FTC"):
        uvtk.Mesh.from_arrays(V, F, TC, FTC + 10)


def test_split_of_a_projector_mapping_rebuilds_every_corner():
    mesh = uvtk.Mesh(*torus())
    m = uvtk.map(mesh, projector="cylinder", seam="shift")
    vmapping, indices, uvs = m.split()
    np.testing.assert_array_equal(uvs[indices], m.uv)
    np.testing.assert_array_equal(mesh.positions[vmapping][indices], mesh.positions[mesh.triangles])
    # one vertex per distinct (vertex, uv): more than the mesh's where the seam splits them
    distinct = {(int(v), *map(float, p)) for v, p in zip(mesh.triangles.ravel(), m.uv.reshape(-1, 2))}
    assert len(vmapping) == len(distinct) > mesh.vertex_count


def test_meshio_round_trip_through_ply(tmp_path):
    import meshio  # python3-meshio (scripts/setup.sh)
    mesh = uvtk.Mesh(*torus())
    m = uvtk.map(mesh, projector="cylinder")
    out = uvtk.to_meshio(m)
    meshio.write(tmp_path / "t.ply", out)
    back = uvtk.from_meshio(meshio.read(tmp_path / "t.ply"))
    np.testing.assert_array_equal(back.uv, m.uv)
    np.testing.assert_array_equal(back.positions[back.triangles], mesh.positions[mesh.triangles])
    # and uvtk's own PLY, read by meshio
    uvtk.write_mesh(tmp_path / "own.ply", mesh, m)
    own = uvtk.from_meshio(meshio.read(tmp_path / "own.ply"))
    np.testing.assert_array_equal(own.uv, m.uv)


def test_write_mesh_threads_give_the_same_bytes(tmp_path):
    mesh = uvtk.Mesh(*torus(64, 32))
    m = uvtk.map(mesh, projector="cylinder")
    for threads in (0, 1, 2):
        uvtk.write_mesh(tmp_path / f"t{threads}.obj", mesh, m, threads=threads, header="uvtk map in.obj")
    first = (tmp_path / "t0.obj").read_bytes()
    assert first.startswith(b"# uvtk map in.obj\n")
    assert first == (tmp_path / "t1.obj").read_bytes() == (tmp_path / "t2.obj").read_bytes()
    with pytest.raises(ValueError, match="threads"):
        uvtk.write_mesh(tmp_path / "t.obj", mesh, m, threads=-1)


# ---- report(html=) ----

def test_report_writes_html_for_file_and_numpy_meshes(tmp_path, meshes_dir):
    for i, mesh in enumerate((uvtk.read_mesh(meshes_dir / "torus.obj"), uvtk.Mesh(*torus()))):
        m = uvtk.map(mesh, projector="cylinder")
        page, record = tmp_path / f"r{i}.html", tmp_path / f"r{i}.json"
        rep = uvtk.report(mesh, m, html=page, json=record, views="checker", size=(64, 64))
        text = page.read_text(encoding="utf-8")
        assert text.startswith("<!DOCTYPE html>") and "data:image/png;base64," in text
        assert rep["verdict"] == m.verdict["status"] or rep["verdict"]["status"] == m.verdict["status"]
        import json
        assert json.loads(record.read_text()) == rep


# ---- Dask ----

def test_map_many_on_a_local_cluster_writes_what_the_program_writes(tmp_path, cli):
    import distributed  # python3-distributed (scripts/setup.sh)
    meshes = tmp_path / "in"
    meshes.mkdir()
    for i, (p, t) in enumerate((torus(12, 8), torus(16, 6), quad_with_seam()[:2])):
        uvtk.write_mesh(meshes / f"m{i}.obj", uvtk.Mesh(p, t))
    (meshes / "broken.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    expected = tmp_path / "program"
    run = cli("map", meshes, "-o", expected, "--projector", "cylinder", "-q")
    assert run.returncode == 3, run.stderr  # one mesh failed to read
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        batch = uvtk.map_many(meshes, tmp_path / "dask", client=client, projector="cylinder")
        # a scheduler's address is all it takes
        by_address = uvtk.map_many([meshes / "m0.obj"], tmp_path / "address", client=cluster.scheduler_address,
                                   projector="cylinder")
    assert by_address["mapped"] == 1
    assert (tmp_path / "address" / "m0.obj").read_bytes() == (expected / "m0.obj").read_bytes()
    assert batch["mapped"] == 3 and batch["failed"] == 1 and sum(batch["verdicts"].values()) == 3
    assert batch["jobs"] == 2 and batch["tool"] == {"name": "uvtk", "version": uvtk.__version__}
    assert batch["meshes"][0]["status"] == "failed" and "broken.off" in batch["meshes"][0]["error"]
    # the batch as `uvtk map DIR --json` writes batch.json: the same keys, each mesh's summary the same record
    run = cli("map", meshes, "-o", tmp_path / "again", "--json", tmp_path / "json", "--projector", "cylinder", "-q")
    import json
    program = json.loads((tmp_path / "json" / "batch.json").read_text())
    assert set(batch) - {"verdicts"} == set(program)
    assert batch["options"] == program["options"]
    for ours, theirs in zip(batch["meshes"], program["meshes"]):
        assert set(ours) - {"summary"} <= set(theirs) | {"error"} and ours["status"] == theirs["status"]
        if ours["status"] == "ok":
            assert ours["verdict"] == theirs["verdict"]
            record = json.loads(pathlib.Path(theirs["summary"]).read_text())
            for volatile in ("milliseconds", "output", "input"):
                record.pop(volatile, None)
                ours["summary"].pop(volatile, None)
            assert ours["summary"] == record
    assert [pathlib.Path(r["input"]).name for r in batch["meshes"]] == ["broken.off", "m0.obj", "m1.obj", "m2.obj"]
    for name in ("m0.obj", "m1.obj", "m2.obj"):
        assert (tmp_path / "dask" / name).read_bytes() == (expected / name).read_bytes(), name
    # Dask's default scheduler, the same bytes
    local = uvtk.map_many([meshes / "m1.obj"], tmp_path / "bag", projector="cylinder")
    assert local["mapped"] == 1 and (tmp_path / "bag" / "m1.obj").read_bytes() == (expected / "m1.obj").read_bytes()


def test_map_many_hands_out_every_mesh_once_in_order_in_shrinking_chunks():
    from uvtk import _batch
    for count, workers in ((0, 2), (1, 2), (7, 1), (200, 2), (1000, 8)):
        items = list(range(count))
        chunks = _batch._chunks(items, workers)
        assert [i for c in chunks for i in c] == items
        sizes = [len(c) for c in chunks]
        assert all(a >= b for a, b in zip(sizes, sizes[1:])), sizes
        assert not sizes or sizes[-1] == 1
    # 200 meshes on 2 workers: a quarter of a worker's share first (200 / 2 / 4 = 25), one mesh at the end
    assert [len(c) for c in _batch._chunks(list(range(200)), 2)][:3] == [25, 21, 19]


def test_map_many_keeps_freed_buffers_only_where_the_environment_turned_mallocs_adaptivity_off(monkeypatch):
    from uvtk import _batch
    monkeypatch.setattr(_batch, "_heap_kept", False)
    monkeypatch.delenv("MALLOC_TRIM_THRESHOLD_", raising=False)
    _batch._keep_freed_buffers()
    assert _batch._heap_kept is False  # this process's allocator is left alone


# ---- the README ----

def test_the_readmes_python_lines_run(tmp_path, meshes_dir, monkeypatch):
    readme = pathlib.Path(__file__).resolve().parents[2] / "README.md"
    block = re.search(r"```python\n(.*?)```", readme.read_text(encoding="utf-8"), re.S).group(1)
    assert "uvtk.map_many(" in block and "m.split()" in block
    (tmp_path / "meshes").mkdir()
    for name in ("torus.obj", "cube.obj"):
        (tmp_path / "meshes" / name).write_bytes((meshes_dir / name).read_bytes())
    (tmp_path / "mesh.obj").write_bytes((meshes_dir / "torus.obj").read_bytes())
    monkeypatch.chdir(tmp_path)
    scope = {}
    exec(compile(block, str(readme), "exec"), scope)  # noqa: S102 (the README's own lines)
    assert scope["img"].shape == (384, 512, 3) and scope["m"].uv.shape[1:] == (3, 2)
    assert scope["batch"]["mapped"] == 2 and (tmp_path / "out" / "torus.obj").exists()
