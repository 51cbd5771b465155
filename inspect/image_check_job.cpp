#include "inspect/image_check_job.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/json_text.h"

namespace uvtk::inspect {

namespace {

[[gnu::format(printf, 2, 3)]] void appendf(std::string& text, const char* format, ...) {
  char line[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(line, sizeof line, format, args);
  va_end(args);
  text += line;
}

nlohmann::json vec3Json(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

// Whether q varies over the corners: the lod tolerance's default is coarser for projective mappings.
bool projective(const render::TexcoordSource& texcoords) {
  const std::vector<Vec4>& c = texcoords.corners;
  return std::any_of(c.begin(), c.end(), [&](const Vec4& corner) { return corner.w() != c.front().w(); });
}

}  // namespace

ImageCheckRun checkImageShot(const ImageCheckOptions& a, const MappedMesh& mapped, const FrameOptions& frame,
                             const render::RenderOptions& options) {
  const Image shot = io::readTexture(a.image).image;  // grey, grey and alpha, RGB or RGBA, from its header
  if (shot.width != frame.width || shot.height != frame.height)
    throw InputError(a.image + ": error: the shot is " + std::to_string(shot.width) + "x" + std::to_string(shot.height) +
                     " pixels, the rendering " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                     " (--size)");
  const render::TexcoordSource texcoords = mapped.texcoordSource(frame.perPixel, frame.baked);
  const bool isProjective = projective(texcoords);
  const verify::Reference reference = verify::drawReference(mapped.mesh, texcoords, options);
  const verify::ImageCheckResult result = verify::checkImage(shot, reference, options, isProjective, a.precision);
  const verify::ImagePrecision& p = result.precision;

  ImageCheckRun run;
  run.pass = result.pass;
  std::string& text = run.text;
  appendf(text, "uvtk check: %s against %s as uvtk draws it (%dx%d)\n", a.image.c_str(), a.input.c_str(), frame.width,
          frame.height);
  appendf(text,
          "tolerances: coordinates max(1, |c|) 2^-%d texel, filter weights 2^-%d, level of detail 2^-%d beyond its "
          "neighbours', colour 2^-%d\n",
          p.coordBits, p.weightBits, *p.lodBits, *p.colorBits);
  appendf(text, "pixels: %zu checked, %zu invalid (%.3f%%)\n", result.checked, result.invalid,
          100.0 * result.invalidShare);
  for (const verify::InvalidPixel& q : result.firstInvalid)
    appendf(text, "  x %d, row %d: shot %.4f %.4f %.4f, valid %.4f..%.4f %.4f..%.4f %.4f..%.4f\n", q.x, q.row,
            q.shot.x(), q.shot.y(), q.shot.z(), q.low.x(), q.high.x(), q.low.y(), q.high.y(), q.low.z(), q.high.z());
  if (result.invalid > result.firstInvalid.size())
    appendf(text, "  ... and %zu more (the error mask shows them all)\n", result.invalid - result.firstInvalid.size());
  appendf(text, result.pass ? "uvtk check: PASS\n" : "uvtk check: FAIL (%zu invalid pixels)\n", result.invalid);

  io::OutputSet outputs;  // the mask and the record, published together
  if (!a.errorMask.empty()) io::writeImage(outputs, a.errorMask, result.errorMask, io::PixelType::UInt8);
  if (!a.json.empty()) {
    nlohmann::json invalid = nlohmann::json::array();
    for (const verify::InvalidPixel& q : result.firstInvalid)
      invalid.push_back({{"x", q.x}, {"row", q.row}, {"shot", vec3Json(q.shot)}, {"low", vec3Json(q.low)},
                         {"high", vec3Json(q.high)}});
    const nlohmann::json record = {
        {"input", a.input},
        {"image", a.image},
        {"width", frame.width},
        {"height", frame.height},
        {"projective", isProjective},
        {"precision",
         {{"coord_bits", p.coordBits}, {"weight_bits", p.weightBits}, {"lod_bits", *p.lodBits}, {"color_bits", *p.colorBits}}},
        {"checked", result.checked},
        {"invalid", result.invalid},
        {"invalid_share", result.invalidShare},
        {"first_invalid", invalid},
        {"error_mask", a.errorMask.empty() ? nlohmann::json() : nlohmann::json(a.errorMask)},
        {"status", result.pass ? "pass" : "fail"}};
    outputs.writeText(a.json, io::jsonText(record, 2) + "\n");
  }
  outputs.publish();
  return run;
}

}  // namespace uvtk::inspect
