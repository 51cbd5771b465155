"""uvtk's PEP 517 build backend (pyproject.toml: backend-path = ["python"]), with nothing but the
standard library, so that `pip install .` and `pip wheel .` work offline, with or without build
isolation (docs/python.md, "Installing with pip").

It builds the library, the program and the Python package with CMake (the targets below) in a
build directory, installs CMake's `python` component (libuvtk, libuvtk_point, the image and benchmark plugins,
the `uvtk` program and the package uvtk/) into a staging folder, and packs a wheel:

    uvtk/__init__.py, _uvtk.cpython-*.so, __init__.pyi, py.typed, ...   the package
    uvtk/lib/libuvtk.so.*, libuvtk_point.so.*    found by _uvtk through its RPATH $ORIGIN/lib
    uvtk/lib/uvtk/libuvtk_image_oiio.so          found by the library from its own folder
    uvtk/lib/uvtk/libuvtk_benchmark_runner.so    found by the program (uvtk bench) from bin/
    uvtk/bin/uvtk                                the program (its plugins: ../lib/uvtk from bin/)
    uvtk-V.data/scripts/uvtk                     on the environment's PATH: runs uvtk/bin/uvtk

The build directory: config setting `build-dir` (pip --config-settings build-dir=PATH), else the
environment variable UVTK_BUILD_DIR, else build-wheel/ in the source tree. A directory already
configured (the release build, build/) is reused as it is: only the targets below are built in it,
so the test command does not compile the project twice.
"""
import base64
import hashlib
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import zipfile

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TARGETS = ["uvtk", "uvtk_python", "uvtk_library", "uvtk_point", "uvtk_image_oiio", "uvtk_benchmark_runner"]
NAME = "uvtk"


def _version():
    with open(os.path.join(SOURCE, "CMakeLists.txt"), encoding="utf-8") as f:
        found = re.search(r"project\(\s*uvtk\s+VERSION\s+([0-9][0-9.]*)", f.read())
    if not found:
        raise RuntimeError("uvtk_build_backend: no project(uvtk VERSION ...) in CMakeLists.txt")
    return found.group(1)


def _project():
    """pyproject.toml's [project] table: the dependencies and the description live there once."""
    import tomllib  # Python 3.11+; the module is built for the interpreter that runs this

    with open(os.path.join(SOURCE, "pyproject.toml"), "rb") as f:
        return tomllib.load(f).get("project", {})


def _tag():
    interpreter = f"cp{sys.version_info.major}{sys.version_info.minor}"
    abi = interpreter + getattr(sys, "abiflags", "")
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{interpreter}-{abi}-{platform}"


def _metadata():
    project = _project()
    lines = ["Metadata-Version: 2.1", f"Name: {NAME}", f"Version: {_version()}",
             f"Summary: {project.get('description', '')}"]
    if project.get("requires-python"):
        lines.append(f"Requires-Python: {project['requires-python']}")
    lines += [f"Requires-Dist: {d}" for d in project.get("dependencies", [])]
    lines += [f"Project-URL: {k}, {v}" for k, v in project.get("urls", {}).items()]
    readme = os.path.join(SOURCE, "README.md")
    body = ""
    if os.path.exists(readme):
        lines.append("Description-Content-Type: text/markdown")
        with open(readme, encoding="utf-8") as f:
            body = f.read()
    return "\n".join(lines) + "\n\n" + body


def _wheel_file():
    return f"Wheel-Version: 1.0\nGenerator: uvtk_build_backend\nRoot-Is-Purelib: false\nTag: {_tag()}\n"


def _dist_info():
    return f"{NAME}-{_version()}.dist-info"


def _build_dir(config_settings):
    chosen = (config_settings or {}).get("build-dir") or os.environ.get("UVTK_BUILD_DIR")
    return os.path.abspath(chosen or os.path.join(SOURCE, "build-wheel"))


def _run(command):
    print("uvtk_build_backend: " + " ".join(command), file=sys.stderr, flush=True)
    subprocess.run(command, check=True, stdout=sys.stderr)


def _build(build_dir):
    """Configures (unless it already is), builds the targets, and checks the module is for this Python."""
    cmake = shutil.which("cmake") or "cmake"
    if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
        generator = ["-G", "Ninja"] if shutil.which("ninja") else []
        _run([cmake, "-S", SOURCE, "-B", build_dir, *generator, "-DCMAKE_BUILD_TYPE=Release",
              "-DUVTK_BUILD_TESTS=OFF", "-DUVTK_BUILD_BENCH=OFF", "-DUVTK_BUILD_PYTHON=ON",
              f"-DPython3_EXECUTABLE={sys.executable}"])
    jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
    _run([cmake, "--build", build_dir, "-j", jobs, "--target", *TARGETS])
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    if not os.path.exists(os.path.join(build_dir, "python", "uvtk", "_uvtk" + suffix)):
        raise RuntimeError(f"uvtk_build_backend: {build_dir} has no python/uvtk/_uvtk{suffix}: it was configured "
                           f"for another Python than {sys.executable} (or without pybind11)")


def _stage(build_dir, staging):
    """CMake's `python` component installed into `staging`; returns {path in the wheel: file}."""
    _run([shutil.which("cmake") or "cmake", "--install", build_dir, "--prefix", staging, "--component", "python"])
    files = {}
    package = None
    for root, _, names in os.walk(staging):
        for name in names:
            path = os.path.join(root, name)
            relative = os.path.relpath(path, staging).replace(os.sep, "/")
            if "/site-packages/uvtk/" in "/" + relative or "/dist-packages/uvtk/" in "/" + relative:
                package = relative[:relative.index("/uvtk/")]
                files["uvtk/" + relative[len(package) + len("/uvtk/"):]] = path
            elif relative == "bin/uvtk":
                files["uvtk/bin/uvtk"] = path
            elif relative.startswith("lib/uvtk/") and name.endswith(".so"):
                files["uvtk/lib/uvtk/" + name] = path
            elif relative.startswith("lib/") and "/" not in relative[4:] and ".so" in name:
                # Each library once, under its soname (the name the loader looks for); the link-time
                # symlinks (libuvtk.so) are for compilers, which the wheel does not serve.
                real = os.path.realpath(path)
                files["uvtk/lib/" + (_soname(real) or os.path.basename(real))] = real
    if package is None:
        raise RuntimeError("uvtk_build_backend: the install has no uvtk package (site-packages/uvtk)")
    return files


def _soname(path):
    try:
        out = subprocess.run(["objdump", "-p", path], check=True, capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    found = re.search(r"^\s*SONAME\s+(\S+)", out, re.M)
    return found.group(1) if found else None


LAUNCHER = """#!python
# The uvtk program of the package uvtk (installed by pip): runs uvtk/bin/uvtk, which finds its
# image plugin beside it (uvtk/lib/uvtk).
import importlib.util
import os
import sys

spec = importlib.util.find_spec("uvtk")
program = os.path.join(spec.submodule_search_locations[0], "bin", "uvtk")
os.execv(program, [sys.argv[0], *sys.argv[1:]])
"""


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def _write_wheel(wheel_directory, files):
    version = _version()
    wheel_name = f"{NAME}-{version}-{_tag()}.whl"
    dist_info = _dist_info()
    data_dir = f"{NAME}-{version}.data"
    entries = []  # (name, bytes, mode)
    for name in sorted(files):
        path = files[name]
        with open(path, "rb") as f:
            entries.append((name, f.read(), os.stat(path).st_mode & 0o777))
    entries.append((f"{data_dir}/scripts/uvtk", LAUNCHER.encode(), 0o755))
    entries.append((f"{dist_info}/METADATA", _metadata().encode(), 0o644))
    entries.append((f"{dist_info}/WHEEL", _wheel_file().encode(), 0o644))
    entries.append((f"{dist_info}/top_level.txt", b"uvtk\n", 0o644))
    record = [_record_line(n, d) for n, d, _ in entries] + [f"{dist_info}/RECORD,,"]
    entries.append((f"{dist_info}/RECORD", ("\n".join(record) + "\n").encode(), 0o644))
    os.makedirs(wheel_directory, exist_ok=True)
    target = os.path.join(wheel_directory, wheel_name)
    with zipfile.ZipFile(target, "w", compression=zipfile.ZIP_DEFLATED) as wheel:
        for name, data, mode in entries:
            info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
            info.external_attr = (0o100000 | mode) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            wheel.writestr(info, data)
    return wheel_name


# ---- PEP 517 hooks ----

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    path = os.path.join(metadata_directory, _dist_info())
    os.makedirs(path, exist_ok=True)
    with open(os.path.join(path, "METADATA"), "w", encoding="utf-8") as f:
        f.write(_metadata())
    with open(os.path.join(path, "WHEEL"), "w", encoding="utf-8") as f:
        f.write(_wheel_file())
    return _dist_info()


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    build_dir = _build_dir(config_settings)
    _build(build_dir)
    with tempfile.TemporaryDirectory(prefix="uvtk-wheel-") as staging:
        return _write_wheel(wheel_directory, _stage(build_dir, staging))


def build_sdist(sdist_directory, config_settings=None):
    """The files git tracks (or, outside a clone, the source tree less build folders) as NAME-V.tar.gz."""
    import tarfile

    version = _version()
    base = f"{NAME}-{version}"
    try:
        listed = subprocess.run(["git", "-C", SOURCE, "ls-files", "-z"], check=True, capture_output=True).stdout
        names = [n for n in listed.decode().split("\0") if n]
    except (OSError, subprocess.CalledProcessError):
        names = []
        for root, dirs, files in os.walk(SOURCE):
            dirs[:] = [d for d in dirs if not d.startswith(("build", ".git"))]
            names += [os.path.relpath(os.path.join(root, f), SOURCE) for f in files]
    os.makedirs(sdist_directory, exist_ok=True)
    target = os.path.join(sdist_directory, base + ".tar.gz")
    with tarfile.open(target, "w:gz") as tar:
        for name in sorted(names):
            path = os.path.join(SOURCE, name)
            if os.path.isfile(path):
                tar.add(path, arcname=f"{base}/{name}", recursive=False)
        info = tarfile.TarInfo(f"{base}/PKG-INFO")
        data = _metadata().encode()
        info.size = len(data)
        import io

        tar.addfile(info, io.BytesIO(data))
    return base + ".tar.gz"
