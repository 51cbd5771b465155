// `uvtk check --image`: a picture another renderer made of a mesh (a GPU, a shader) checked, pixel
// by pixel, against uvtk's rendering of the same scene under verify/'s tolerances: the report,
// the error mask and the record (docs/check.md, "Checking a screenshot").
#pragma once

#include <string>

#include "inspect/frame.h"
#include "inspect/mapped_mesh.h"
#include "render/renderer.h"
#include "verify/image_check.h"

namespace uvtk::inspect {

struct ImageCheckOptions {
  std::string input;      // the mesh file, for the report and the record
  std::string image;      // the shot: grey, grey and alpha, RGB or RGBA, of the frame's size
  std::string errorMask;  // the error mask (an 8-bit image); none when empty
  std::string json;       // the record; none when empty
  verify::ImagePrecision precision;
};

struct ImageCheckRun {
  std::string text;  // the report for stdout, every line ending in '\n', the status last
  bool pass = true;
};

// Reads the shot first (InputError "SHOT: error: ..." for a shot of another size than the frame,
// naming both, or of more than 4 channels), draws `mapped` with `options` (its texture
// coordinates as `frame` says: per vertex, per pixel or baked) and checks the shot against it,
// then writes the error mask and the record, published together. UsageError for a scene that
// verify::checkImage does not support.
ImageCheckRun checkImageShot(const ImageCheckOptions& a, const MappedMesh& mapped, const FrameOptions& frame,
                             const render::RenderOptions& options);

}  // namespace uvtk::inspect
