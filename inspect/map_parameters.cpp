#include "inspect/map_parameters.h"

#include <cmath>
#include <cstdio>

namespace uvtk::inspect {

namespace {

analysis::TextureSize textureSizeOf(const param::ParameterDictionary& p) {
  analysis::TextureSize size;
  if (const std::optional<std::array<int, 2>> wh = param::readTextureSize(p)) size.width = (*wh)[0], size.height = (*wh)[1];
  return size;
}

}  // namespace

analysis::Thresholds readThresholds(const param::ParameterDictionary& p) {
  analysis::Thresholds t;
  for (const std::string& entry : p.getTexts("fail-on"))
    if (!analysis::parseVerdict(entry)) t.set(entry, analysis::Verdict::Fail, p.spelled("fail-on"));
  for (const std::string& entry : p.getTexts("warn-on")) t.set(entry, analysis::Verdict::Warn, p.spelled("warn-on"));
  return t;
}

int readOverlapResolution(const param::ParameterDictionary& p, int fallback) {
  return p.getInteger("overlap-resolution", fallback, analysis::kOverlapFollowsMesh, analysis::kMaxOverlapResolution);
}

void checkOverlapResolution(int overlapResolution) {
  if (overlapResolution < analysis::kOverlapFollowsMesh || overlapResolution > analysis::kMaxOverlapResolution)
    throw UsageError("--overlap-resolution: expected " + std::to_string(analysis::kOverlapFollowsMesh) + " to " +
                     std::to_string(analysis::kMaxOverlapResolution) + " pixels");
}

MapSettings readMapSettings(const param::ParameterDictionary& p) {
  MapSettings s;
  s.projector = param::makeProjector(p);
  s.thresholds = readThresholds(p);
  s.overlapResolution = readOverlapResolution(p, analysis::kOverlapFollowsMesh);
  s.textureSize = textureSizeOf(p);
  if (p.given("density")) {
    const double density = p.getNumber("density", 0.0);
    if (!(density > 0.0 && std::isfinite(density))) {
      char found[32];
      std::snprintf(found, sizeof found, "%g", density);
      throw UsageError(p.spelled("density") + ": expected a positive number of texels per object unit, found " + found);
    }
    s.density = density;
  }
  s.threads = p.getInteger("threads", 0, 0, 1024);
  return s;
}

std::vector<std::string> mapParameterNames() {
  std::vector<std::string> names = param::projectorParameterNames();
  names.insert(names.end(), {"fail-on", "warn-on", "overlap-resolution", "texture-size", "density", "threads"});
  return names;
}

}  // namespace uvtk::inspect
