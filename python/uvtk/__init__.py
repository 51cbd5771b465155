"""uvtk: texture coordinates for triangle meshes, and proof that they are right.

The Python face of the C++ library (docs/python.md): the numbers are those of the `uvtk` command
line, bit for bit. Options are keywords named as the command line's options (cap_angle=30 is
--cap-angle 30). map's and texgen's signatures list every keyword with its type, default, choices
and the meaning `uvtk map --help` shows: they are built here from the library's one option table
(uvtk._uvtk._map_options()), and __init__.pyi is generated from the same table (uvtk._stubgen).
"""
import collections.abc as _abc
import difflib as _difflib
import inspect as _inspect
import os as _os
import re as _re
import typing as _typing

try:  # a dependency (the wheel's Requires-Dist): missing, `import uvtk` says so at once
    import numpy as _np
    import numpy.typing as _npt  # eval's signature: numpy.typing.ArrayLike
except ModuleNotFoundError as _error:
    # The stubs are made at build time by an interpreter that may have no numpy (pip's build
    # isolation with an index): python/CMakeLists.txt sets UVTK_STUBGEN for it.
    if not _os.environ.get("UVTK_STUBGEN"):
        raise ModuleNotFoundError("uvtk needs numpy (a dependency of the package): pip install numpy",
                                  name="numpy") from _error
    _np = None

from . import _uvtk
from ._uvtk import *  # noqa: F401,F403  (every public name of the extension)
from ._uvtk import __version__  # noqa: F401

# The extension's classes, exceptions and functions are uvtk's: their names in messages, reprs and
# pickles are uvtk.Mesh, not uvtk._uvtk.Mesh.
for _name in dir(_uvtk):
    _object = getattr(_uvtk, _name)
    if not _name.startswith("_") and getattr(_object, "__module__", None) == _uvtk.__name__:
        try:
            _object.__module__ = __name__
        except (AttributeError, TypeError):
            pass
del _name, _object


# ---- signatures from the option table ----

# The keywords that name a file to write (report's and compare's json=, html=, ...): a str or a path.
_FILE_KEYWORDS = ("json", "html", "markdown", "sheet")
_NUMBERS_PLACEHOLDER = _re.compile(r"^[A-Z](,[A-Z])+(\|\w+)?$|^[A-Z]x[A-Z]$")
_NUMBERS_TEXT = _re.compile(r"^-?[0-9.]+([,x]-?[0-9.]+)+$")


def _annotation(option):
    """The Python type of an option of the table (kind, choices, optional)."""
    kind = option["kind"]
    if option["choices"]:
        annotation = _typing.Literal[tuple(option["choices"])]
    elif kind == "bool":
        annotation = bool
    elif kind == "int":
        annotation = int
    elif kind == "float":
        annotation = float
    elif kind.startswith("float["):
        annotation = _abc.Sequence[float]
    elif kind == "str[]":
        annotation = _abc.Sequence[str]
    elif kind == "float|auto":
        annotation = _typing.Union[float, _typing.Literal["auto"]]
    elif kind == "int|int[2]":
        annotation = _typing.Union[int, _abc.Sequence[int]]
    elif option["keyword"] in _FILE_KEYWORDS:
        annotation = _typing.Union[str, _os.PathLike]
    elif option["keyword"] == "size":  # size=(w, h) is written "WxH" (the extension's commandLine)
        annotation = _typing.Union[str, _abc.Sequence[int]]
    elif _NUMBERS_PLACEHOLDER.match(option.get("type_name", "")) or _NUMBERS_TEXT.match(option["default"]):
        # a value the command line spells as numbers in text ("1024,1024", L,R,B,T|auto): text or the numbers
        annotation = _typing.Union[str, _abc.Sequence[float]]
    else:
        annotation = str
    return _typing.Optional[annotation] if _none_allowed(option) else annotation


def _none_allowed(option):
    """None means "not given" for the optional options but a choice (fit: None is a TypeError; its
    default is --help's, 'bbox'), and for a choice without a default (texgen's mode)."""
    if option["optional"] and not option["choices"]:
        return True
    if option["choices"]:
        return not option["default"]
    return not option["default"] and option["kind"] not in ("str", "bool", "str[]")


def _default(option):
    """The option's default as --help shows it, as a Python value (None where it may be left unset)."""
    if _none_allowed(option):
        return None
    kind, text = option["kind"], option["default"]
    if kind == "bool":
        return False
    if kind == "str[]":
        return ()
    if kind == "int":  # report's texture_size shows "1024,1024" and takes N
        values = {int(x) for x in text.split(",")}
        return values.pop() if len(values) == 1 else text
    if kind == "float":
        return float(text)
    if kind.startswith("float["):
        return tuple(float(x) for x in text.split(","))
    if kind == "int|int[2]":
        values = tuple(int(x) for x in text.split(","))
        return values[0] if len(set(values)) == 1 else values
    return text


def _keyword_doc(option):
    """One keyword's entry: 'cap_angle: float = 45.0' and its meaning, indented."""
    annotation = _inspect.formatannotation(_annotation(option))
    text = f"{option['keyword']}: {annotation} = {_default(option)!r}\n    {option['help']}"
    if option["choices"]:
        text += f" (one of: {', '.join(option['choices'])})"
    return text


def _signed(function, table, doc, first, returns=None):
    """`function` with a signature (first positional parameters, then the table's keywords) and a
    docstring listing every keyword."""
    parameters = [_inspect.Parameter(name, _inspect.Parameter.POSITIONAL_OR_KEYWORD, default=default, annotation=kind)
                  for name, default, kind in first]
    parameters += [_inspect.Parameter(o["keyword"], _inspect.Parameter.KEYWORD_ONLY, default=_default(o),
                                      annotation=_annotation(o)) for o in table]
    function.__signature__ = _inspect.Signature(parameters, return_annotation=returns or Mapping)
    function.__doc__ = doc + "\n\nKeywords (as `uvtk " + function.__name__ + " --help` shows them):\n\n" + \
        "\n".join(_keyword_doc(o) for o in table)
    function.__module__ = __name__
    return function


MAP_OPTIONS = tuple(_uvtk._map_options())
TEXGEN_OPTIONS = tuple(_uvtk._texgen_options())
REPORT_OPTIONS = tuple(_uvtk._report_options())
RENDER_OPTIONS = tuple(_uvtk._render_options())
COMPARE_OPTIONS = tuple(_uvtk._compare_options())


def _eval_options():
    """eval's keywords: the names the point API reads (uvtk::point::parameterNames), each as map's
    table (the projector's) or texgen's describes it, and threads; two differ from those tables:
    fit is none unless given (points have no mesh to fit to), and the texgen shortcut is `texgen`,
    which also takes the linear modes (texgen's own `mode` leaves those to s and t)."""
    names = set(_uvtk._eval_parameter_names()) | {"threads"}
    table, seen = [], set()
    for option in MAP_OPTIONS + TEXGEN_OPTIONS:
        if option["name"] in names and option["name"] not in seen:
            seen.add(option["name"])
            table.append(dict(option, default="none") if option["name"] == "fit" else option)
        elif option["name"] == "mode":
            shortcut = dict(option, name="texgen", keyword="texgen",
                            choices=["object_linear", "eye_linear"] + list(option["choices"]),
                            help="Texture coordinates by GL texgen: s, t (and r for normal_map, reflection_map) "
                                 "in this mode, under the view of eye, center and up; s, t, r, q override it")
    return tuple(table + [shortcut])


EVAL_OPTIONS = _eval_options()


def map(mesh, options=None, **keywords):  # noqa: A001 (uvtk.map, as `uvtk map`)
    return _uvtk.map(mesh, options, **keywords)


def _nearest(keywords, table):
    """A mistyped keyword is a ValueError naming the nearest one, as map's are ("cap_angel: not a
    parameter here; did you mean cap_angle?"); others go on to the command line's parser."""
    known = [o["keyword"] for o in table]
    for keyword in keywords:
        if keyword not in known:
            near = _difflib.get_close_matches(keyword, known, n=1, cutoff=0.6)
            if near:
                raise ValueError(f"{keyword}: not a parameter here; did you mean {near[0]}?")


def eval(points, normals=None, mesh=None, **keywords):  # noqa: A001 (uvtk.eval, as `uvtk eval`)
    return _uvtk.eval(points, normals, mesh, **keywords)


def read_mesh(path: _typing.Union[str, _os.PathLike], with_warnings: bool = False, threads: int = 0):
    return _uvtk.read_mesh(path, with_warnings, threads)


def write_mesh(path: _typing.Union[str, _os.PathLike], mesh, m=None,
               uv_digits: _typing.Literal["double", "float"] = "double", write_w: bool = False, ascii: bool = False,
               header: str = "", threads: int = 0) -> None:
    return _uvtk.write_mesh(path, mesh, m, uv_digits, write_w, ascii, header, threads)


def texgen(mesh, options=None, **keywords):
    _nearest(keywords, TEXGEN_OPTIONS)
    return _uvtk.texgen(mesh, options, **keywords)


def report(mesh, m, **keywords):
    _nearest(keywords, REPORT_OPTIONS)
    return _uvtk.report(mesh, m, **keywords)


def render(mesh, m, dtype="uint8", **keywords):
    _nearest(keywords, RENDER_OPTIONS)
    return _uvtk.render(mesh, m, dtype, **keywords)


def compare(mesh, **keywords):
    _nearest(keywords, COMPARE_OPTIONS)
    return _uvtk.compare(mesh, **keywords)


def _doc(function):
    """The extension's docstring without its first line (pybind11's signature)."""
    return function.__doc__.split("\n", 2)[-1].strip()


read_mesh.__doc__ = _doc(_uvtk.read_mesh)
write_mesh.__doc__ = _doc(_uvtk.write_mesh)
_MESH = ("mesh", _inspect.Parameter.empty, _typing.Optional[Mesh])
_ARRAY_LIKE = _npt.ArrayLike if _np else _typing.Any
_MAPPING = ("m", _inspect.Parameter.empty, Mapping)
_signed(report, REPORT_OPTIONS, _doc(_uvtk.report), [_MESH, _MAPPING], dict)
_signed(render, RENDER_OPTIONS, _doc(_uvtk.render),
        [_MESH, _MAPPING, ("dtype", "uint8", _typing.Literal["uint8", "float32"])],
        _np.ndarray if _np else "numpy.ndarray")
_signed(compare, COMPARE_OPTIONS, _doc(_uvtk.compare), [("mesh", _inspect.Parameter.empty, Mesh)], dict)
_signed(map, MAP_OPTIONS, _uvtk.map.__doc__.split("\n", 2)[-1].strip(),
        [("mesh", _inspect.Parameter.empty, Mesh), ("options", None, _typing.Optional[MapOptions])])
_signed(eval, EVAL_OPTIONS, _doc(_uvtk.eval),
        [("points", _inspect.Parameter.empty, _ARRAY_LIKE), ("normals", None, _typing.Optional[_ARRAY_LIKE]),
         ("mesh", None, _typing.Optional[Mesh])],
        EvalResult)
_signed(texgen, TEXGEN_OPTIONS, _uvtk.texgen.__doc__.split("\n", 2)[-1].strip(),
        [("mesh", _inspect.Parameter.empty, Mesh), ("options", None, _typing.Optional[TexgenOptions])])

from ._layouts import *  # noqa: E402,F401,F403
from ._batch import *  # noqa: E402,F401,F403
