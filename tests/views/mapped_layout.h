// A mesh with its UVs and what the views read from them: the fixture the view tests share.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "analysis/judgement.h"
#include "core/mesh.h"
#include "core/uv_map.h"
#include "param/projector.h"
#include "render/renderer.h"
#include "views/views.h"

namespace uvtk::views {

struct Mapped {
  Mesh mesh;
  UvMap uv;
  analysis::Judgement judgement;
  std::optional<render::PixelMapping> exact;
  bool wrapsU = false;
  std::vector<double> q;  // texgen's

  // After the UVs change.
  void analyse() {
    analysis::JudgementOptions options;
    options.overlapResolution = 256;
    judgement = analysis::judge(mesh, uv, options);
  }
  ViewInput input() const {
    ViewInput in;
    in.mesh = &mesh, in.uv = &uv, in.judgement = &judgement;
    in.wrapsU = wrapsU, in.exact = exact;
    in.q = q.empty() ? nullptr : &q;
    return in;
  }
};

// The mesh through a projector, with the exact mapping as apps/uvtk/cmd_render.cpp builds it.
inline Mapped mapWith(Mesh mesh, const param::ProjectorOptions& options) {
  param::Projection projection = param::project(std::move(mesh), options);
  Mapped m;
  m.mesh = std::move(projection.mesh);
  m.uv = std::move(projection.uv);
  m.analyse();
  auto mapping = std::make_shared<param::Projector>(options, projection.localFromObject);
  m.wrapsU = mapping->traits().wraps;
  m.exact = render::PixelMapping{[mapping](const Vec3& p, const Vec3& n, std::int32_t) -> Vec4 {
                                   const param::PointUv uv = mapping->at(p, n);
                                   const double nan = std::numeric_limits<double>::quiet_NaN();
                                   return uv.state == param::CornerState::Invalid ? Vec4(nan, nan, 0, 1)
                                                                                  : Vec4(uv.uv.x(), uv.uv.y(), 0, 1);
                                 },
                                 mapping->traits().wraps, mapping->needsNormal()};
  return m;
}

inline param::ProjectorOptions projector(param::SurfaceKind surface) {
  param::ProjectorOptions o;
  o.surface = surface;
  if (surface != param::SurfaceKind::Plane) o.placement.fit = param::Fit::None;  // the generators' own axes
  return o;
}

}  // namespace uvtk::views
