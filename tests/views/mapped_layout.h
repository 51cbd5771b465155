// A mesh with its UVs and what the views read from them: the fixture the view tests share.
#pragma once

#include <optional>
#include <vector>

#include "analysis/judgement.h"
#include "core/mesh.h"
#include "core/uv_map.h"
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

}  // namespace uvtk::views
