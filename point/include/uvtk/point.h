// uvtk's mappings at single points: the reference to test other mapping code against (a shader, an
// exporter, a game engine's texgen). A Mapping is prepared once from the options `uvtk eval` takes
// (any projector, O-mapping, preset, convention and placement of `uvtk map`, any texgen mode of
// `uvtk texgen`); at() then evaluates one point without a mesh and without allocating. The numbers
// are those of `uvtk eval` and `uvtk map` bit for bit (before seam and pole repair, which need a mesh).
// Conventions: docs/conventions.md.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

// The library is built with hidden symbols; these are its interface.
#define UVTK_POINT_API __attribute__((visibility("default")))

namespace uvtk::point {

using Vector3 = std::array<double, 3>;

enum class Status {
  Ok,
  Pole,    // on the axis of a wrapping surface: v is exact, u is undefined (0); texgen: the sphere map's singular point
  OnSeam,  // on a seam: u = 0 and u = 1 are the same point (or, on a cube, an edge: the tie rule picked the face)
  Invalid,  // no value: the point or normal is not finite or zero, the ray misses the surface, or the result overflows
};

// "ok", "pole", "on-seam", "invalid": the names `uvtk eval` prints.
inline const char* statusName(Status status) {
  switch (status) {
    case Status::Ok: return "ok";
    case Status::Pole: return "pole";
    case Status::OnSeam: return "on-seam";
    case Status::Invalid: return "invalid";
  }
  return "invalid";
}

struct Result {
  double u = 0.0, v = 0.0;  // a projector's (u, v), or texgen's (s, t); 0 when invalid
  double w = 0.0;           // the cube face id (0..5: +X -X +Y -Y +Z -Z) in the faces layout, texgen's r; else 0
  double q = 1.0;           // texgen's q, not divided out; the camera projector's w_c (u, v divided by it); else 1
  Status status = Status::Invalid;
  const char* reason = "";  // why the status is not ok, one sentence (static storage); empty when ok
  // One turn about a wrapping surface's axis, in (u, v): (1, 0) unless a UV transform scales or turns
  // it. Texture coordinates that differ by whole turns are the same point. Zero when nothing wraps.
  std::array<double, 2> period{};
  // --projector triplanar: the projections along x, y and z, each (u, v), and their weights (sum 1);
  // u, v above are those of the dominant axis (the largest weight, ties to x before y before z),
  // what `uvtk map` writes for a face with this normal. Zero for the other mappings.
  std::array<std::array<double, 2>, 3> triplanarUv{};
  std::array<double, 3> triplanarWeights{};
  Vector3 position{};        // the point evaluated
  const char* mapping = "";  // the options of the Mapping that evaluated it (valid while it lives)
};

// One option of a Mapping, typed: its name as `uvtk eval` spells it without the dashes
// ("cap-angle"), its value, and where it came from for messages ("": the name as the Face spells
// it). Nothing (std::monostate) is "not given" where an option may be left out. A choice is its
// name (std::string("cylinder")), a vector its numbers (std::vector<double>{0, 0, 5}), a flag a bool.
using ParameterValue =
    std::variant<std::monostate, bool, std::int64_t, double, std::vector<double>, std::string, std::vector<std::string>>;
struct Parameter {
  std::string name;
  ParameterValue value;
  std::string place{};  // where it came from; empty: the caller does not say
};

// Who gave the parameters, which decides how a message names one: capAngle (Library), cap_angle
// (Keyword, as Python's), --cap-angle (CommandLine).
enum class Face { Library, Keyword, CommandLine };

// A value of the wrong kind (a number where a flag belongs, a text where numbers do).
class UVTK_POINT_API ParameterTypeError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

class UVTK_POINT_API Mapping {
 public:
  // `options` as `uvtk eval` takes them, e.g. "--projector sphere --omap normal" or "--texgen
  // sphere_map --eye 0,0,5". The placement is --fit none unless given; a fitted placement (--fit
  // bbox, center, pca, obb, or a --convention) is fitted to `meshPositions` exactly as `uvtk map`
  // fits it to that mesh. Throws std::invalid_argument with the command line's message.
  // The text is read once into typed parameters: each --name is followed by its value (--name
  // value or --name=value: true or false, an integer, a number, comma-separated numbers, or a
  // text) unless it is a flag (nothing, or another --name, follows it).
  explicit Mapping(const std::string& options, const std::vector<Vector3>& meshPositions = {});
  // The same mapping from typed parameters, e.g. {{"projector", std::string("cylinder")}, {"caps",
  // true}}; options() spells them as the command line would. Throws ParameterTypeError for a value of
  // the wrong kind, std::invalid_argument for any other refused value, naming the parameter as `face`
  // spells it.
  explicit Mapping(const std::vector<Parameter>& parameters, const std::vector<Vector3>& meshPositions = {},
                   Face face = Face::Library);
  ~Mapping();
  Mapping(Mapping&&) noexcept;
  Mapping& operator=(Mapping&&) noexcept;

  // The mapping at an object-space point. `normal` is read by the normal and reflection
  // O-mappings, by cylinder caps and by the texgen modes that use normals; it need not be unit.
  Result at(const Vector3& position, const Vector3& normal = {0.0, 0.0, 0.0}) const noexcept;

  bool needsNormal() const;  // whether at() reads the normal
  const std::string& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The names of every option a Mapping takes, as `uvtk eval` spells them without the dashes.
UVTK_POINT_API std::vector<std::string> parameterNames();

// The distance in UV units between texture coordinates (u, v) and `expected`, with whole periods
// removed (u compared modulo 1 on a wrapping surface) and, at a pole, only the component across
// the period compared (u is undefined there). NaN gives infinity.
UVTK_POINT_API double uvError(double u, double v, const Result& expected);

}  // namespace uvtk::point
