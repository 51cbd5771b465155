// The Python module uvtk (docs/python.md): a thin face over the public C++ libraries, uvtk/uvtk.h
// and uvtk/point.h, and the process's cancellation request (core/cancel.h) for Ctrl-C. Options
// arrive as keywords and become the command line's words, so every option of the CLI works here,
// parsed and rejected with the CLI's messages.
// Arrays go out as read-only numpy views of the C++ object's vectors, which the view keeps alive.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <future>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "core/cancel.h"
#include "core/parallel.h"
#include "uvtk/point.h"
#include "uvtk/uvtk.h"

namespace py = pybind11;
namespace api = uvtk::api;

namespace {

// A mapping and the uvtk.Mesh it was made from: with --seam cut the mapping's own mesh has more
// faces, and report(mesh, m) must still accept the mesh the user passed.
struct PyMapping {
  api::Mapping mapping;
  py::object input;
};

// What uvtk.eval returns: one entry per point.
struct EvalResult {
  py::object u, v, w, q, status;
  py::list reason;
  std::string mapping;
  py::object triplanarUv, triplanarWeights;  // --projector triplanar: (..., 3, 2) and (..., 3); else None

  // dict(result)'s keys: the triplanar arrays only when there are some.
  std::vector<std::string> keys() const {
    std::vector<std::string> out{"u", "v", "w", "q", "status", "reason"};
    if (!triplanarUv.is_none()) out.insert(out.end(), {"triplanar_uv", "triplanar_weights"});
    return out;
  }
};

using Shape = std::vector<py::ssize_t>;

Shape cStrides(const Shape& shape, py::ssize_t itemSize) {
  Shape strides(shape.size(), itemSize);
  for (std::size_t i = shape.size(); i-- > 1;) strides[i - 1] = strides[i] * shape[i];
  return strides;
}

// A read-only array over `data` that keeps `owner` alive.
template <class T>
py::array view(py::handle owner, const T* data, const Shape& shape) {
  py::array array(py::dtype::of<T>(), shape, cStrides(shape, sizeof(T)), data, owner);
  array.attr("flags").attr("writeable") = false;
  return array;
}

// An array that owns `values` (moved, not copied): a capsule deletes them with the array.
template <class T>
py::array owning(std::vector<T>&& values, const Shape& shape) {
  auto* owned = new std::vector<T>(std::move(values));
  const py::capsule capsule(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array(py::dtype::of<T>(), shape, cStrides(shape, sizeof(T)), owned->data(), capsule);
}

py::ssize_t count(std::size_t n) { return py::ssize_t(n); }

// ---- arguments ----

// The type of `object` as Python spells it: int, numpy.ndarray, uvtk.Mesh.
std::string typeName(py::handle object) {
  const py::handle type = py::type::handle_of(object);
  const std::string module = py::str(type.attr("__module__")), name = py::str(type.attr("__qualname__"));
  return module == "builtins" ? name : module + "." + name;
}

// "FUNCTION(): ARGUMENT: expected EXPECTED, found TYPE", in place of pybind11's "Unable to cast".
py::type_error argumentTypeError(const char* function, const char* argument, const std::string& expected,
                                 py::handle found) {
  return py::type_error(std::string(function) + "(): " + argument + ": expected " + expected + ", found " +
                        typeName(found));
}

template <class T>
const T& argumentOf(const char* function, const char* argument, const char* expected, py::handle object) {
  if (!py::isinstance<T>(object)) throw argumentTypeError(function, argument, expected, object);
  return object.cast<const T&>();
}

const api::Mesh& meshOf(const char* function, py::handle object) {
  return argumentOf<api::Mesh>(function, "mesh", "a uvtk.Mesh", object);
}

// A path as the system takes it: a str, bytes or os.PathLike, encoded as os.fsencode encodes it.
std::string pathOf(const char* function, py::handle object) {
  if (!py::isinstance<py::str>(object) && !py::isinstance<py::bytes>(object) && !py::hasattr(object, "__fspath__"))
    throw argumentTypeError(function, "path", "a str, bytes or os.PathLike", object);
  const std::string path = py::bytes(py::module_::import("os").attr("fsencode")(object));
  if (path.find('\0') != std::string::npos)
    throw py::value_error(std::string(function) + "(): path: holds a NUL character");
  return path;
}

// ---- keywords -> typed parameters ----

// numpy scalars and arrays become Python numbers and lists, paths (os.PathLike) strings.
py::object plain(py::handle value) {
  if (py::hasattr(value, "__fspath__")) return py::module_::import("os").attr("fspath")(value);
  if (!py::isinstance<py::str>(value) && py::hasattr(value, "tolist")) return value.attr("tolist")();
  return py::reinterpret_borrow<py::object>(value);
}

// The keywords as typed parameters, each named by its keyword in messages: True and False are
// booleans (and so are numpy's), int an integer, float a number, a str or os.PathLike a text, a
// sequence of numbers a list of numbers, of str a list of texts, None nothing. The engine decides
// what each parameter takes (ParameterTypeError -> TypeError naming the keyword).
api::Parameters keywordParameters(const py::kwargs& kwargs) {
  api::Parameters parameters;
  parameters.face = api::Parameters::Face::Keyword;
  for (const auto& [key, rawValue] : kwargs) {
    const std::string keyword = key.cast<std::string>();
    std::string name = keyword;
    for (char& c : name) c = c == '_' ? '-' : c;
    const py::object value = plain(rawValue);
    api::ParameterValue typed;
    const auto kindError = [&] {
      return py::type_error(keyword + ": expected a bool, a number, a str or a sequence of numbers or of str, got " +
                            py::repr(rawValue).cast<std::string>());
    };
    if (value.is_none()) {
    } else if (py::isinstance<py::bool_>(value)) {
      typed = value.cast<bool>();
    } else if (py::isinstance<py::int_>(value)) {
      try {
        typed = value.cast<std::int64_t>();
      } catch (const py::cast_error&) {
        throw py::value_error(keyword + ": " + py::repr(value).cast<std::string>() + " is out of range");
      }
    } else if (py::isinstance<py::float_>(value)) {
      typed = value.cast<double>();
    } else if (py::isinstance<py::str>(value)) {
      typed = value.cast<std::string>();
    } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
      const py::sequence items = value;
      // An empty sequence is an empty list of texts: fail_on=() (the signature's default) is none.
      if (items.size() == 0 || py::isinstance<py::str>(items[0])) {
        std::vector<std::string> texts;
        for (const py::handle item : items) {
          if (!py::isinstance<py::str>(item)) throw kindError();
          texts.push_back(item.cast<std::string>());
        }
        typed = std::move(texts);
      } else {
        std::vector<double> numbers;
        for (const py::handle item : items) {
          if (py::isinstance<py::bool_>(item) || !(py::isinstance<py::int_>(item) || py::isinstance<py::float_>(item)))
            throw kindError();
          numbers.push_back(item.cast<double>());
        }
        typed = std::move(numbers);
      }
    } else {
      throw kindError();
    }
    parameters.values.push_back({name, std::move(typed), keyword});
  }
  return parameters;
}

// The typed parameters of either an options object or keywords (not both: which would win is unclear).
template <class Options>
api::Parameters parametersFrom(const char* function, const char* expected, const py::object& options,
                               const py::kwargs& kwargs) {
  if (!options.is_none() && kwargs.size() > 0)
    throw py::type_error("give the options either as an options object or as keywords, not both");
  if (!options.is_none()) return argumentOf<Options>(function, "options", expected, options).parameters();
  return keywordParameters(kwargs);
}

// ---- long calls ----

// How often a call waiting for the library looks for Ctrl-C.
constexpr std::chrono::milliseconds kSignalCheckInterval{50};

// Runs `work` on a thread of its own with the GIL released, and waits for it in slices, running
// Python's signal handlers between them: on Ctrl-C (or any exception a handler raises) the library
// is asked to stop (its loops throw uvtk::Cancelled), the thread is joined, and the handler's
// exception is raised. What `work` throws is rethrown here, where the module's translation applies.
// `work` must not touch Python objects.
template <class Work>
auto interruptible(Work&& work) -> decltype(work()) {
  std::future<decltype(work())> done;
  try {
    done = std::async(std::launch::async, [&work] { return work(); });
  } catch (const std::system_error&) {
    // The system has no thread to give (memory, limits): the work runs here, beyond Ctrl-C's reach.
    py::gil_scoped_release release;
    return work();
  }
  for (;;) {
    {
      py::gil_scoped_release release;
      if (done.wait_for(kSignalCheckInterval) == std::future_status::ready) break;
    }
    if (PyErr_CheckSignals() != 0) {
      py::error_already_set interrupt;
      {
        py::gil_scoped_release release;
        uvtk::requestCancel();
        done.wait();
        uvtk::clearCancel();
      }
      throw interrupt;
    }
  }
  return done.get();
}

// ---- meshes ----

std::string shapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i) text += (i ? ", " : "") + std::to_string(array.shape(i));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

void requireShape(const char* what, const py::array& array, const Shape& shape, const char* expected) {
  bool ok = array.ndim() == py::ssize_t(shape.size());
  for (std::size_t i = 0; ok && i < shape.size(); ++i) ok = shape[i] < 0 || array.shape(py::ssize_t(i)) == shape[i];
  if (!ok) throw py::value_error(std::string(what) + ": expected an array of shape " + expected + ", got " + shapeText(array));
}

// Arrays are converted by these types' constructors, which raise numpy's error (MemoryError when
// the copy does not fit); their ensure() clears it and returns null.
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

py::array asArray(const py::object& object) { return py::module_::import("numpy").attr("asarray")(object); }

// A mesh holds at most this many vertices, faces and corners: its indices are int32.
constexpr py::ssize_t kMaxMeshCount = std::numeric_limits<int>::max();

// Refused before any copy is made: ValueError "WHAT: N UNIT, more than ...".
void requireMeshCount(const char* what, py::ssize_t n, const char* unit) {
  if (n > kMaxMeshCount)
    throw py::value_error(std::string(what) + ": " + std::to_string(n) + " " + unit + ", more than the " +
                          std::to_string(kMaxMeshCount) + " a mesh holds (its indices are int32)");
}

// TypeError naming `what` unless `array` holds real numbers: floating or integer (bool, complex,
// object and text arrays are refused; forcecast would drop an imaginary part or parse text).
void requireRealNumbers(const char* what, const py::array& array) {
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error(std::string(what) + ": expected real numbers (a floating or integer array), found dtype " +
                         py::str(array.dtype()).cast<std::string>());
}

// Triangles of any integer dtype, as int32 (an index that does not fit is a ValueError).
std::vector<api::Triangle> trianglesFrom(const py::object& object) {
  const py::array any = asArray(object);
  const char kind = any.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw py::type_error("triangles: expected an integer array, found dtype " +
                         py::str(any.dtype()).cast<std::string>());
  requireShape("triangles", any, {-1, 3}, "(F, 3)");
  requireMeshCount("triangles", any.shape(0), "faces");
  const Indices indices(any);
  std::vector<api::Triangle> triangles(std::size_t(indices.shape(0)));
  const std::int64_t* data = indices.data();
  for (std::size_t i = 0; i < triangles.size() * 3; ++i) {
    if (data[i] < std::numeric_limits<int>::min() || data[i] > std::numeric_limits<int>::max() ||
        (kind == 'u' && data[i] < 0))
      throw py::value_error("triangles: face " + std::to_string(i / 3) + " has index " +
                            py::str(any.attr("flat")[py::int_(i)]).cast<std::string>() + ", beyond int32");
    triangles[i / 3][i % 3] = int(data[i]);
  }
  return triangles;
}

api::Mesh meshFrom(const py::object& positionsObject, const py::object& triangles, const py::object& uv,
                   const py::object& normals) {
  const py::array positionsGiven = asArray(positionsObject);
  requireRealNumbers("positions", positionsGiven);
  requireShape("positions", positionsGiven, {-1, 3}, "(N, 3)");
  requireMeshCount("positions", positionsGiven.shape(0), "vertices");
  const Doubles positions(positionsGiven);
  api::Mesh mesh;
  mesh.positions.resize(std::size_t(positions.shape(0)));
  std::copy_n(positions.data(), mesh.positions.size() * 3, mesh.positions.data()->data());
  mesh.triangles = trianglesFrom(triangles);
  const py::ssize_t faces = count(mesh.triangles.size());
  if (!uv.is_none()) {
    const py::array cornersGiven = asArray(uv);
    requireRealNumbers("uv", cornersGiven);
    requireShape("uv", cornersGiven, {faces, 3, 2}, "(F, 3, 2)");
    requireMeshCount("uv", 3 * faces, "corners");
    const Doubles corners(cornersGiven);
    mesh.cornerTexcoords.assign(mesh.triangles.size(), {-1, -1, -1});
    for (std::size_t c = 0; c < mesh.triangles.size() * 3; ++c) {
      const double u = corners.data()[2 * c], v = corners.data()[2 * c + 1];
      if (std::isnan(u) && std::isnan(v)) continue;  // this corner has none
      mesh.cornerTexcoords[c / 3][c % 3] = int(mesh.texcoords.size());
      mesh.texcoords.push_back({u, v, 0.0});
    }
  }
  if (!normals.is_none()) {
    const py::array normalsGiven = asArray(normals);
    requireRealNumbers("normals", normalsGiven);
    const bool perVertex = normalsGiven.ndim() == 2;
    if (perVertex) {
      requireShape("normals", normalsGiven, {count(mesh.positions.size()), 3}, "(N, 3) or (F, 3, 3)");
    } else {
      requireShape("normals", normalsGiven, {faces, 3, 3}, "(N, 3) or (F, 3, 3)");
      requireMeshCount("normals", 3 * faces, "corners");
    }
    const Doubles given(normalsGiven);
    if (perVertex) {
      mesh.normals.resize(mesh.positions.size());
      mesh.cornerNormals = mesh.triangles;
    } else {
      mesh.normals.resize(mesh.triangles.size() * 3);
      mesh.cornerNormals.resize(mesh.triangles.size());
      for (std::size_t c = 0; c < mesh.normals.size(); ++c) mesh.cornerNormals[c / 3][c % 3] = int(c);
    }
    std::copy_n(given.data(), mesh.normals.size() * 3, mesh.normals.data()->data());
  }
  api::checkMesh(mesh);
  return mesh;
}

// A corner table's values as (F, 3, K), NaN where a corner has none; None without a table.
py::object perCorner(const std::vector<api::Vector3>& values, const std::vector<api::Triangle>& corners, std::size_t k) {
  if (corners.empty()) return py::none();
  py::array_t<double> array(Shape{count(corners.size()), 3, count(k)});
  double* out = array.mutable_data();
  for (std::size_t c = 0; c < corners.size() * 3; ++c) {
    const int index = corners[c / 3][c % 3];
    for (std::size_t i = 0; i < k; ++i)
      out[c * k + i] = index >= 0 && std::size_t(index) < values.size() ? values[std::size_t(index)][i]
                                                                         : std::numeric_limits<double>::quiet_NaN();
  }
  return std::move(array);
}

py::dict warningsDict(const api::MeshWarnings& w) {
  py::dict d;
  d["degenerate_faces"] = w.degenerateFaces;
  d["unreferenced_vertices"] = w.unreferencedVertices;
  d["non_simple_polygons"] = w.nonSimplePolygons;
  d["first_non_simple_polygon_line"] = w.firstNonSimplePolygonLine;
  d["vertex_colours"] = w.vertexColours;
  d["parameter_vertices"] = w.parameterVertices;
  d["welded_corners"] = w.weldedCorners;
  d["skipped_primitives"] = w.skippedPrimitives;
  d["listed_invalid_uv_faces"] = w.listedInvalidUvFaces;
  return d;
}

// ---- mappings ----

py::object jsonLoads(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

py::dict verdictDict(const api::Verdict& verdict) {
  py::list reasons;
  for (const api::Reason& r : verdict.reasons) {
    py::dict reason;
    reason["rule"] = r.rule;
    reason["severity"] = r.severity;
    reason["value"] = r.value;
    reason["threshold"] = r.threshold;
    reason["faces"] = r.faces;
    reason["text"] = r.text;
    reasons.append(reason);
  }
  py::dict d;
  d["status"] = verdict.status;
  d["reasons"] = reasons;
  return d;
}

std::unique_ptr<PyMapping> wrap(api::Mapping&& mapping, py::object input) {
  return std::make_unique<PyMapping>(PyMapping{std::move(mapping), std::move(input)});
}

// The mapping, after checking that `mesh` is what it maps: the mesh it was made from, its own
// mesh, or a mesh of as many faces.
const api::Mapping& mappingFor(const char* function, py::handle mesh, py::handle mapping) {
  const PyMapping& m = argumentOf<PyMapping>(function, "m", "a uvtk.Mapping", mapping);
  if (mesh.is(m.input) || mesh.is_none()) return m.mapping;
  const api::Mesh& given = meshOf(function, mesh);
  if (&given != &m.mapping.mesh && given.triangles.size() != m.mapping.mesh.triangles.size())
    throw py::value_error(std::string(function) + ": the mesh has " + std::to_string(given.triangles.size()) +
                          " faces and the mapping's " + std::to_string(m.mapping.mesh.triangles.size()) +
                          ": pass the mesh the mapping was made from");
  return m.mapping;
}

api::WriteOptions writeOptions(const std::string& uvDigits, bool writeW, bool ascii, const std::string& header,
                               int threads) {
  if (threads < 0 || threads > 1024) throw py::value_error("write_mesh(): threads: expected 0 to 1024, got " + std::to_string(threads));
  api::WriteOptions options;
  options.header = header;
  options.threads = threads;
  options.uvDigits = uvDigits;
  options.writeW = writeW;
  options.ascii = ascii;
  return options;
}

// ---- single points ----

// eval's points a thread takes at a time, between two looks for a cancellation (parallelFor's).
constexpr std::size_t kPointsPerBlock = 4096;

EvalResult evaluate(const py::object& pointsObject, const py::object& normals, const py::object& mesh,
                    const py::kwargs& kwargs) {
  const py::array pointsGiven = asArray(pointsObject);
  requireRealNumbers("points", pointsGiven);
  if (pointsGiven.ndim() < 1 || pointsGiven.shape(pointsGiven.ndim() - 1) != 3)
    throw py::value_error("points: expected an array of shape (..., 3), got " + shapeText(pointsGiven));
  const Doubles points(pointsGiven);
  Shape shape(points.shape(), points.shape() + points.ndim() - 1);
  const std::size_t n = std::size_t(points.size() / 3);
  // One normal for every point (step 0) or one per point (step 3); without any, (0, 0, 0).
  std::optional<Doubles> normalArray;
  if (!normals.is_none()) {
    const py::array normalsGiven = asArray(normals);
    requireRealNumbers("normals", normalsGiven);
    if (normalsGiven.size() != 3 && normalsGiven.size() != points.size())
      throw py::value_error("normals: expected one normal (3,) or one per point " + shapeText(points) + ", got " +
                            shapeText(normalsGiven));
    normalArray.emplace(normalsGiven);
  }
  std::vector<uvtk::point::Vector3> positions;
  if (!mesh.is_none()) positions = meshOf("eval", mesh).positions;
  int threads = 0;  // the points spread over threads; the numbers do not depend on how many
  py::kwargs mappingKeywords;
  for (const auto& [key, value] : kwargs)
    if (key.cast<std::string>() == "threads") {
      if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value))
        throw py::type_error("threads: expected an int, got " + py::repr(value).cast<std::string>());
      threads = value.cast<int>();
      if (threads < 0 || threads > 1024) throw py::value_error("threads: expected 0 to 1024, got " + std::to_string(threads));
    } else {
      mappingKeywords[key] = value;
    }
  const std::vector<uvtk::point::Parameter> parameters = keywordParameters(mappingKeywords).values;

  py::array_t<double> u(shape), v(shape), w(shape), q(shape);
  py::array_t<std::uint8_t> status(shape);
  Shape uvShape = shape, weightShape = shape;
  uvShape.insert(uvShape.end(), {3, 2});
  weightShape.push_back(3);
  py::array_t<double> triplanarUv(uvShape), triplanarWeights(weightShape);
  std::vector<const char*> reasons(n);
  const double* p = points.data();
  const double* normal = normalArray ? normalArray->data() : nullptr;
  const std::size_t normalStep = normalArray && normalArray->size() != 3 ? 3 : 0;
  double *uOut = u.mutable_data(), *vOut = v.mutable_data(), *wOut = w.mutable_data(), *qOut = q.mutable_data();
  std::uint8_t* statusOut = status.mutable_data();
  double *uvOut = triplanarUv.mutable_data(), *weightOut = triplanarWeights.mutable_data();
  const std::string mappingText = interruptible([&] {
    const uvtk::point::Mapping mapping(parameters, positions, uvtk::point::Face::Keyword);
    const std::size_t blocks = (n + kPointsPerBlock - 1) / kPointsPerBlock;
    uvtk::parallelFor(int(blocks), threads, [&](int block) {
      const std::size_t end = std::min(n, (std::size_t(block) + 1) * kPointsPerBlock);
      for (std::size_t i = std::size_t(block) * kPointsPerBlock; i < end; ++i) {
        const uvtk::point::Vector3 at{p[3 * i], p[3 * i + 1], p[3 * i + 2]};
        const uvtk::point::Vector3 nAt = normal ? uvtk::point::Vector3{normal[normalStep * i], normal[normalStep * i + 1],
                                                                       normal[normalStep * i + 2]}
                                                : uvtk::point::Vector3{0.0, 0.0, 0.0};
        const uvtk::point::Result r = mapping.at(at, nAt);
        uOut[i] = r.u, vOut[i] = r.v, wOut[i] = r.w, qOut[i] = r.q;
        statusOut[i] = std::uint8_t(r.status);
        reasons[i] = r.reason;
        for (std::size_t axis = 0; axis < 3; ++axis) {
          uvOut[6 * i + 2 * axis] = r.triplanarUv[axis][0];
          uvOut[6 * i + 2 * axis + 1] = r.triplanarUv[axis][1];
          weightOut[3 * i + axis] = r.triplanarWeights[axis];
        }
      }
    });
    return mapping.options();
  });
  const bool triplanar = kwargs.contains("projector") && py::str(kwargs["projector"]).cast<std::string>() == "triplanar";
  EvalResult result{u, v, w, q, status, py::list(), mappingText, triplanar ? py::object(triplanarUv) : py::none(),
                    triplanar ? py::object(triplanarWeights) : py::none()};
  for (const char* reason : reasons) result.reason.append(reason);
  return result;
}

// The options of a command as the library describes them (api::*Options::describe()): the one table
// uvtk/__init__.py builds the functions' signatures and the stubs from.
py::list optionTable(const std::vector<api::OptionDescription>& options) {
  py::list out;
  for (const api::OptionDescription& o : options) {
    py::dict d;
    std::string keyword = o.name;
    for (char& c : keyword) c = c == '-' ? '_' : c;
    d["name"] = o.name;
    d["keyword"] = keyword;
    d["kind"] = o.kind;
    d["optional"] = o.optional;
    d["default"] = o.defaultText;
    d["choices"] = py::cast(o.choices);
    d["help"] = o.help;
    d["type_name"] = o.typeName;
    out.append(d);
  }
  return out;
}

// ---- pickling: a mesh's own vectors as arrays, copied back as they were ----

template <class T, std::size_t N>
py::array arrayOf(const std::vector<std::array<T, N>>& values) {
  py::array_t<T> array(Shape{count(values.size()), py::ssize_t(N)});
  if (!values.empty()) std::copy_n(values.data()->data(), values.size() * N, array.mutable_data());
  return std::move(array);
}

template <class T, std::size_t N>
std::vector<std::array<T, N>> vectorOf(const char* what, const py::handle& object) {
  const py::array_t<T, py::array::c_style | py::array::forcecast> array(py::reinterpret_borrow<py::object>(object));
  if (array.ndim() != 2 || array.shape(1) != py::ssize_t(N))
    throw py::value_error(std::string("unpickling: ") + what + " has the wrong shape");
  std::vector<std::array<T, N>> values(std::size_t(array.shape(0)));
  if (!values.empty()) std::copy_n(array.data(), values.size() * N, values.data()->data());
  return values;
}

py::tuple meshState(const api::Mesh& mesh) {
  return py::make_tuple(1, arrayOf(mesh.positions), arrayOf(mesh.triangles), arrayOf(mesh.texcoords),
                        arrayOf(mesh.cornerTexcoords), arrayOf(mesh.normals), arrayOf(mesh.cornerNormals),
                        py::array(py::cast(mesh.faceFlags)));
}

api::Mesh meshFromState(const py::tuple& state) {
  if (state.size() != 8 || state[0].cast<int>() != 1) throw py::value_error("unpickling: not a uvtk.Mesh state");
  api::Mesh mesh;
  mesh.positions = vectorOf<double, 3>("positions", state[1]);
  mesh.triangles = vectorOf<int, 3>("triangles", state[2]);
  mesh.texcoords = vectorOf<double, 3>("texcoords", state[3]);
  mesh.cornerTexcoords = vectorOf<int, 3>("corner texcoords", state[4]);
  mesh.normals = vectorOf<double, 3>("normals", state[5]);
  mesh.cornerNormals = vectorOf<int, 3>("corner normals", state[6]);
  mesh.faceFlags = state[7].cast<std::vector<std::uint8_t>>();
  api::checkMesh(mesh);
  return mesh;
}

// A mapping's state: its mesh, every per-corner and per-face array, its source, verdict and
// summary, and the mesh it was made from (None when that was its own mesh). Unpickled, it is the
// same data, not mapped nor judged again (api::restoreMapping): write_mesh writes it, report and
// render refuse it (docs/python.md, "Pickling").
py::tuple mappingState(const py::object& self) {
  const PyMapping& m = self.cast<const PyMapping&>();
  const api::Mapping& mapping = m.mapping;
  py::list reasons;
  for (const api::Reason& r : mapping.verdict.reasons)
    reasons.append(py::make_tuple(r.rule, r.severity, r.value, r.threshold, r.faces, r.text));
  std::vector<std::uint8_t> state(mapping.state.size()), invalid(mapping.invalidReason.size());
  std::transform(mapping.state.begin(), mapping.state.end(), state.begin(), [](api::CornerState s) { return std::uint8_t(s); });
  std::transform(mapping.invalidReason.begin(), mapping.invalidReason.end(), invalid.begin(),
                 [](api::InvalidReason r) { return std::uint8_t(r); });
  // The input travels only where it differs from the mapping's mesh (seam="cut").
  const auto same = [&](const api::Mesh& a) {
    const api::Mesh& b = mapping.mesh;
    return a.positions == b.positions && a.triangles == b.triangles && a.texcoords == b.texcoords &&
           a.cornerTexcoords == b.cornerTexcoords && a.normals == b.normals && a.cornerNormals == b.cornerNormals &&
           a.faceFlags == b.faceFlags;
  };
  const bool ownMesh = m.input.is_none() || (py::isinstance<api::Mesh>(m.input) && same(m.input.cast<const api::Mesh&>()));
  return py::make_tuple(1, meshState(mapping.mesh), arrayOf(mapping.uv), py::array(py::cast(mapping.w)),
                        py::array(py::cast(mapping.q)), py::array(py::cast(state)), py::array(py::cast(invalid)),
                        py::array(py::cast(mapping.faceFlags)), mapping.source, mapping.verdict.status, reasons,
                        mapping.summaryJson, ownMesh ? py::object(py::none()) : m.input);
}

template <class T>
std::vector<T> flatOf(const py::handle& object) {
  const py::array_t<T, py::array::c_style | py::array::forcecast> array(py::reinterpret_borrow<py::object>(object));
  return std::vector<T>(array.data(), array.data() + array.size());
}

std::unique_ptr<PyMapping> mappingFromState(const py::tuple& t) {
  if (t.size() != 13 || t[0].cast<int>() != 1) throw py::value_error("unpickling: not a uvtk.Mapping state");
  api::Mapping mapping;
  mapping.mesh = meshFromState(t[1]);
  mapping.uv = vectorOf<double, 2>("uv", t[2]);
  mapping.w = flatOf<double>(t[3]);
  mapping.q = flatOf<double>(t[4]);
  for (const std::uint8_t s : flatOf<std::uint8_t>(t[5])) mapping.state.push_back(api::CornerState(s));
  for (const std::uint8_t r : flatOf<std::uint8_t>(t[6])) mapping.invalidReason.push_back(api::InvalidReason(r));
  mapping.faceFlags = flatOf<std::uint8_t>(t[7]);
  mapping.source = t[8].cast<std::string>();
  mapping.verdict.status = t[9].cast<std::string>();
  for (const py::handle r : t[10].cast<py::list>()) {
    const py::tuple reason = r.cast<py::tuple>();
    mapping.verdict.reasons.push_back({reason[0].cast<std::string>(), reason[1].cast<std::string>(), reason[2].cast<double>(),
                                       reason[3].cast<double>(), reason[4].cast<std::size_t>(), reason[5].cast<std::string>()});
  }
  mapping.summaryJson = t[11].cast<std::string>();
  // What writeMesh needs (the engine's mesh and UVs), made from the data: not mapped nor judged again.
  return std::make_unique<PyMapping>(
      PyMapping{api::restoreMapping(std::move(mapping)), py::reinterpret_borrow<py::object>(t[12])});
}

}  // namespace

PYBIND11_MODULE(_uvtk, m) {
  m.doc() = R"(uvtk: texture coordinates for triangle meshes, and proof that they are right.

The Python face of the C++ library (docs/python.md): the numbers are those of the `uvtk` command
line, bit for bit. Options are keywords named as the command line's options (cap_angle=30 is
--cap-angle 30). Keywords reach the engine as typed values (True is a flag, 0 is False, a str where
a number belongs is a TypeError), read by the function the command line's options reach; the
messages name the keyword.)";

  py::register_exception<api::InputError>(m, "InputError", PyExc_Exception)
      .doc() = "A file could not be read: 'PATH:LINE: error: ...' (the command line's exit 3).";
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const api::ParameterTypeError& e) {
      PyErr_SetString(PyExc_TypeError, e.what());
    } catch (const uvtk::point::ParameterTypeError& e) {
      PyErr_SetString(PyExc_TypeError, e.what());
    } catch (const uvtk::Cancelled&) {
      // Ctrl-C in another thread's call: the request to stop is the whole process's.
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
  });
  py::register_exception<api::OutputError>(m, "OutputError", PyExc_OSError)
      .doc() = "An output could not be written, and nothing was left behind: 'PATH: error: cannot write: ...'.";

  m.attr("__version__") = api::version();
  m.def("_map_options", [] { return optionTable(api::MapOptions::describe()); },
        "map's keywords as `uvtk map --help` shows them: name, keyword, kind, optional, default, choices, help.");
  m.def("_texgen_options", [] { return optionTable(api::TexgenOptions::describe()); },
        "texgen's keywords as `uvtk texgen --help` shows them.");
  m.def("_report_options", [] { return optionTable(api::ReportOptions::describe()); },
        "report's keywords as `uvtk report --help` shows them.");
  m.def("_render_options", [] { return optionTable(api::RenderOptions::describe()); },
        "render's keywords as `uvtk render --help` shows them.");
  m.def("_compare_options", [] { return optionTable(api::CompareOptions::describe()); },
        "compare's keywords as `uvtk compare --help` shows them.");
  m.def("_eval_parameter_names", &uvtk::point::parameterNames, "The names eval's keywords take (dashes, not underscores).");
  m.def("version", &api::version, "The library's version, as `uvtk --version` prints it.");

  // Corner states (Mapping.state), face flags (Mapping.face_flags), invalid reasons, point statuses.
  m.attr("OK") = int(api::CornerState::Ok);
  m.attr("POLE") = int(api::CornerState::Pole);
  m.attr("INVALID") = int(api::CornerState::Invalid);
  m.attr("INVALID_REASONS") = py::make_tuple("valid", "miss", "behind", "out_of_range", "not_finite", "no_texcoord");
  m.attr("FACE_INVALID") = int(api::kFaceInvalid);
  m.attr("FACE_POLE") = int(api::kFacePole);
  m.attr("FACE_SEAM_STRADDLE") = int(api::kFaceSeamStraddle);
  m.attr("FACE_CUBE_SEAM") = int(api::kFaceCubeSeam);
  m.attr("FACE_CAP") = int(api::kFaceCap);
  m.attr("FACE_SPHERE_MAP_SINGULAR") = int(api::kFaceSphereMapSingular);
  m.attr("FACE_TURNED_AWAY") = int(api::kFaceTurnedAway);
  m.attr("POINT_OK") = int(uvtk::point::Status::Ok);
  m.attr("POINT_POLE") = int(uvtk::point::Status::Pole);
  m.attr("POINT_ON_SEAM") = int(uvtk::point::Status::OnSeam);
  m.attr("POINT_INVALID") = int(uvtk::point::Status::Invalid);
  m.attr("POINT_STATUS_NAMES") = py::make_tuple("ok", "pole", "on-seam", "invalid");

  // ---- Mesh ----
  py::class_<api::Mesh>(m, "Mesh", R"(A triangle mesh: positions, triangles, and optional per-corner UVs and normals.

Mesh(positions, triangles, uv=None, normals=None): positions (N, 3) numbers, triangles (F, 3) of any
integer dtype (stored as int32), uv (F, 3, 2) per corner (NaN: that corner has none), normals (N, 3)
per vertex or (F, 3, 3) per corner. Checked as a file reader checks a file: ValueError names the
first problem. The arrays are copied in; the properties are read-only views.)")
      .def(py::init(&meshFrom), py::arg("positions"), py::arg("triangles"), py::arg("uv") = py::none(),
           py::arg("normals") = py::none())
      .def_property_readonly(
          "positions",
          [](py::object self) {
            const api::Mesh& mesh = self.cast<const api::Mesh&>();
            return view(self, mesh.positions.data()->data(), {count(mesh.positions.size()), 3});
          },
          "(N, 3) float64, a read-only view.")
      .def_property_readonly(
          "triangles",
          [](py::object self) {
            const api::Mesh& mesh = self.cast<const api::Mesh&>();
            return view(self, mesh.triangles.data()->data(), {count(mesh.triangles.size()), 3});
          },
          "(F, 3) int32 vertex indices, counter-clockwise seen from the front; a read-only view.")
      .def_property_readonly(
          "uv", [](const api::Mesh& mesh) { return perCorner(mesh.texcoords, mesh.cornerTexcoords, 2); },
          "(F, 3, 2) float64 per-corner texture coordinates (NaN where a corner has none), or None.")
      .def_property_readonly(
          "normals", [](const api::Mesh& mesh) { return perCorner(mesh.normals, mesh.cornerNormals, 3); },
          "(F, 3, 3) float64 per-corner normals (NaN where a corner has none), or None.")
      .def(py::pickle([](const api::Mesh& mesh) { return meshState(mesh); },
                      [](const py::tuple& state) { return meshFromState(state); }))
      .def_property_readonly("vertex_count", [](const api::Mesh& mesh) { return mesh.positions.size(); })
      .def_property_readonly("face_count", [](const api::Mesh& mesh) { return mesh.triangles.size(); })
      .def("__repr__", [](const api::Mesh& mesh) {
        return "<uvtk.Mesh " + std::to_string(mesh.positions.size()) + " vertices, " +
               std::to_string(mesh.triangles.size()) + " faces" + (mesh.cornerTexcoords.empty() ? "" : ", uv") + ">";
      });

  m.def(
      "read_mesh",
      [](py::object path, bool withWarnings, int threads) -> py::object {
        const std::string file = pathOf("read_mesh", path);
        if (threads < 0 || threads > 1024) throw py::value_error("read_mesh(): threads: expected 0 to 1024, got " + std::to_string(threads));
        api::MeshWarnings warnings;
        api::Mesh mesh = interruptible([&] { return api::readMesh(file, &warnings, threads); });
        py::object result = py::cast(std::move(mesh));
        return withWarnings ? py::make_tuple(result, warningsDict(warnings)) : result;
      },
      py::arg("path"), py::arg("with_warnings") = false, py::arg("threads") = 0,
      R"(Reads a mesh file (.obj, .off, .ply, .stl, .gltf, .glb) as `uvtk map` does: strictly, polygons
ear-clipped into triangles. Raises uvtk.InputError "PATH:LINE: error: ...". with_warnings=True
returns (mesh, warnings dict); threads: those parsing a large OBJ (0: one per hardware thread; the
same mesh).)");
  m.def("check_mesh", [](py::object mesh) { return warningsDict(api::checkMesh(meshOf("check_mesh", mesh))); },
        py::arg("mesh"),
        "What a reader would accept with a warning (degenerate faces, unreferenced vertices, ...), as a dict.");

  // ---- Options objects: the structs' fields, snake_case ----
  py::class_<api::MapOptions>(m, "MapOptions", "The options of `uvtk map` as fields; MapOptions.parse(command_line).")
      .def(py::init<>())
      .def_static("parse", &api::MapOptions::parse, py::arg("command_line"),
                  "From `uvtk map`'s syntax, e.g. '--projector cylinder --caps'. ValueError with the CLI's message.")
      .def("command_line", &api::MapOptions::commandLine, "The options as `uvtk map` takes them (those not at their default).")
      .def("__repr__", [](const api::MapOptions& o) { return "uvtk.MapOptions.parse(" + py::repr(py::str(o.commandLine())).cast<std::string>() + ")"; })
      .def(py::pickle([](const api::MapOptions& o) { return py::make_tuple(o.commandLine()); },
                      [](const py::tuple& state) { return api::MapOptions::parse(state[0].cast<std::string>()); }))
      .def("__eq__", [](const api::MapOptions& a, const api::MapOptions& b) { return a.commandLine() == b.commandLine(); })
      .def_readwrite("projector", &api::MapOptions::projector)
      .def_readwrite("omap", &api::MapOptions::omap)
      .def_readwrite("fit", &api::MapOptions::fit)
      .def_readwrite("axis", &api::MapOptions::axis)
      .def_readwrite("center", &api::MapOptions::center)
      .def_readwrite("axis_dir", &api::MapOptions::axisDir)
      .def_readwrite("ref_dir", &api::MapOptions::refDir)
      .def_readwrite("scale", &api::MapOptions::scale)
      .def_readwrite("plane_u", &api::MapOptions::planeU)
      .def_readwrite("plane_v", &api::MapOptions::planeV)
      .def_readwrite("caps", &api::MapOptions::caps)
      .def_readwrite("cap_angle", &api::MapOptions::capAngle)
      .def_readwrite("cap_layout", &api::MapOptions::capLayout)
      .def_readwrite("sphere_preset", &api::MapOptions::spherePreset)
      .def_readwrite("cube_convention", &api::MapOptions::cubeConvention)
      .def_readwrite("cube_layout", &api::MapOptions::cubeLayout)
      .def_readwrite("eye", &api::MapOptions::eye)
      .def_readwrite("up", &api::MapOptions::up)
      .def_readwrite("fovy", &api::MapOptions::fovy)
      .def_readwrite("aspect", &api::MapOptions::aspect)
      .def_readwrite("tile", &api::MapOptions::tile)
      .def_readwrite("blend", &api::MapOptions::blend)
      .def_readwrite("triplanar_preset", &api::MapOptions::triplanarPreset)
      .def_readwrite("angle_limit", &api::MapOptions::angleLimit)
      .def_readwrite("margin", &api::MapOptions::margin)
      .def_readwrite("texels_per_unit", &api::MapOptions::texelsPerUnit)
      .def_readwrite("at_infinity", &api::MapOptions::atInfinity)
      .def_readwrite("seam", &api::MapOptions::seam)
      .def_readwrite("pole", &api::MapOptions::pole)
      .def_readwrite("pole_eps", &api::MapOptions::poleEps)
      .def_readwrite("seam_place", &api::MapOptions::seamPlace)
      .def_readwrite("seam_place_auto", &api::MapOptions::seamPlaceAuto)
      .def_readwrite("uv_scale", &api::MapOptions::uvScale)
      .def_readwrite("uv_offset", &api::MapOptions::uvOffset)
      .def_readwrite("uv_rotate", &api::MapOptions::uvRotate)
      .def_readwrite("flip_u", &api::MapOptions::flipU)
      .def_readwrite("flip_v", &api::MapOptions::flipV)
      .def_readwrite("precision", &api::MapOptions::precision)
      .def_readwrite("math", &api::MapOptions::math)
      .def_readwrite("convention", &api::MapOptions::convention)
      .def_readwrite("fail_on", &api::MapOptions::failOn)
      .def_readwrite("warn_on", &api::MapOptions::warnOn)
      .def_readwrite("overlap_resolution", &api::MapOptions::overlapResolution)
      .def_readwrite("texture_size", &api::MapOptions::textureSize)
      .def_readwrite("density", &api::MapOptions::density)
      .def_readwrite("threads", &api::MapOptions::threads);

  py::class_<api::TexgenOptions>(m, "TexgenOptions", "The options of `uvtk texgen` as fields; TexgenOptions.parse(command_line).")
      .def(py::init<>())
      .def_static("parse", &api::TexgenOptions::parse, py::arg("command_line"),
                  "From `uvtk texgen`'s syntax, e.g. '--s object_linear:1,0,0,0'. ValueError with the CLI's message.")
      .def("command_line", &api::TexgenOptions::commandLine)
      .def("__repr__", [](const api::TexgenOptions& o) { return "uvtk.TexgenOptions.parse(" + py::repr(py::str(o.commandLine())).cast<std::string>() + ")"; })
      .def(py::pickle([](const api::TexgenOptions& o) { return py::make_tuple(o.commandLine()); },
                      [](const py::tuple& state) { return api::TexgenOptions::parse(state[0].cast<std::string>()); }))
      .def("__eq__", [](const api::TexgenOptions& a, const api::TexgenOptions& b) { return a.commandLine() == b.commandLine(); })
      .def_readwrite("s", &api::TexgenOptions::s)
      .def_readwrite("t", &api::TexgenOptions::t)
      .def_readwrite("r", &api::TexgenOptions::r)
      .def_readwrite("q", &api::TexgenOptions::q)
      .def_readwrite("mode", &api::TexgenOptions::mode)
      .def_readwrite("texmatrix", &api::TexgenOptions::texmatrix)
      .def_readwrite("normalize", &api::TexgenOptions::normalize)
      .def_readwrite("eye", &api::TexgenOptions::eye)
      .def_readwrite("center", &api::TexgenOptions::center)
      .def_readwrite("up", &api::TexgenOptions::up)
      .def_readwrite("model", &api::TexgenOptions::model)
      .def_readwrite("precision", &api::TexgenOptions::precision);

  // ---- Mapping ----
  py::class_<PyMapping>(m, "Mapping", R"(A mesh with texture coordinates per corner, and their judgement.

Made by uvtk.map, uvtk.texgen or uvtk.file_uvs. Arrays are read-only views of the mapping's own
memory, per corner (F, 3) in face order: corner k of face f. With seam="cut", .mesh is the mesh cut
along the seam (more vertices and faces than the input).)")
      .def_property_readonly(
          "uv",
          [](py::object self) {
            const api::Mapping& mapping = self.cast<const PyMapping&>().mapping;
            return view(self, mapping.uv.data()->data(), {count(mapping.uv.size() / 3), 3, 2});
          },
          "(F, 3, 2) float64: (u, v) per corner; (0, 0) where the corner is invalid.")
      .def_property_readonly(
          "w",
          [](py::object self) -> py::object {
            const api::Mapping& mapping = self.cast<const PyMapping&>().mapping;
            if (mapping.w.empty()) return py::none();
            return view(self, mapping.w.data(), {count(mapping.w.size() / 3), 3});
          },
          "(F, 3) float64: the cube face id (cube_layout='faces') or texgen's r; None when there is none.")
      .def_property_readonly(
          "q",
          [](py::object self) -> py::object {
            const api::Mapping& mapping = self.cast<const PyMapping&>().mapping;
            if (mapping.q.empty()) return py::none();
            return view(self, mapping.q.data(), {count(mapping.q.size() / 3), 3});
          },
          "(F, 3) float64: texgen's q, not divided out; None means 1.")
      .def_property_readonly(
          "state",
          [](py::object self) {
            const api::Mapping& mapping = self.cast<const PyMapping&>().mapping;
            static_assert(sizeof(api::CornerState) == 1);
            return view(self, reinterpret_cast<const std::uint8_t*>(mapping.state.data()), {count(mapping.state.size() / 3), 3});
          },
          "(F, 3) uint8: uvtk.OK, uvtk.POLE (u repaired or 0) or uvtk.INVALID (no coordinate).")
      .def_property_readonly(
          "invalid_reason",
          [](py::object self) {
            const api::Mapping& mapping = self.cast<const PyMapping&>().mapping;
            static_assert(sizeof(api::InvalidReason) == 1);
            return view(self, reinterpret_cast<const std::uint8_t*>(mapping.invalidReason.data()),
                        {count(mapping.invalidReason.size() / 3), 3});
          },
          "(F, 3) uint8: why a corner is invalid, an index into uvtk.INVALID_REASONS (0: valid).")
      .def_property_readonly(
          "face_flags",
          [](py::object self) {
            const api::Mapping& mapping = self.cast<const PyMapping&>().mapping;
            return view(self, mapping.faceFlags.data(), {count(mapping.faceFlags.size())});
          },
          "(F,) uint8: bits uvtk.FACE_INVALID, FACE_POLE, FACE_SEAM_STRADDLE, FACE_CUBE_SEAM, FACE_CAP, FACE_SPHERE_MAP_SINGULAR, FACE_TURNED_AWAY.")
      .def_property_readonly(
          "mesh", [](const PyMapping& self) -> const api::Mesh& { return self.mapping.mesh; },
          py::return_value_policy::reference_internal,
          "The uvtk.Mesh the coordinates belong to: the input, or cut along the seam (seam='cut').")
      .def_property_readonly("source", [](const PyMapping& self) { return self.mapping.source; },
                             "'projector', 'texgen' or 'file'.")
      .def_property_readonly("verdict", [](const PyMapping& self) { return verdictDict(self.mapping.verdict); },
                             "{'status': 'pass'|'warn'|'fail', 'reasons': [{rule, severity, value, threshold, faces, text}]}.")
      .def_property_readonly("summary", [](const PyMapping& self) { return jsonLoads(self.mapping.summaryJson); },
                             "The record `uvtk map --json` writes (without times and output), as a dict.")
      .def(py::pickle([](py::object self) { return mappingState(self); },
                      [](const py::tuple& state) { return mappingFromState(state); }))
      .def("__repr__", [](const PyMapping& self) {
        const api::Mapping& mapping = self.mapping;
        return "<uvtk.Mapping " + mapping.source + ": " + std::to_string(mapping.mesh.positions.size()) + " vertices, " +
               std::to_string(mapping.mesh.triangles.size()) + " faces, verdict " + mapping.verdict.status + ">";
      });

  m.def(
      "map",
      [](py::object mesh, py::object options, py::kwargs kwargs) {
        const api::Parameters parameters = parametersFrom<api::MapOptions>("map", "a uvtk.MapOptions", options, kwargs);
        const api::Mesh& input = meshOf("map", mesh);
        return wrap(interruptible([&] { return api::map(input, parameters); }), mesh);
      },
      py::arg("mesh"), py::arg("options") = py::none(),
      R"(Maps `mesh` by a projector, as `uvtk map` does (the same numbers, bit for bit).

Every option of `uvtk map` but its outputs is a keyword: projector="cylinder", fit="obb",
caps=True, cap_angle=30, center=(0, 0, 1), seam_place="auto" or 90, texture_size=(2048, 1024) or
2048, fail_on=["flipped_area=0.01"], threads=1, ... (or options=uvtk.MapOptions(...)). Flags take
True or False; None means "not given" only for the optional ones (center, eye, up, density);
fit="none" asks for no fit. Returns a uvtk.Mapping. A value of the wrong kind raises TypeError, a
wrong value or an unknown keyword ValueError, naming the keyword.)");
  m.def(
      "texgen",
      [](py::object mesh, py::object options, py::kwargs kwargs) {
        const api::Parameters parameters =
            parametersFrom<api::TexgenOptions>("texgen", "a uvtk.TexgenOptions", options, kwargs);
        const api::Mesh& input = meshOf("texgen", mesh);
        return wrap(interruptible([&] { return api::texgen(input, parameters); }), mesh);
      },
      py::arg("mesh"), py::arg("options") = py::none(),
      R"(OpenGL texgen's (s, t, r, q) on `mesh`, as `uvtk texgen` computes them.

Keywords are the options of `uvtk texgen`: s="object_linear:1,0,0,0", t="eye_linear:0,1,0,0",
mode="sphere_map", eye=(0, 0, 5), no_normalize=True, threads=1 (those judging the mapping), ... (or
options=uvtk.TexgenOptions(...)). Returns a uvtk.Mapping (r in .w, q in .q). A value of the wrong
kind raises TypeError, a wrong value or an unknown keyword ValueError, naming the keyword.)");
  m.def(
      "file_uvs",
      [](py::object mesh) {
        const api::Mesh& input = meshOf("file_uvs", mesh);
        return wrap(interruptible([&] { return api::fileUvs(input); }), mesh);
      },
      py::arg("mesh"), "The mesh's own texture coordinates, judged. ValueError when it has none.");

  m.def(
      "write_mesh",
      [](py::object path, py::object mesh, py::object mapping, const std::string& uvDigits, bool writeW, bool ascii,
         const std::string& header, int threads) {
        const std::string file = pathOf("write_mesh", path);
        if (mapping.is_none() && py::isinstance<PyMapping>(mesh)) std::swap(mesh, mapping);
        if (mapping.is_none()) {
          const api::Mesh& own = meshOf("write_mesh", mesh);
          interruptible([&] { api::writeMesh(file, own); });
          return;
        }
        const api::Mapping& mapped = mappingFor("write_mesh", mesh, mapping);
        const api::WriteOptions options = writeOptions(uvDigits, writeW, ascii, header, threads);
        interruptible([&] { api::writeMesh(file, mapped, options); });
      },
      py::arg("path"), py::arg("mesh"), py::arg("m") = py::none(), py::arg("uv_digits") = "double",
      py::arg("write_w") = false, py::arg("ascii") = false, py::arg("header") = "", py::arg("threads") = 0,
      R"(Writes a mesh by the path's extension (.obj, .ply, .glb, .gltf + .bin), whole or not at all
(uvtk.OutputError).

write_mesh(path, mesh, m): the mapping's mesh with its per-corner UVs, as `uvtk map -o` writes it
(uv_digits='double' round-trips every double, 'float' every float, in an OBJ; write_w=True writes
vt u v w in an OBJ; ascii=True writes a .ply as text; header="uvtk map IN" writes the comment
lines `uvtk map` writes at the top of an OBJ or PLY, so that the bytes are the program's; threads:
those formatting an OBJ, 0 one per hardware thread, the same bytes).
write_mesh(path, mesh): the mesh with its own texture coordinates and normals.)");

  m.def(
      "report",
      [](py::object mesh, py::object mapping, py::kwargs kwargs) {
        const api::Mapping& mapped = mappingFor("report", mesh, mapping);
        const api::Parameters parameters = keywordParameters(kwargs);
        return jsonLoads(interruptible([&] { return api::report(mapped, parameters); }));
      },
      py::arg("mesh"), py::arg("m"),
      R"(The report of mapping `m` as a dict: the document `uvtk report --json` writes, verdict first.

Keywords are the options of `uvtk report`: json="r.json" and html="r.html" also write those files;
views=, size=(w, h), texture_size=, threads=.)");
  m.def(
      "render",
      [](py::object mesh, py::object mapping, const std::string& dtype, py::kwargs kwargs) {
        if (dtype != "uint8" && dtype != "float32")
          throw py::value_error("render: dtype is '" + dtype + "', expected uint8 or float32");
        const api::Mapping& mapped = mappingFor("render", mesh, mapping);
        const api::Parameters parameters = keywordParameters(kwargs);
        api::Image image;
        std::vector<std::uint8_t> bytes;
        interruptible([&] {
          image = api::render(mapped, parameters);
          if (dtype == "uint8") bytes = image.bytes();
        });
        const Shape shape{image.height, image.width, image.channels};
        return dtype == "uint8" ? owning(std::move(bytes), shape) : owning(std::move(image.pixels), shape);
      },
      py::arg("mesh"), py::arg("m"), py::arg("dtype") = "uint8",
      R"(A picture of mapping `m` as a numpy array (H, W, C), row 0 at the top.

Keywords are the options of `uvtk render`: view="checker" (uvgrid, stretch, linf, angle, area,
seams, uverror, layout; several comma-separated make a contact sheet; "" renders the texture),
size=(width, height), view_dir=(x, y, z), texture="checker:64:8", spp=4, ... dtype="uint8" gives
the PNG's 8-bit values, dtype="float32" the values in [0, 1].)");
  m.def(
      "compare",
      [](py::object mesh, py::kwargs kwargs) {
        const api::Mesh& input = meshOf("compare", mesh);
        const api::Parameters parameters = keywordParameters(kwargs);
        const api::Comparison comparison = interruptible([&] { return api::compare(input, parameters); });
        py::dict result;
        result["json"] = jsonLoads(comparison.json);
        result["table"] = comparison.table;
        result["best"] = comparison.best;
        return result;
      },
      py::arg("mesh"),
      R"(Every projector configuration on `mesh`, ranked, as `uvtk compare` ranks them.

Keywords are the options of `uvtk compare` (by="angle", top=8, no_baselines=True, fail_on=[...]).
Returns {'json': the --json document as a dict, 'table': the Markdown table, 'best': the name}.)");
  // ---- single points ----
  py::class_<EvalResult>(m, "EvalResult", "uvtk.eval's values, one per point: arrays u, v, w, q, status; list reason.")
      .def_readonly("u", &EvalResult::u, "u (texgen: s)")
      .def_readonly("v", &EvalResult::v, "v (texgen: t)")
      .def_readonly("w", &EvalResult::w, "the cube face id (faces layout) or texgen's r, else 0")
      .def_readonly("q", &EvalResult::q, "texgen's q, else 1")
      .def_readonly("status", &EvalResult::status, "uint8: uvtk.POINT_OK, POINT_POLE, POINT_ON_SEAM, POINT_INVALID")
      .def_readonly("reason", &EvalResult::reason, "why a status is not ok, one sentence ('' when ok)")
      .def_readonly("triplanar_uv", &EvalResult::triplanarUv,
                    "--projector triplanar: the (u, v) of the x, y and z projections, shape (..., 3, 2); else None")
      .def_readonly("triplanar_weights", &EvalResult::triplanarWeights,
                    "--projector triplanar: their weights (sum 1), shape (..., 3); else None")
      .def_readonly("mapping", &EvalResult::mapping, "the options string of the mapping that evaluated them")
      .def("keys", &EvalResult::keys)
      .def("__getitem__", [](py::object self, const std::string& key) {
        const std::vector<std::string> keys = self.cast<const EvalResult&>().keys();
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) throw py::key_error(key);
        return self.attr(key.c_str());
      })
      .def("__repr__", [](const EvalResult& r) {
        return "<uvtk.EvalResult " + std::to_string(r.reason.size()) + " points, " + r.mapping + ">";
      });

  m.def("eval", &evaluate, py::arg("points"), py::arg("normals") = py::none(), py::arg("mesh") = py::none(),
        R"(The mapping at single points, as `uvtk eval` computes it (before seam and pole repair).

points (..., 3); normals None, one (3,) for all, or one per point (read by the normal and
reflection O-mappings, cylinder caps and texgen). Keywords are `uvtk eval`'s mapping options:
projector="cylinder", omap="normal", texgen="sphere_map", eye=(0, 0, 5), ...; the placement is
fit="none" unless given; mesh=uvtk.Mesh fits a fitted placement to that mesh as `uvtk map` does;
threads= spreads the points over threads (0: one per hardware thread; the same numbers).
Returns a uvtk.EvalResult: arrays u, v, w, q (float64) and status (uint8) of the points' shape,
and the list reason.)");
}
