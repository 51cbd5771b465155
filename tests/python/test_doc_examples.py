"""Every `uvtk ...` command example in README.md and docs/*.md runs, with the exit status and the
output the text shows (issue 50, point 1: the docs cannot drift).

An example is a line of a fenced shell block (```sh, ```bash, ```console, ``` without a language)
or of an indented code block whose command is `uvtk` (after an optional `$ ` prompt; also `uvtk`
after a pipe, `&&`, `time -v` ...). Its trailing `# comment` is not part of it. The examples of one
block run in order, in one fresh folder, through bash with the built program first on PATH; the
folder holds a copy of the bundled meshes as `meshes/`, and the placeholder files an example names
(mesh.obj, scan.obj, ...) are made from the bundled meshes by FILES just before the first example
that names them, unless an earlier example of the block wrote them. Shell variables assigned in a
block (`C="--projector sphere ..."`) stay set for the rest of the document, as in a reader's shell.

What the text shows is checked: lines of the program's output right under the command (`uvtk X:
...` lines; in a `$ `-prompt block every line up to the next prompt), output blocks that name no
command (OUTPUT_BLOCKS says which command prints them), and claims in comments (CLAIMS). A line of
expected output matches one output line whole, in order (stdout and stderr each in their own
order); a time in ms may differ, and `...` stands for any text (a line that is only `...` for any
lines). The exit status is 0 unless EXIT says otherwise.

An example that cannot run here is in SKIP with the reason; one the program gets wrong is in XFAIL
with what happens. Every example is either run or in SKIP, and every entry of the tables matches an
example (test_tables_match_the_docs), so a new example in the docs is run by this test.
"""
import json
import os
import pathlib
import re
import shutil
import subprocess

import pytest

from conftest import _find_binary

ROOT = pathlib.Path(__file__).resolve().parents[2]
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
NOT_SHELL = {"python", "py", "cpp", "c++", "c", "cmake", "json", "yaml", "toml"}
SUBCOMMANDS = r"(?:map|compare|report|render|texgen|eval|check|run|schema|bench|merge-reports)"
# `uvtk` as a command: at the line's start or after a pipe, `&&`, `;`, or a wrapper
# (`/usr/bin/time -v`, `perf stat -r N`, `VAR=value`, `parallel`).
COMMAND = re.compile(r"(?:^|[|;&]\s*|(?:time -v|perf stat -r \d+|parallel|[A-Z_]+=\S+)\s+)uvtk\s+(?:"
                     + SUBCOMMANDS + r"|--version|--help|-h)\b(?!:)")
OUTPUT_LINE = re.compile(r"^uvtk(?: [a-z-]+)?: ")  # `uvtk map: 482 vertices ...`, `uvtk: error: ...`
ASSIGNMENT = re.compile(r"""^[A-Z][A-Z0-9_]*=("[^"]*"|'[^']*'|\S*)$""")  # C="--projector sphere ..." alone
HEREDOC = re.compile(r"^cat > (\S+) <<'?(\w+)'?$")

# ---- the placeholder files -------------------------------------------------------------------
# A recipe is called with (folder, name, run), run(script) running bash in the folder.

def _from_meshes(mesh):
    return lambda d, name, run: shutil.copy(d / "meshes" / mesh, d / name)


def _shell(script):
    return lambda d, name, run: run(script)


def _upright_off(mesh):
    """An OFF file of an OBJ mesh in the xy plane, turned into the xz plane ((x, y, z) -> (x, -z, y))."""
    def make(d, name, run):
        vs, fs = [], []
        for line in (d / "meshes" / mesh).read_text().splitlines():
            if line.startswith("v "):
                x, y, z = (float(c) for c in line.split()[1:4])
                vs.append(f"{x!r} {-z!r} {y!r}")
            elif line.startswith("f "):
                fs.append([str(int(c.split("/")[0]) - 1) for c in line.split()[1:]])
        (d / name).write_text(f"OFF\n{len(vs)} {len(fs)} 0\n" + "".join(f"{v}\n" for v in vs)
                              + "".join(f"{len(f)} {' '.join(f)}\n" for f in fs))
    return make


def _moved_corner(d, name, run):
    """docs/check.md's worked example: the icosphere under `uvtk map --projector sphere`, then one
    corner's u (face 100, corner 1) moved by 0.01 through a vt of its own."""
    run(f"uvtk map meshes/icosphere.obj --projector sphere -o {name} -q")
    lines = (d / name).read_text().splitlines()
    vts = [line for line in lines if line.startswith("vt ")]
    face = [i for i, line in enumerate(lines) if line.startswith("f ")][100]
    corners = lines[face].split()
    indices = corners[2].split("/")  # corner 1: after "f" and corner 0
    u, v = vts[int(indices[1]) - 1].split()[1:3]
    corners[2] = "/".join([indices[0], str(len(vts) + 1), *indices[2:]])
    lines[face] = " ".join(corners)
    last_vt = max(i for i, line in enumerate(lines) if line.startswith("vt "))
    lines.insert(last_vt + 1, f"vt {float(u) + 0.01!r} {v}")
    (d / name).write_text("\n".join(lines) + "\n")


def _knot(d, name, run):
    """The (2, 3) torus knot of `uvtk_meshgen --like-real` (3840 vertices), which the README's knot
    examples show (meshes/torus_knot.glb is a coarser one); the build tree has the generator."""
    meshgen = os.environ.get("UVTK_MESHGEN") or (_BINARY.parents[2] / "meshes" / "uvtk_meshgen" if _BINARY else "")
    if not pathlib.Path(meshgen).is_file():
        pytest.skip("knot.obj is uvtk_meshgen --like-real's knot: no uvtk_meshgen beside the program (UVTK_MESHGEN)")
    subprocess.run([str(meshgen), "--like-real", str(d / "like_real")], check=True, capture_output=True)
    shutil.copy(d / "like_real" / "torus_knot.obj", d / name)


def _folder_of(*meshes):
    def make(d, name, run):
        (d / name).mkdir()
        for mesh in meshes:
            shutil.copy(d / "meshes" / mesh, d / name / mesh)
    return make


def _summaries(nested):
    """What GNU parallel or a job array leaves: one `uvtk map --json` summary a mesh."""
    def make(d, name, run):
        for stem in ("torus", "cylinder_capped"):
            out = f"{name}/{stem}" if nested else name
            summary = f"{out}/summary.json" if nested else f"{out}/{stem}.json"
            run(f"mkdir -p {out} && uvtk map meshes/{stem}.obj -o {out}/{stem}.obj --json {summary} -q")
    return make


# Placeholder name -> how to make it in the example's folder (a bundled mesh, or what `uvtk` makes
# of one). Chosen so that each example shows what its text says.
FILES = {
    "mesh.obj": _from_meshes("cylinder_capped.obj"),    # a cylinder for --caps, any shape for the rest
    "IN.obj": _from_meshes("torus.obj"),
    "part.off": _upright_off("plane_grid.obj"),         # OFF input, a flat part across the two planes x = 0, z = 2
    "part.obj": _from_meshes("cylinder_capped.obj"),
    "scan.obj": _shell("uvtk map meshes/scanned_patch.ply --projector plane -o scan.obj -q"),  # an open scan with vt
    "model.obj": _shell("uvtk map meshes/icosphere.obj --projector sphere --convention blender -o model.obj -q"),
    "mine.obj": _shell("uvtk map meshes/torus.obj --projector cylinder --uv-digits float -o mine.obj -q"),
    "reference.obj": _shell("uvtk map meshes/torus.obj --projector cylinder -o reference.obj -q"),
    "new_export.obj": _shell("uvtk map meshes/torus.obj --projector cylinder --uv-digits float -o new_export.obj -q"),
    "old_export.obj": _shell("uvtk map meshes/torus.obj --projector cylinder -o old_export.obj -q"),
    "knot.obj": _knot,
    "tri.obj": _shell(r"printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > tri.obj"),  # docs/benchmarks.md's
    "photo.jpg": _shell("uvtk render meshes/plane_grid.obj --projector plane --texture uvgrid --size 256x256 -o photo.jpg -q"),
    "sky.png": _shell("uvtk render meshes/icosphere.obj --projector sphere --texture uvgrid --size 256x192 -o sky.png -q"),  # 4 x 3
    "rows.jsonl": _shell("""printf '{"p": [0, 0, 1], "n": [0, 0, 1]}\\n{"p": [1, 0, 0], "n": [1, 0, 0]}\\n' > rows.jsonl"""),
    "scans/": _folder_of("torus.obj", "icosphere.obj", "scanned_patch.ply"),
    "meshes.txt": _shell("printf 'meshes/torus.obj\\n# a comment\\nmeshes/cube.obj\\n' > meshes.txt"),
}
# Placeholders that only some examples read (elsewhere the same name is an example's output).
FILES_FOR = {
    ("check.md", "uvtk check model.obj --projector sphere --tolerance 1e-3 --worst 2"): {"model.obj": _moved_corner},
    # the GNU parallel and Slurm runs are skipped: their outputs, as they would leave them
    ("scale-out.md", "uvtk merge-reports -o merged.json out/"): {"out/": _summaries(nested=True)},
    ("scale-out.md", "uvtk merge-reports -o merged.json reports/"): {"reports/": _summaries(nested=False)},
    # README's screenshot check reads the quad-derivative picture of the block above it
    ("commands.md", "uvtk check meshes/sphere_latlong.obj $C --image gpu.png --error-mask bad.png"):
        {"gpu.png": _shell("uvtk render meshes/sphere_latlong.obj $C --derivatives quad-coarse -o gpu.png -q")},
}
# Commands that the text names but that are no uvtk: what stands in for them.
STAND_INS = {
    "my_shader_dump": "my_shader_dump() { printf 'x,y,z,nx,ny,nz\\n0.3,0.8,-2,0,0,1\\n-1,0.5,-3,0.2,0.9,0.4\\n'; }",
}

# ---- what cannot run here, and what the program gets wrong -------------------------------------

SYNOPSIS = "a synopsis (the command's grammar: alternatives and [options]), not a command"
# (document, the command's start) -> why it is not run
SKIP = {
    ("commands.md", "uvtk map IN.obj|.off|.ply"): SYNOPSIS,
    ("commands.md", "uvtk texgen IN.obj --s object_linear:a,b,c,d"): SYNOPSIS,
    ("commands.md", "uvtk render IN.obj [--projector"): SYNOPSIS,
    ("commands.md", "uvtk report IN.obj [projector options]"): SYNOPSIS,
    ("commands.md", "uvtk compare IN.obj [--by"): SYNOPSIS,
    ("commands.md", "uvtk bench [--mesh FILE]"): SYNOPSIS,
    ("check.md", "uvtk check MESH.obj [--projector"): SYNOPSIS,
    ("check.md", "uvtk check MESH --image SHOT.png [every"): SYNOPSIS,
    ("eval.md", "uvtk eval [--point x,y,z"): SYNOPSIS,
    ("scenes.md", "uvtk run SCENE.json [--output-dir DIR]"): SYNOPSIS,
    ("scenes.md", "uvtk run SCENE.json --plan [--json PLAN.json]"): SYNOPSIS,
    ("scale-out.md", "uvtk merge-reports -o MERGED.json INPUT..."): SYNOPSIS,
    ("benchmarks.md", "/usr/bin/time -v uvtk map sphere2048.obj"): "a 231 MB OBJ of the 2048 x 1024 sphere that the text does not make: seconds and 565 MB",
    ("benchmarks.md", "perf stat -r 100 uvtk map tri.obj"): "perf (not a dependency of the project) needs access to performance events, which containers often refuse",
    ("benchmarks.md", "uvtk bench --mesh s4m.obj"): "a 4 M-triangle, 220 MB sphere (uvtk_meshgen --sphere 1414 1414) mapped end to end per thread count, over 800 MB each: beyond this test's budget",
    ("benchmarks.md", "uvtk bench --projector sphere --precision double,float"): "32 s on 2 cores (the 2048 x 1024 sphere in 8 configurations, 0.5 s each, and its reference), half this test's budget",
    ("precision.md", "uvtk bench --threads 1,2 --render"): "59 s on 2 cores (the 2048 x 1024 sphere in every configuration, and 18 rendering configurations): this test's whole budget",
    ("robustness.md", "/usr/bin/time -v uvtk map huge.obj"): "a 20 M-triangle mesh: 29 s and 3.1 GB",
    ("scale-out.md", "parallel "): "GNU parallel (not a dependency of the project)",
    ("scale-out.md", 'uvtk map "$mesh" -o "out/$name/$name.obj"'): "a Slurm array task's script: $mesh and $name come from SLURM_ARRAY_TASK_ID",
}
# (document, the command's start) -> a program that the example needs besides uvtk and the shell
REQUIRES = {
    ("benchmarks.md", "/usr/bin/time -v uvtk map tri.obj"): "/usr/bin/time",
}
# (document, the command's start) -> what the program does that its docs say it should not
XFAIL = {}

# ---- what the text says the program does -------------------------------------------------------

# (document, command) -> exit status, where the text says it is not 0
EXIT = {
    ("check.md", "uvtk check model.obj --projector sphere --tolerance 1e-3 --worst 2"): 1,  # FAIL above --tolerance
    ("commands.md", "uvtk check meshes/sphere_latlong.obj $C --image gpu.png --error-mask bad.png"): 1,  # "FAIL: ..."
}


def _csv_row(out, row=1):
    return out.splitlines()[row].split(",")


# (document, command) -> a check of what its comment (or the prose around it) says it prints;
# called with (stdout, stderr, folder).
CLAIMS = {
    ("README.md", "uvtk map mesh.obj -o mapped.obj --projector atlas"):  # "a verdict on stderr" (the atlas passes)
        lambda out, err, d: re.search(r"^uvtk map: .*; verdict pass$", err, re.M) and not out,
    ("README.md", "uvtk compare mesh.obj --write-best best.obj"):  # "rank them all, write the best"
        lambda out, err, d: "| 1 |" in out and (d / "best.obj").exists() and "uvtk compare: wrote best.obj" in err,
    ("README.md", "uvtk report mapped.obj --html report.html"):
        lambda out, err, d: (d / "report.html").stat().st_size > 0,
    ("README.md", "uvtk run meshes/demo.json --output-dir out --json out/run.json"):  # "then open out/index.html"
        lambda out, err, d: (d / "out" / "index.html").exists() and (d / "out" / "run.json").exists(),
    ("README.md", "uvtk run meshes/demo.json --plan"):  # "the stages it would run, and nothing else"
        lambda out, err, d: re.match(r"uvtk run meshes/demo.json: \d+ stages\n", out) and not (d / "meshes" / "obj").exists(),
    ("README.md", "uvtk schema"):  # "the JSON Schema (schema/scene.schema.json)"
        lambda out, err, d: out == (ROOT / "schema" / "scene.schema.json").read_text(),
    ("commands.md", "uvtk render meshes/sphere_latlong.obj $C --view mipline -o mipline.png --json m.json"):  # "450 seam pixels"
        lambda out, err, d: json.loads((d / "m.json").read_text())["mip_line"]["where"]["seam"] == 450,
    ("commands.md", "uvtk check meshes/sphere_latlong.obj $C --image gpu.png --error-mask bad.png"):  # "FAIL: 455 invalid pixels, the line"
        lambda out, err, d: "uvtk check: FAIL (455 invalid pixels)" in out.splitlines() and (d / "bad.png").exists(),
    ("commands.md", "uvtk eval --projector sphere --point 0,1,0 --point 0,0,2"):  # "x,y,z,u,v,w,q,status,reason, 17 digits"
        lambda out, err, d: out.splitlines()[0] == "x,y,z,u,v,w,q,status,reason" and len(out.splitlines()) == 3,
    ("eval.md", "uvtk eval --point 0,1,0"):  # sphere: 0,1,0,0.25,0.5,0,1,ok,""
        lambda out, err, d: out.splitlines()[1] == '0,1,0,0.25,0.5,0,1,ok,""',
    ("eval.md", "uvtk eval --projector cube --omap centroid --cube-convention direct --cube-layout faces --point=-0.2,0.5,-0.84"):
        # face -Z: w = 5, (0.38095..., 0.79761...)
        lambda out, err, d: _csv_row(out)[3].startswith("0.38095") and _csv_row(out)[4].startswith("0.79761")
        and _csv_row(out)[5] == "5",
    ("eval.md", "uvtk eval --s object_linear:1,2,3,4 --point 1,1,1"):  # s = x + 2y + 3z + 4 = 10
        lambda out, err, d: _csv_row(out)[3] == "10",
    ("benchmarks.md", "/usr/bin/time -v uvtk map tri.obj -o out.obj"):  # "Maximum resident set size"
        lambda out, err, d: "Maximum resident set size" in err,
    ("commands.md", "uvtk map meshes/cube.obj --projector cube -o cube_cross.obj"):  # "the cross layout"
        lambda out, err, d: (d / "cube_cross.obj").exists(),
}
# Blocks of output that show no command: (document, the block's first line) -> the commands that
# print it (run in a fresh folder prepared as above) and their exit status, or a reason to skip.
OUTPUT_BLOCKS = {
    ("commands.md", "uvtk map: 482 vertices, 960 faces"): (
        "uvtk map meshes/sphere_latlong.obj -o a.obj; uvtk map meshes/torus.obj --projector cylinder -o b.obj", 0),
    ("commands.md", "Ranked by verdict, then by L2 stretch"): ("uvtk compare knot.obj --write-best best.obj", 0),
    ("check.md", "uvtk check: gpu.png against meshes/icosphere.obj"): (
        "O='--projector sphere --filter linear_mipmap_linear --texture checker:64:8 --size 320x240'; "
        "uvtk render meshes/icosphere.obj $O --uv-offset 0.0078125,0 -o gpu.png -q && "
        "uvtk check meshes/icosphere.obj $O --image gpu.png", 1),
    ("robustness.md", "reading huge.obj: 826.8/1128.9 MB"): "the 20 M-triangle run above (skipped)",
}

# Examples in the prose (inline code), chiefly the failing ones: (document, the text quoted from it,
# the command that shows it, its exit status, lines it prints). The quoted text must be in the
# document as it stands, so that a change there fails here until the entry follows.
INLINE = [
    ("README.md", "`uvtk: error: unknown option '--projektor'; did you mean '--projector'?`",
     "uvtk map meshes/torus.obj --projektor sphere -o x.obj", 2,
     ["uvtk: error: unknown option '--projektor'; did you mean '--projector'?"]),
    ("commands.md", "`uvtk eval --projector cube --convention notes --point=-0.2,0.5,-0.84` prints the notes' worked\n"
                  "example, the -Z face (w = 5) at (u, v) = (0.380952..., 0.797619...)",
     "uvtk eval --projector cube --convention notes --point=-0.2,0.5,-0.84", 0,
     ["-0.20000000000000001,0.5,-0.83999999999999997,0.380952...,0.797619...,5,1,ok,\"\""]),
    ("eval.md", "`<stdin>:2: error: expected 3 columns (x,y,z), found 2`",
     "printf '1,2,3\\n1,2\\n' | uvtk eval", 3, ["<stdin>:2: error: expected 3 columns (x,y,z), found 2"]),
    ("eval.md", "`<stdin>:3: error: expected a number in\ncolumn 2 (y), found 'abc'`",
     "printf '1,2,3\\n1,2,3\\n1,abc,3\\n' | uvtk eval", 3, ["<stdin>:3: error: expected a number in column 2 (y), found 'abc'"]),
    ("eval.md", "`printf 'x,y,z,nx,ny,nz,ex,ey,ez\\n0,0,1,0,0,1,1,0,2\\n' | uvtk eval --projector plane --omap reflection`",
     "printf 'x,y,z,nx,ny,nz,ex,ey,ez\\n0,0,1,0,0,1,1,0,2\\n' | uvtk eval --projector plane --omap reflection", 0,
     ["x,y,z,nx,ny,nz,ex,ey,ez,u,v,w,q,status,reason", "uvtk eval: 1 points, ..."]),
    ("check.md", "`FILE: error: expected texture coordinates (vt) on every face corner, found\nnone on face N`",
     "uvtk check meshes/torus.obj", 3,
     ["meshes/torus.obj: error: expected texture coordinates (vt) on every face corner, found none on face 0"]),
    ("robustness.md", "`big.pgm: error: image is 16384 x 16384, 268435456 pixels, more than the limit of 134217728` (exit 3",
     "printf 'P5\\n16384 16384\\n255\\n' > big.pgm && uvtk render meshes/torus.obj --projector sphere --texture big.pgm -o x.png", 3,
     ["big.pgm: error: image is 16384 x 16384, 268435456 pixels, more than the limit of 134217728"]),
]

# ---- reading the docs ----------------------------------------------------------------------

def _strip_comment(line):
    """The command and its trailing `# comment` (a # at a word's start, outside quotes)."""
    quote = None
    for i, c in enumerate(line):
        if quote:
            if c == quote:
                quote = None
        elif c in "'\"":
            quote = c
        elif c == "#" and (i == 0 or line[i - 1].isspace()):
            return line[:i].rstrip(), line[i + 1:].strip()
    return line.rstrip(), ""


def _blocks(doc):
    """(first line number, language or 'indented', [(line number, text)]) of each code block."""
    lines = doc.read_text(encoding="utf-8").splitlines()
    blocks, i = [], 0
    while i < len(lines):
        fence = re.match(r"^(\s*)(```+|~~~+)\s*(\S*)", lines[i])
        if fence:
            start, body = i + 1, []
            i += 1
            while i < len(lines) and not lines[i].strip().startswith(fence.group(2)):
                body.append((i + 1, lines[i][len(fence.group(1)):]))
                i += 1
            blocks.append((start, fence.group(3).lower(), body))
        elif lines[i].startswith("    ") and (i == 0 or not lines[i - 1].strip()):
            start, body = i + 1, []
            while i < len(lines) and (lines[i].startswith("    ") or not lines[i].strip()):
                body.append((i + 1, lines[i][4:]))
                i += 1
            while body and not body[-1][1].strip():
                body.pop()
            blocks.append((start, "indented", body))
            continue
        i += 1
    return blocks


def _is_command(text):
    return bool(COMMAND.search(text)) and not OUTPUT_LINE.match(text)


def _examples():
    """The examples (dicts: doc, line, command, comment, expected output lines, prefix of shell
    variables, block: the block's items in order) and the output blocks that show no command."""
    examples, output_blocks = [], []
    for doc in DOCS:
        assignments = []  # the document's shell variables so far
        for start, lang, body in _blocks(doc):
            if lang in NOT_SHELL:
                continue
            prompt = any(text.startswith("$ ") for _, text in body)
            block, current, k = [], None, 0
            while k < len(body):
                lineno, text = body[k]
                while text.endswith("\\") and k + 1 < len(body):  # continuation lines
                    k += 1
                    text = text[:-1].rstrip() + " " + body[k][1].strip()
                k += 1
                if prompt and not text.startswith("$ "):
                    if current is not None:
                        current["expected"].append(text)  # a console block: output up to the next prompt
                    continue
                raw = text[2:] if prompt else text
                command, comment = _strip_comment(raw.strip())
                heredoc = HEREDOC.match(command)
                if heredoc:  # a file the block writes: cat > FILE <<'EOF' ... EOF
                    content = []
                    while k < len(body) and body[k][1].strip() != heredoc.group(2):
                        content.append(body[k][1])
                        k += 1
                    k += 1
                    block.append({"kind": "file", "name": heredoc.group(1), "text": "\n".join(content) + "\n"})
                    current = None
                elif ASSIGNMENT.match(command) and not _is_command(command):
                    assignments.append(command)
                elif _is_command(command):
                    current = {"kind": "example", "doc": doc.name, "line": lineno, "command": command,
                               "comment": comment, "expected": [], "prefix": list(assignments), "block": block}
                    block.append(current)
                    examples.append(current)
                elif OUTPUT_LINE.match(text) and current is not None:
                    current["expected"].append(text)
                elif not command and comment and text[:1].isspace() and current is not None:
                    current["comment"] += " " + comment  # a comment continued under its command
                elif text.strip():
                    current = None  # another program's line
            if not block and any(OUTPUT_LINE.match(text) for _, text in body):
                output_blocks.append({"doc": doc.name, "line": start, "lines": [t for _, t in body], "first": body[0][1]})
    return examples, output_blocks


def _lookup(table, example, prefix=False):
    for (doc, command), value in table.items():
        if doc == example["doc"] and (example["command"].startswith(command) if prefix else example["command"] == command):
            return value
    return None


def _id(example):
    return f"{example['doc']}:{example['line']}"


EXAMPLES, OUTPUT_ONLY = _examples()
_BINARY = _find_binary()


def _skip_reason(example):
    required = _lookup(REQUIRES, example, prefix=True)
    if required and not shutil.which(required):
        return f"needs {required} (not a dependency of the project)"
    return _lookup(SKIP, example, prefix=True)


def _param(example):
    marks = []
    if _skip_reason(example):
        marks.append(pytest.mark.skip(reason=_skip_reason(example)))
    elif _lookup(XFAIL, example, prefix=True):
        marks.append(pytest.mark.xfail(reason=_lookup(XFAIL, example, prefix=True), strict=True))
    return pytest.param(example, id=_id(example), marks=marks)


# ---- comparing output ----------------------------------------------------------------------

def _pattern(line):
    """A regular expression for one line of expected output: times may differ, `...` is any text."""
    parts = re.split(r"(\.\.\.|\d+(?:\.\d+)? ms\b)", line.rstrip())
    return re.compile("".join(".*" if p == "..." else r"\d+(?:\.\d+)? ms" if p.endswith(" ms") else re.escape(p)
                              for p in parts))


def _assert_prints(expected, out, err, what):
    """Each expected line is one whole line of stdout or stderr, in order within each stream."""
    streams = {"stdout": out.splitlines(), "stderr": err.splitlines()}
    cursor = {"stdout": 0, "stderr": 0}
    for line in expected:
        if not line.strip() or re.fullmatch(r"[\s|]*\.\.\.[\s|]*", line):
            continue  # a gap: any lines
        pattern = _pattern(line)
        for name, lines in streams.items():
            found = next((i for i in range(cursor[name], len(lines)) if pattern.fullmatch(lines[i].rstrip())), None)
            if found is not None:
                cursor[name] = found + 1
                break
        else:
            pytest.fail(f"{what}: the text shows\n  {line}\nbut the program printed\n--- stdout\n{out}--- stderr\n{err}")


# ---- running -------------------------------------------------------------------------------

def _environment(binary):
    env = dict(os.environ)
    env["PATH"] = f"{binary.parent}{os.pathsep}{env.get('PATH', '')}"
    return env


def _runner(folder, env, prefix):
    def run(script, check=True):
        body = "\n".join([*STAND_INS.values(), *prefix, "set -o pipefail", script])
        done = subprocess.run(["bash", "-c", body], cwd=folder, env=env, capture_output=True, text=True,
                              stdin=subprocess.DEVNULL, timeout=300)
        if check:
            assert done.returncode == 0, f"preparing: {script}\n{done.stdout}{done.stderr}"
        return done
    return run


def _prepare(folder, example, run):
    """Makes the placeholder files the example names that are not there yet."""
    recipes = {**FILES, **(_lookup(FILES_FOR, example) or {})}
    for name in sorted({token.strip("'\"") for token in re.split(r"[\s<>=]+", example["command"])}):
        path = folder / name.rstrip("/")
        if name in recipes and not path.exists():
            recipes[name](folder, name.rstrip("/"), run)


def _fresh_folder(folder, meshes_dir):
    folder.mkdir(parents=True, exist_ok=True)
    shutil.copytree(meshes_dir, folder / "meshes", ignore=shutil.ignore_patterns("*.cpp", "*.h", "CMakeLists.txt"))
    return folder


_RESULTS = {}  # id(block) -> {id(example): CompletedProcess, "folder": path}


def _run_block(example, env, meshes_dir, tmp_path_factory):
    """Runs the example's block once, in order in one folder (each example's inputs are there)."""
    key = id(example["block"])
    if key not in _RESULTS:
        folder = _fresh_folder(tmp_path_factory.mktemp("block"), meshes_dir)
        results = {"folder": folder}
        for item in example["block"]:
            if item["kind"] == "file":
                (folder / item["name"]).write_text(item["text"])
            elif not _skip_reason(item):
                run = _runner(folder, env, item["prefix"])
                try:
                    _prepare(folder, item, run)
                except pytest.skip.Exception as skipped:
                    results[id(item)] = skipped
                    continue
                results[id(item)] = run(item["command"], check=False)
        _RESULTS[key] = results
    return _RESULTS[key]


@pytest.mark.parametrize("example", [_param(e) for e in EXAMPLES])
def test_doc_example(example, uvtk_bin, meshes_dir, tmp_path_factory):
    results = _run_block(example, _environment(uvtk_bin), meshes_dir, tmp_path_factory)
    done = results[id(example)]
    if isinstance(done, pytest.skip.Exception):
        pytest.skip(str(done))
    where = f"{_id(example)}: {example['command']}"
    status = _lookup(EXIT, example) or 0
    assert done.returncode == status, f"{where}: exit {done.returncode}, not {status}\n--- stdout\n{done.stdout}--- stderr\n{done.stderr}"
    _assert_prints(example["expected"], done.stdout, done.stderr, where)
    claim = _lookup(CLAIMS, example)
    if claim:
        assert claim(done.stdout, done.stderr, results["folder"]), (
            f"{where}: not what the text says ({example['comment']})\n--- stdout\n{done.stdout}--- stderr\n{done.stderr}")


@pytest.mark.parametrize("block", OUTPUT_ONLY, ids=lambda b: f"{b['doc']}:{b['line']}")
def test_doc_output_block(block, uvtk_bin, meshes_dir, tmp_path):
    source = next((v for (doc, first), v in OUTPUT_BLOCKS.items() if doc == block["doc"] and block["first"].startswith(first)), None)
    assert source is not None, f"{block['doc']}:{block['line']}: output that names no command: say in OUTPUT_BLOCKS what prints it"
    if isinstance(source, str):
        pytest.skip(source)
    script, status = source
    folder = _fresh_folder(tmp_path / "run", meshes_dir)
    run = _runner(folder, _environment(uvtk_bin), [])
    _prepare(folder, {"doc": block["doc"], "command": script}, run)
    done = run(script, check=False)
    assert done.returncode == status, f"{script}: exit {done.returncode}, not {status}\n{done.stdout}{done.stderr}"
    _assert_prints(block["lines"], done.stdout, done.stderr, f"{block['doc']}:{block['line']}: {script}")


@pytest.mark.parametrize("doc, quoted, script, status, lines", [pytest.param(*e, id=f"{e[0]}:{e[2][:40]}") for e in INLINE])
def test_doc_inline_example(doc, quoted, script, status, lines, uvtk_bin, meshes_dir, tmp_path):
    text = next(d for d in DOCS if d.name == doc).read_text(encoding="utf-8")
    assert quoted in text, f"{doc} no longer says {quoted!r}: update INLINE"
    folder = _fresh_folder(tmp_path / "run", meshes_dir)
    done = _runner(folder, _environment(uvtk_bin), [])(script, check=False)
    assert done.returncode == status, f"{script}: exit {done.returncode}, not {status}\n{done.stdout}{done.stderr}"
    _assert_prints(lines, done.stdout, done.stderr, f"{doc}: {script}")


def test_tables_match_the_docs():
    """Every example is found, every entry of the tables names one (no stale entry), and the
    program is spelled `uvtk` in every example."""
    assert len(EXAMPLES) > 50 and len({_id(e) for e in EXAMPLES}) == len(EXAMPLES)
    for table, prefix in ((SKIP, True), (REQUIRES, True), (XFAIL, True), (EXIT, False), (CLAIMS, False), (FILES_FOR, False)):
        for key in table:
            assert any(_lookup({key: 1}, e, prefix) for e in EXAMPLES), f"no example in the docs is {key}"
    for doc, first in OUTPUT_BLOCKS:
        assert any(b["doc"] == doc and b["first"].startswith(first) for b in OUTPUT_ONLY), f"no output block {doc}: {first}"
    for doc in DOCS:
        for start, lang, body in _blocks(doc):
            for lineno, text in body:
                assert lang in NOT_SHELL or not re.search(r"(^|\s)(\./)?build/apps/uvtk/uvtk\b", text), (
                    f"{doc.name}:{lineno}: the program is `uvtk` in the docs' examples")
