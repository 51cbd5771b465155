# The Python module against hostile input (issue 48; docs/robustness.md, "Python face"): arrays
# too big to copy, numbers of the wrong kind, objects of the wrong type, a machine out of memory,
# Ctrl-C during a long call. What could crash the interpreter runs in a child process, so that a
# crash fails its test instead of ending the run.
import inspect
import json
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import uvtk


def tetrahedron():
    positions = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    triangles = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    return positions, triangles


def lat_long_sphere(segments, rings):
    """The unit sphere as a latitude-longitude grid with single-vertex poles: 2 * segments * (rings - 1) faces."""
    theta = np.pi * np.arange(1, rings) / rings
    phi = 2 * np.pi * np.arange(segments) / segments
    ring = np.stack([np.outer(np.sin(theta), np.cos(phi)), np.outer(np.sin(theta), np.sin(phi)),
                     np.repeat(np.cos(theta)[:, None], segments, axis=1)], axis=-1).reshape(-1, 3)
    positions = np.concatenate([[[0.0, 0.0, 1.0]], ring, [[0.0, 0.0, -1.0]]])
    grid = 1 + np.arange((rings - 1) * segments).reshape(rings - 1, segments)
    a, b = grid[:-1], grid[1:]
    a1, b1 = np.roll(a, -1, axis=1), np.roll(b, -1, axis=1)
    top = np.stack([np.zeros(segments, dtype=np.int64), grid[0], np.roll(grid[0], -1)], axis=-1)
    bottom = np.stack([np.full(segments, len(positions) - 1), np.roll(grid[-1], -1), grid[-1]], axis=-1)
    quads = [np.stack(corners, axis=-1).reshape(-1, 3) for corners in ((a, b, b1), (a, b1, a1))]
    return positions, np.concatenate([top, *quads, bottom])


def child(*bodies):
    """The source of a child Python running `bodies`: SIGINT raises KeyboardInterrupt (even where
    the test runner ignores it), and lat_long_sphere and tetrahedron are defined."""
    return "\n".join([
        "import json, os, resource, signal, sys, time",
        "import numpy as np",
        "import uvtk",
        "signal.signal(signal.SIGINT, signal.default_int_handler)",
        inspect.getsource(tetrahedron),
        inspect.getsource(lat_long_sphere),
        *map(textwrap.dedent, bodies),
    ])


# Outcomes as the child sees them: each case's exception type and message, one JSON line each.
OUTCOMES = '''
def outcome(name, call):
    try:
        call()
        result = {"case": name, "error": None}
    except BaseException as error:
        result = {"case": name, "error": type(error).__name__, "message": str(error)}
    print(json.dumps(result), flush=True)

def limit_memory(extra_bytes):
    """Address space limited to what the process holds now and extra_bytes more."""
    with open("/proc/self/status") as status:
        size = next(int(line.split()[1]) * 1024 for line in status if line.startswith("VmSize:"))
    resource.setrlimit(resource.RLIMIT_AS, (size + extra_bytes, resource.RLIM_INFINITY))
'''


def run_outcomes(body, timeout=120):
    done = subprocess.run([sys.executable, "-c", child(OUTCOMES, body)], capture_output=True, text=True,
                          timeout=timeout)
    assert done.returncode == 0, f"the child died (status {done.returncode}):\n{done.stderr[-3000:]}"
    return {o["case"]: o for o in map(json.loads, done.stdout.splitlines())}


# ---- arrays too big ----


def test_arrays_too_big_to_copy_are_refused_never_a_crash():
    # The address space limited to 1 GiB more than the child holds: numpy's copy of a broadcast
    # array fails as it would on any machine, and it cannot take the machine's memory.
    outcomes = run_outcomes('''
        P, T = tetrahedron()
        limit_memory(1 << 30)
        outcome("faces beyond int32", lambda: uvtk.Mesh(P, np.broadcast_to(T[:1], (10**10, 3))))
        outcome("triangles copy", lambda: uvtk.Mesh(P, np.broadcast_to(T[:1], (10**9, 3))))
        outcome("positions copy", lambda: uvtk.Mesh(np.broadcast_to(P[:1], (10**9, 3)), T))
        outcome("vertices beyond int32", lambda: uvtk.Mesh(np.broadcast_to(P[:1], (2**31, 3)), T))
        outcome("eval points copy", lambda: uvtk.eval(np.broadcast_to(P[:1], (10**9, 3))))
    ''')
    assert outcomes["faces beyond int32"]["error"] == "ValueError"
    assert outcomes["faces beyond int32"]["message"] == (
        "triangles: 10000000000 faces, more than the 2147483647 a mesh holds (its indices are int32)")
    assert outcomes["vertices beyond int32"]["error"] == "ValueError"
    assert outcomes["vertices beyond int32"]["message"].startswith("positions: 2147483648 vertices, more than")
    for case in ("triangles copy", "positions copy", "eval points copy"):
        assert outcomes[case]["error"] == "MemoryError", outcomes[case]


def test_the_library_out_of_memory_is_a_memory_error():
    # Once the mesh is made, no memory more: no thread starts (the call runs on the caller's, and
    # parallelFor's work on it), and the library's arrays do not fit: std::bad_alloc. Then 64 MiB
    # more: the threads start, the arrays still do not fit. (glibc ends a process whose new thread
    # gets a stack, possibly one cached from an earlier thread, but not its thread-local storage:
    # the order matters, docs/robustness.md.)
    outcomes = run_outcomes('''
        P, T = lat_long_sphere(1000, 500)
        mesh = uvtk.Mesh(P, T)
        limit_memory(0)
        outcome("map without a thread", lambda: uvtk.map(mesh, projector="sphere"))
        limit_memory(64 << 20)
        outcome("map", lambda: uvtk.map(mesh, projector="sphere"))
        outcome("eval", lambda: uvtk.eval(P, projector="sphere"))
    ''')
    for case in ("map without a thread", "map", "eval"):
        assert outcomes[case]["error"] == "MemoryError", outcomes[case]


# ---- numbers of the wrong kind ----

WRONG_KINDS = {
    "complex128": lambda a: a + 1j,
    "bool": lambda a: a != 0,
    "object": lambda a: a.astype(object),
    "<U32": lambda a: a.astype(str),
    "datetime64[s]": lambda a: a.astype(np.int64).astype("datetime64[s]"),
}


@pytest.mark.parametrize("dtype", WRONG_KINDS)
@pytest.mark.parametrize("argument", ["positions", "uv", "normals", "points", "eval normals"])
def test_real_numbers_of_another_kind_are_a_type_error_naming_the_argument_and_dtype(argument, dtype):
    positions, triangles = tetrahedron()
    uv = positions[triangles][:, :, :2].copy()
    normals = positions.copy()
    wrong = WRONG_KINDS[dtype]
    calls = {
        "positions": lambda: uvtk.Mesh(wrong(positions), triangles),
        "uv": lambda: uvtk.Mesh(positions, triangles, uv=wrong(uv)),
        "normals": lambda: uvtk.Mesh(positions, triangles, normals=wrong(normals)),
        "points": lambda: uvtk.eval(wrong(positions)),
        "eval normals": lambda: uvtk.eval(positions, normals=wrong(normals)),
    }
    name = argument.split()[-1]
    with pytest.raises(TypeError, match=rf"^{name}: expected real numbers \(a floating or integer array\), "
                                        rf"found dtype {dtype.replace('[', '.').replace(']', '.')}$"):
        calls[argument]()


@pytest.mark.parametrize("dtype", [bool, float, complex, object, str])
def test_triangles_of_anything_but_integers_are_a_type_error(dtype):
    positions, triangles = tetrahedron()
    wrong = triangles.astype(dtype)
    with pytest.raises(TypeError, match=f"^triangles: expected an integer array, found dtype {wrong.dtype}$"):
        uvtk.Mesh(positions, wrong)


def test_integer_and_narrow_float_positions_are_the_same_numbers():
    positions, triangles = tetrahedron()
    for dtype in (np.int8, np.uint16, np.int64, np.float16, np.float32, np.longdouble):
        np.testing.assert_array_equal(uvtk.Mesh(positions.astype(dtype), triangles).positions, positions)
    np.testing.assert_array_equal(uvtk.eval(positions.astype(np.int32)).u, uvtk.eval(positions).u)


def test_eval_without_normals_evaluates_the_zero_normal():
    # Without normals, the module read one per point from past the end of an empty array.
    points = np.random.default_rng(7).normal(size=(2000, 3))
    for keywords in ({"projector": "sphere", "omap": "normal"},
                     {"projector": "cylinder", "omap": "reflection", "eye": (0, 0, 5)}):
        without = uvtk.eval(points, **keywords)
        zero = uvtk.eval(points, normals=np.zeros(3), **keywords)
        for key in ("u", "v", "status"):
            np.testing.assert_array_equal(without[key], zero[key])
        assert without.reason == zero.reason


# ---- objects of the wrong type ----


def wrong_arguments(tmp_path):
    positions, triangles = tetrahedron()
    mesh = uvtk.Mesh(positions, triangles)
    m = uvtk.map(mesh, projector="sphere")
    out = str(tmp_path / "out.obj")
    return {
        "report(): m: expected a uvtk.Mapping, found uvtk.Mesh": lambda: uvtk.report(mesh, mesh),
        "report(): mesh: expected a uvtk.Mesh, found uvtk.Mapping": lambda: uvtk.report(m, m),
        "render(): m: expected a uvtk.Mapping, found uvtk.Mesh": lambda: uvtk.render(mesh, mesh),
        "render(): m: expected a uvtk.Mapping, found NoneType": lambda: uvtk.render(mesh, None),
        "write_mesh(): m: expected a uvtk.Mapping, found uvtk.Mesh": lambda: uvtk.write_mesh(out, mesh, mesh),
        "write_mesh(): mesh: expected a uvtk.Mesh, found int": lambda: uvtk.write_mesh(out, 3),
        "write_mesh(): path: expected a str, bytes or os.PathLike, found int": lambda: uvtk.write_mesh(3, mesh),
        "compare(): mesh: expected a uvtk.Mesh, found str": lambda: uvtk.compare("mesh.obj"),
        "eval(): mesh: expected a uvtk.Mesh, found numpy.ndarray": lambda: uvtk.eval(positions, mesh=positions),
        "check_mesh(): mesh: expected a uvtk.Mesh, found tuple": lambda: uvtk.check_mesh((positions, triangles)),
        "map(): mesh: expected a uvtk.Mesh, found uvtk.Mapping": lambda: uvtk.map(m),
        "map(): options: expected a uvtk.MapOptions, found uvtk.TexgenOptions":
            lambda: uvtk.map(mesh, options=uvtk.TexgenOptions()),
        "texgen(): mesh: expected a uvtk.Mesh, found NoneType": lambda: uvtk.texgen(None),
        "texgen(): options: expected a uvtk.TexgenOptions, found dict": lambda: uvtk.texgen(mesh, options={}),
        "file_uvs(): mesh: expected a uvtk.Mesh, found float": lambda: uvtk.file_uvs(1.5),
        "read_mesh(): path: expected a str, bytes or os.PathLike, found NoneType": lambda: uvtk.read_mesh(None),
    }


def test_an_object_of_the_wrong_type_is_a_type_error_naming_function_and_argument(tmp_path):
    for message, call in wrong_arguments(tmp_path).items():
        with pytest.raises(TypeError) as error:
            call()
        assert str(error.value) == message
    assert not list(tmp_path.iterdir())


def test_a_nul_in_a_path_is_a_value_error(tmp_path):
    positions, triangles = tetrahedron()
    with pytest.raises(ValueError, match=r"^read_mesh\(\): path: holds a NUL character$"):
        uvtk.read_mesh(str(tmp_path / "a\0b.obj"))
    with pytest.raises(ValueError, match=r"^write_mesh\(\): path: holds a NUL character$"):
        uvtk.write_mesh(str(tmp_path / "a\0b.obj"), uvtk.Mesh(positions, triangles))
    assert not list(tmp_path.iterdir())


# ---- the exceptions' faces ----


def test_user_mistakes_raise_the_documented_exceptions_never_runtime_error(tmp_path):
    positions, triangles = tetrahedron()
    mesh = uvtk.Mesh(positions, triangles)
    m = uvtk.map(mesh, projector="sphere")
    (tmp_path / "folder").mkdir()
    mistakes = [
        (uvtk.InputError, lambda: uvtk.read_mesh(tmp_path / "missing.obj")),
        (uvtk.InputError, lambda: uvtk.read_mesh(tmp_path / "folder")),
        (uvtk.InputError, lambda: uvtk.render(mesh, m, view="", texture=str(tmp_path / "missing.png"))),
        (uvtk.OutputError, lambda: uvtk.write_mesh(tmp_path / "missing" / "out.obj", mesh, m)),
        (uvtk.OutputError, lambda: uvtk.write_mesh(tmp_path / "folder", mesh, m)),
        (uvtk.OutputError, lambda: uvtk.report(mesh, m, json=str(tmp_path / "missing" / "r.json"))),
        (ValueError, lambda: uvtk.write_mesh(tmp_path / "out.xyz", mesh, m)),
        (ValueError, lambda: uvtk.map(mesh, projector="bogus")),
        (ValueError, lambda: uvtk.map(mesh, threads=10**30)),
        (ValueError, lambda: uvtk.render(mesh, m, size=(0, 0))),
        (ValueError, lambda: uvtk.compare(mesh, top=0)),
        (ValueError, lambda: uvtk.eval(positions, projector="bogus")),
        (ValueError, lambda: uvtk.eval([[0, 0, 0], [1, 2]])),
        (ValueError, lambda: uvtk.file_uvs(mesh)),
        (TypeError, lambda: uvtk.map(mesh, caps="no")),
        (TypeError, lambda: uvtk.map(mesh, center={1: 2})),
        (TypeError, lambda: uvtk.Mesh(None, None)),
    ]
    for expected, call in mistakes:
        with pytest.raises(Exception) as error:
            call()
        assert type(error.value) is expected, f"{type(error.value).__name__}: {error.value}"
    assert issubclass(uvtk.OutputError, OSError)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["folder"]


# ---- Ctrl-C ----


def interrupt(body, after, timeout=120):
    """Runs body in a child, sends SIGINT `after` seconds after it prints its first line, and
    returns (what it printed after that line, its stderr, its status, the seconds from signal to exit)."""
    process = subprocess.Popen([sys.executable, "-c", child(body)], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    try:
        assert process.stdout.readline(), process.stderr.read()
        time.sleep(after)
        sent = time.monotonic()
        process.send_signal(signal.SIGINT)
        out, err = process.communicate(timeout=timeout)
        return out, err, process.returncode, time.monotonic() - sent
    finally:
        process.kill()
        process.wait()


def test_ctrl_c_interrupts_a_long_map_within_a_second_or_so():
    # 4 M faces on two threads: about 3 s of mapping on the 2-core VM.
    out, err, status, seconds = interrupt('''
        P, T = lat_long_sphere(2000, 1000)
        mesh = uvtk.Mesh(P, T)
        print("mapping", flush=True)
        uvtk.map(mesh, projector="sphere", threads=2)
        print("finished", flush=True)
    ''', after=1.0)
    assert "finished" not in out, "the map ended before the signal: make it longer"
    assert status != 0 and err.rstrip().endswith("KeyboardInterrupt"), err[-2000:]
    assert seconds < 3.0


def test_ctrl_c_interrupts_compare_within_a_second_or_so():
    # 360 k faces whose every vertex is on the convex hull: compare began with 17 s in one
    # uninterruptible oriented-box search (now bounded, with a cancellation check around it), and
    # ranked about 25 s in all; the signal comes while the first fits and mappings run.
    out, err, status, seconds = interrupt('''
        P, T = lat_long_sphere(600, 300)
        mesh = uvtk.Mesh(P, T)
        print("comparing", flush=True)
        uvtk.compare(mesh)
        print("finished", flush=True)
    ''', after=1.0)
    assert "finished" not in out, "the compare ended before the signal: make it longer"
    assert status != 0 and err.rstrip().endswith("KeyboardInterrupt"), err[-2000:]
    assert seconds < 2.0


def test_ctrl_c_while_writing_leaves_the_whole_file_or_none(tmp_path):
    out_path = tmp_path / "out.obj"
    out, err, status, seconds = interrupt(f'''
        P, T = lat_long_sphere(1400, 700)
        mesh = uvtk.Mesh(P, T)
        m = uvtk.map(mesh, projector="sphere")
        print("writing", flush=True)
        uvtk.write_mesh({str(out_path)!r}, mesh, m)
        print("finished", flush=True)
    ''', after=0.15)
    assert "finished" in out or err.rstrip().endswith("KeyboardInterrupt"), err[-2000:]
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names in ([], ["out.obj"]), names  # no temporary left
    if names:
        text = out_path.read_bytes()
        assert text.endswith(b"\n") and text.count(b"\nf ") == 2 * 1400 * 699
    assert seconds < 3.0
