// seams: the shaded mesh with its seam edges drawn where they are visible, seam-straddling, pole,
// flipped and invalid faces marked, and pole vertices as dots.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "core/error.h"
#include "views/canvas.h"
#include "views/draw.h"
#include "views/legend.h"
#include "views/palette.h"
#include "views/scene.h"
#include "views/seam_marks.h"

namespace uvtk::views {

namespace {

constexpr int kSeamWidth = 2;             // pixels
constexpr double kPoleDotRadius = 2.5;    // pixels
// A mark passes the depth test when it lies no deeper than the visible surface plus the surface's
// own depth change over kSlopePixels pixels (as glPolygonOffset's slope factor), so that a line on
// the surface is not lost to the distance between pixel centres and the edge, plus
// kDepthEpsilon for the float depth buffer.
constexpr double kSlopePixels = 2.0;
constexpr double kDepthEpsilon = 1e-5;

// A point in image coordinates (x right, y down) with its window depth (docs/conventions.md §7).
struct ScreenPoint {
  Vec2 image;
  double depth;
};

ScreenPoint toScreen(const Vec4& clip, int width, int height) {
  const Vec3 ndc = clip.head<3>() / clip.w();
  return {Vec2((ndc.x() + 1.0) * 0.5 * width, height - (ndc.y() + 1.0) * 0.5 * height), (ndc.z() + 1.0) * 0.5};
}

// The part of the clip-space segment ab inside the view volume -w <= x, y, z <= w (Liang and
// Barsky's parametric clipping, in homogeneous coordinates so that it is exact before the divide).
std::optional<std::pair<Vec4, Vec4>> clipSegment(const Vec4& a, const Vec4& b) {
  if (!a.allFinite() || !b.allFinite()) return std::nullopt;
  double t0 = 0.0, t1 = 1.0;
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {1.0, -1.0}) {
      const double da = a.w() + sign * a[axis], db = b.w() + sign * b[axis];  // >= 0 inside
      if (da < 0.0 && db < 0.0) return std::nullopt;
      if (da < 0.0) t0 = std::max(t0, da / (da - db));
      if (db < 0.0) t1 = std::min(t1, da / (da - db));
    }
  if (t0 > t1) return std::nullopt;
  return std::pair<Vec4, Vec4>(a + t0 * (b - a), a + t1 * (b - a));
}

bool insideViewVolume(const Vec4& c) {
  return c.allFinite() && c.head<3>().cwiseAbs().maxCoeff() <= c.w();
}

// Whether a mark at window `depth` on pixel (x, row) is not hidden by the visible surface.
bool inFront(const Mesh& mesh, const Scene& scene, int x, int row, double depth) {
  const render::VisibilityBuffer& visible = scene.visible;
  const std::size_t i = visible.index(x, row);
  const std::int32_t face = visible.face[i];
  if (face < 0) return true;
  const Triangle& t = mesh.triangles[std::size_t(face)];
  const render::TriangleInterpolator surface(scene.clip[std::size_t(t[0])], scene.clip[std::size_t(t[1])],
                                             scene.clip[std::size_t(t[2])], visible.width, visible.height);
  // The window depth (z_ndc + 1) / 2 changes by half the NDC depth plane's slopes per pixel.
  const Vec3& plane = surface.ndcDepthPlane();
  const double slope = 0.5 * (std::fabs(plane.x()) + std::fabs(plane.y()));
  return depth <= double(visible.depth[i]) + kSlopePixels * slope + kDepthEpsilon;
}

// What the seams view marks a face as: the first that applies.
enum class FaceMark { Invalid, PoleFace, Flipped, Straddle, Plain };

FaceMark markOf(const analysis::FaceDistortion& face, const UvMap& uv, std::size_t f) {
  if (face.status == analysis::FaceStatus::Invalid) return FaceMark::Invalid;
  if (face.status == analysis::FaceStatus::PoleFace) return FaceMark::PoleFace;
  if (face.status == analysis::FaceStatus::Flipped) return FaceMark::Flipped;
  if (uv.faceHas(f, kFaceSeamStraddle)) return FaceMark::Straddle;
  return FaceMark::Plain;
}

Vec3 colourOf(FaceMark mark) {
  switch (mark) {
    case FaceMark::Invalid: return statusColour(analysis::FaceStatus::Invalid);
    case FaceMark::PoleFace: return statusColour(analysis::FaceStatus::PoleFace);
    case FaceMark::Flipped: return statusColour(analysis::FaceStatus::Flipped);
    case FaceMark::Straddle: return kStraddleColour;
    case FaceMark::Plain: break;
  }
  return kNeutralColour;
}

}  // namespace

DrawnView drawSeams(const ViewInput& in, const ViewOptions& options) {
  UVTK_CHECK(in.judgement && in.judgement->faces.size() == in.mesh->faceCount());
  const analysis::Judgement& judgement = *in.judgement;
  const Mesh& mesh = *in.mesh;
  const Scene scene = rasterizeScene(mesh, options.render);
  const int width = scene.visible.width, height = scene.visible.height;

  std::vector<Vec3> colours;
  colours.reserve(mesh.faceCount());
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    colours.push_back(colourOf(markOf(judgement.faces[f], *in.uv, f)));
  }
  Image image = shadeFaces(scene, colours, options.render.background);

  const std::vector<int>& poleVertices = judgement.summary.poleVertices;
  const SeamMarks seams = seamMarks(mesh, *in.uv);
  for (const SeamEdge& edge : seams.edges) {
    const auto clipped = clipSegment(scene.clip[std::size_t(edge.a)], scene.clip[std::size_t(edge.b)]);
    if (!clipped) continue;
    const ScreenPoint a = toScreen(clipped->first, width, height), b = toScreen(clipped->second, width, height);
    // Window depth is affine along the projected segment: a line stays a line under projection.
    drawSegment(image, a.image, b.image, kSeamWidth, SeamMarks::colour(edge), [&](int x, int row, double t) {
      return inFront(mesh, scene, x, row, a.depth + t * (b.depth - a.depth));
    });
  }

  for (int v : poleVertices) {
    UVTK_CHECK(v >= 0 && std::size_t(v) < mesh.vertexCount());
    const Vec4& c = scene.clip[std::size_t(v)];
    if (!insideViewVolume(c)) continue;
    const ScreenPoint p = toScreen(c, width, height);
    const int x = std::min(width - 1, int(p.image.x())), row = std::min(height - 1, int(p.image.y()));
    if (inFront(mesh, scene, x, row, p.depth)) drawDot(image, p.image, kPoleDotRadius, kPoleVertexColour);
  }

  auto count = [](const char* what, std::size_t n) { return std::string(what) + ": " + std::to_string(n); };
  Legend legend;
  legend.title = {"Seams and poles"};
  // The counts are the judgement's (a face both flipped and straddling is drawn flipped and
  // counted in both), so that the legend equals `uvtk map --json` and `uvtk report`.
  using analysis::FaceStatus;
  legend.entries = seamLegendEntries(judgement.summary.seams);
  legend.entries.insert(legend.entries.end(), {
      {kStraddleColour, count("seam-straddling faces", judgement.straddlingFaces)},
      {kPoleVertexColour, count("pole vertices", poleVertices.size())},
      {colourOf(FaceMark::PoleFace), count("pole faces", judgement.summary.poleFaces)},
      {colourOf(FaceMark::Flipped), count("flipped faces", judgement.statusCount(FaceStatus::Flipped))},
      {colourOf(FaceMark::Invalid), count("invalid faces", judgement.statusCount(FaceStatus::Invalid))},
  });
  return {image, legend};
}

}  // namespace uvtk::views
