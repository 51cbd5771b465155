#include "inspect/mapped_mesh.h"

#include <algorithm>
#include <array>
#include <limits>
#include <memory>

#include "core/error.h"
#include "core/progress.h"
#include "inspect/projector_json.h"
#include "param/projector_names.h"
#include "param/projector.h"
#include "param/surface_traits.h"
#include "inspect/measures_json.h"
#include "inspect/run_report.h"
#include "inspect/summary_json.h"

namespace uvtk::inspect {

analysis::ProjectionDirections MappedMesh::projectionDirections() const {
  analysis::ProjectionDirections options;
  if (projector && param::traitsOf(projector->surface).projectsAlongAxis)
    options.projectionDirection = projection->localFromObject.inverse().linear().col(2);
  if (projector && param::traitsOf(projector->surface).blendsProjections) {
    // A local direction d is the object-space normal L^T d (normals transform by the inverse transpose).
    const Mat3 toObject = projection->localFromObject.linear().transpose();
    std::array<Vec3, 3> facing;
    for (int a = 0; a < 3; ++a) facing[std::size_t(a)] = toObject * param::triplanarFacing(projector->triplanar, a);
    options.faceProjectionDirections.reserve(projection->triplanarAxis.size());
    for (const std::uint8_t axis : projection->triplanarAxis) options.faceProjectionDirections.push_back(facing[axis]);
  }
  return options;
}

analysis::Judgement MappedMesh::judge(const analysis::Thresholds& thresholds, int overlapResolution,
                                      int threads, analysis::TextureSize textureSize) const {
  analysis::JudgementOptions options;
  options.wrapsU = projector && exact && exact->wrapsS;  // a wrapping projector's seam is expected
  options.uPeriod = uvScale;
  options.overlapResolution = overlapResolution;
  options.thresholds = thresholds;
  options.threads = threads;
  options.textureSize = textureSize;
  // An atlas's charts must stay apart in the texture; a single projection's charts tile.
  options.separateCharts = projector && param::traitsOf(projector->surface).chartsFromMesh;
  return analysis::judge(mesh, uv, options);
}

views::ViewInput MappedMesh::viewInput(const analysis::Judgement* judgement) const {
  views::ViewInput in;
  in.mesh = &mesh;
  in.uv = &uv;
  in.judgement = judgement;
  in.exact = exact;
  in.wrapsU = exact && exact->wrapsS;
  in.q = q.empty() ? nullptr : &q;
  in.cubeFaceIds = cubeFaceIds();
  return in;
}

bool MappedMesh::cubeFaceIds() const { return projector && writesCubeFaceIds(*projector); }

render::TexcoordSource MappedMesh::texcoordSource(bool perPixel, bool baked) const {
  render::TexcoordSource out;
  if (perPixel) {
    out.pixelMapping = exact;
  } else {
    out.corners = corners(baked);
  }
  out.cubeFaceIds = cubeFaceIds();
  return out;
}

bool writesCubeFaceIds(const param::ProjectorOptions& options) {
  return param::traitsOf(options.surface).hasFaceIds && options.cubeLayout == CubeLayout::Faces;
}

std::vector<Vec4> MappedMesh::corners(bool baked) const {
  std::vector<Vec4> out(uv.uv.size());
  for (std::size_t c = 0; c < out.size(); ++c)
    out[c] = Vec4(uv.uv[c].x(), uv.uv[c].y(), uv.w.empty() ? 0.0 : uv.w[c], q.empty() ? 1.0 : q[c]);
  if (!baked && !cameraQ.empty())  // (s, t, q) = (u q, v q, q): the divide happens per pixel
    for (std::size_t c = 0; c < out.size(); ++c) out[c] = Vec4(out[c][0] * cameraQ[c], out[c][1] * cameraQ[c], 0, cameraQ[c]);
  return out;
}

namespace {

// The atlas at every pixel: a plane chart is linear in the point (then the UV transform); an LSCM
// or ARAP chart is linear on each face, so the pixel's UV is its face's corners' (as written,
// transformed) at the point's barycentric coordinates.
render::PixelMapping atlasPixelMapping(const std::shared_ptr<const param::Atlas>& atlas,
                                       const param::UvTransform& transform, const Mesh& mesh, const UvMap& uv) {
  struct Charts {
    std::shared_ptr<const param::Atlas> atlas;  // shared, not copied: 4 bytes a face
    std::vector<Vec3> corners;  // the solved faces' corner positions, 3 per face (else empty)
    std::vector<Vec2> uv;       // and their UVs
  };
  auto c = std::make_shared<Charts>(Charts{atlas, {}, {}});
  if (std::any_of(atlas->charts.begin(), atlas->charts.end(), [](const param::AtlasChart& a) { return a.solved; })) {
    c->uv = uv.uv;
    c->corners.resize(3 * mesh.faceCount());
    for (std::size_t f = 0; f < mesh.faceCount(); ++f)
      for (int k = 0; k < 3; ++k) c->corners[3 * f + std::size_t(k)] = mesh.positions[std::size_t(mesh.triangles[f][k])];
  }
  return render::PixelMapping{[c, transform](const Vec3& p, const Vec3&, std::int32_t face) {
                                const std::size_t f = std::size_t(face);
                                const param::AtlasChart& chart = c->atlas->charts[std::size_t(c->atlas->chartOfFace[f])];
                                if (chart.solved) {
                                  const Vec3 &a = c->corners[3 * f], &b = c->corners[3 * f + 1], &d = c->corners[3 * f + 2];
                                  const Vec3 n = (b - a).cross(d - a);
                                  const double area = n.squaredNorm();
                                  const double wb = (p - a).cross(d - a).dot(n) / area, wd = (b - a).cross(p - a).dot(n) / area;
                                  const Vec2 st = (1 - wb - wd) * c->uv[3 * f] + wb * c->uv[3 * f + 1] + wd * c->uv[3 * f + 2];
                                  return Vec4(st.x(), st.y(), 0, 1);
                                }
                                Vec2 st = chart.uvAt(p);
                                if (!transform.isIdentity()) st = transform.apply(st);
                                return Vec4(st.x(), st.y(), 0, 1);
                              },
                              false, false};
}

// The projector evaluated at every pixel (docs/conventions.md §9).
render::PixelMapping projectorPixelMapping(const param::ProjectorOptions& options, const param::Projection& projection,
                                           const Mesh& mesh, const UvMap& uv) {
  if (projection.atlas) return atlasPixelMapping(projection.atlas, options.uvTransform, mesh, uv);
  // The range rule as project() applied it, so that per-pixel and per-vertex values agree on it.
  auto projector = std::make_shared<const param::Projector>(options, projection.localFromObject, projection.sensible);
  if (projector->traits().blendsProjections) {  // three lookups blended by the pixel's normal
    render::PixelMapping blend;
    blend.needsNormal = true;
    blend.blendAt = [projector](const Vec3& p, const Vec3& n, std::int32_t) {
      const param::TriplanarSample s = projector->blendAt(p, n);
      return render::TexcoordBlend{s.uv, s.weights};
    };
    return blend;
  }
  // A cap face maps by the side its own normal faces, as project() decided (param/projector.h).
  // Empty when no face is a cap: a zero normal per face would be 24 bytes a face written for nothing.
  auto capNormals = std::make_shared<std::vector<Vec3>>();
  for (std::size_t f = 0; f < uv.faceCount(); ++f)
    if (uv.faceHas(f, kFaceCap)) {
      if (capNormals->empty()) capNormals->assign(uv.faceCount(), Vec3::Zero());
      const Triangle& t = mesh.triangles[f];
      (*capNormals)[f] = triangleAreaNormal(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    }
  // The cube's faces layout keeps the face id as r: per pixel the face of the pixel's own probe.
  const bool faceIds = writesCubeFaceIds(options);
  return render::PixelMapping{[projector, capNormals, faceIds](const Vec3& p, const Vec3& n, std::int32_t face) -> Vec4 {
                                const Vec3 capNormal = capNormals->empty() ? Vec3::Zero() : (*capNormals)[std::size_t(face)];
                                const bool cap = !capNormal.isZero();
                                const param::PointUv mapped = projector->at(p, cap ? capNormal : n, cap);
                                const double nan = std::numeric_limits<double>::quiet_NaN();
                                if (mapped.state == param::CornerState::Invalid) return Vec4(nan, nan, 0, 1);
                                if (!faceIds) return Vec4(mapped.uv.x(), mapped.uv.y(), 0, 1);
                                return Vec4(mapped.uv.x(), mapped.uv.y(), mapped.cubeFace ? double(*mapped.cubeFace) : nan, 1);
                              },
                              projector->traits().wraps, projector->needsNormal()};
}

}  // namespace

UvMap fileUvs(const Mesh& mesh, const std::string& path) {
  if (!mesh.hasTexcoords()) throw UsageError(path + " has no texture coordinates (vt): give --projector");
  UvMap uv;
  uv.uv.resize(3 * mesh.faceCount(), Vec2::Zero());
  // What the file's UVs cannot tell (pole faces, faces turned away from a planar projection), as a
  // uvtk writer listed it (io/face_lists.h).
  uv.faceFlags = mesh.listedFaceFlags;
  uv.faceFlags.resize(mesh.faceCount(), kFaceOk);
  uv.w.assign(3 * mesh.faceCount(), 0.0);
  uv.cornerInvalid.assign(3 * mesh.faceCount(), 0);
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::size_t corner = 3 * f + std::size_t(k);
      const int t = mesh.cornerTexcoords[f][k];
      if (t >= 0) {
        uv.uv[corner] = mesh.texcoords[std::size_t(t)].head<2>();
        uv.w[corner] = mesh.texcoords[std::size_t(t)].z();
      } else {
        uv.cornerInvalid[corner] = kCornerNoTexcoord;
        uv.faceFlags[f] |= kFaceInvalid;
      }
    }
  markFannedPoles(mesh, uv);
  return uv;
}

MappedMesh mapByProjector(Mesh mesh, param::ProjectorOptions options, bool seamPlaceAuto, int threads) {
  MappedMesh out;
  if (seamPlaceAuto) {
    out.seamPlacement = param::placeSeam(mesh, options);
    options.placement.turnDegrees = out.seamPlacement->turnDegrees;
  }
  out.projection = param::project(std::move(mesh), options, threads);
  out.mesh = std::move(out.projection->mesh);
  out.uv = std::move(out.projection->uv);
  out.projector = options;
  out.source = "projector";
  out.exact = projectorPixelMapping(options, *out.projection, out.mesh, out.uv);
  analysis::markTurnedAwayFaces(out.mesh, out.projectionDirections(), out.uv, threads);
  if (param::traitsOf(options.surface).isPerspective) {
    const param::CameraTransform camera(options.camera);
    out.cameraQ.assign(out.uv.uv.size(), 1.0);
    for (std::size_t f = 0; f < out.mesh.faceCount(); ++f)
      for (int k = 0; k < 3; ++k) {
        const std::size_t c = 3 * f + std::size_t(k);
        if (out.uv.cornerInvalid[c] == kCornerValid)
          out.cameraQ[c] = camera.homogeneous(out.mesh.positions[out.mesh.triangles[f][k]]).w();
      }
  }
  return out;
}

MappedMesh mapByTexgen(Mesh mesh, const texgen::TexgenOptions& options) {
  MappedMesh out;
  texgen::TexgenResult generated = texgen::generateTexcoords(mesh, options);
  out.uv = std::move(generated.uv);
  out.q = std::move(generated.q);
  out.mesh = std::move(mesh);
  out.source = "texgen";
  out.exact = render::PixelMapping{
      [options](const Vec3& p, const Vec3& n, std::int32_t) { return texgen::texgenAt(p, n, options); }, false, true};
  return out;
}

MappedMesh withFileUvs(Mesh mesh, const std::string& path) {
  MappedMesh out;
  out.uv = fileUvs(mesh, path);
  out.mesh = std::move(mesh);
  out.source = "file";
  return out;
}

void addMappingOrigin(nlohmann::json& record, const MappedMesh& mapped) {
  if (mapped.projector) record["options"] = inspect::projectorOptionsJson(*mapped.projector);
  if (mapped.seamPlacement) record["seam_placement"] = inspect::seamPlacementJson(*mapped.seamPlacement);
}

nlohmann::json mapSummaryJson(const MappedMesh& mapped, const analysis::Judgement& judgement,
                              const nlohmann::json& input, const std::string& output) {
  nlohmann::json j = mapped.projection ? summaryJson(mapped.projection->summary, mapped.projector && param::traitsOf(mapped.projector->surface).blendsProjections) : nlohmann::json::object();
  j["judgement"] = judgementJson(mapped, judgement);
  j["verdict"] = j["judgement"]["verdict"];
  j["reasons"] = j["judgement"]["reasons"];
  j["texcoords"] = mapped.source;
  if (!mapped.cameraQ.empty()) {
    // The camera projector's (s, t, q) = (u q, v q, q) per corner, 3 per face in face order: what
    // interpolates perspective-correctly, where the file holds the divided (u, v).
    const std::vector<Vec4> corners = mapped.corners(false);
    nlohmann::json homogeneous = nlohmann::json::array();
    for (const Vec4& c : corners) homogeneous.push_back({c[0], c[1], c[3]});
    j["homogeneous_texcoords"] = std::move(homogeneous);
  }
  if (const std::optional<analysis::Gutters> gutters = mapped.atlasGutters())
    j["atlas"] = atlasJson(*mapped.projection->atlas, *gutters);
  j["input"] = input;
  j["output"] = output;
  addMappingOrigin(j, mapped);
  return j;
}

std::optional<analysis::Gutters> MappedMesh::atlasGutters() const {
  if (!projection || !projection->atlas || !projector) return std::nullopt;
  const std::array<int, 2>& size = projector->atlas.textureSize;
  return analysis::measureGutters(mesh, uv, projection->atlas->chartOfFace, size[0], size[1]);
}

void printMappingNotes(const std::string& inputPath, const MeshWarnings& warnings, const MappedMesh& mapped) {
  printInputWarnings(inputPath, warnings);
  if (mapped.seamPlacement) param::printSeamPlacement(*mapped.seamPlacement);
  if (mapped.projection && mapped.projection->atlas && mapped.projection->atlas->fallbackCharts > 0) {
    const param::Atlas& a = *mapped.projection->atlas;
    std::string note = inputPath + ": note: " + std::to_string(a.fallbackCharts) + " of " +
                       std::to_string(a.charts.size()) + " charts kept their plane projection (" +
                       param::traitsOf(mapped.projector->surface).name + " failed on them)";
    for (const std::string& reason : a.fallbackReasons) note += "; " + reason;
    printProgressMessage(note);
  }
}

render::Camera ViewCamera::frame(const Mesh& mesh, const std::string& meshFile, int width, int height) const {
  return render::frameSphere(render::boundingSphere(mesh.positions), viewDir, up, render::Projection{}, width, height,
                             meshFile);
}

}  // namespace uvtk::inspect
