#include "inspect/frame.h"

#include <algorithm>
#include <chrono>
#include <sstream>

#include "core/error.h"
#include "core/stopwatch.h"
#include "inspect/measures_json.h"
#include "io/image_io.h"
#include "render/procedural.h"

namespace uvtk::inspect {

namespace {

// The cube-map sources read from files: the word, and the layout of its single image (Faces for
// the six files of cubefaces).
const std::vector<std::pair<std::string, CubeLayout>> kCubeFileSources = {{"cubefaces", CubeLayout::Faces},
                                                                          {"cubecross", CubeLayout::Cross},
                                                                          {"cubestrip", CubeLayout::Strip},
                                                                          {"cube3x2", CubeLayout::ThreeByTwo}};

// The cube-map file source `source` begins with ("word:"), if any.
const std::pair<std::string, CubeLayout>* cubeFileSource(const std::string& source) {
  for (const auto& entry : kCubeFileSources)
    if (source.compare(0, entry.first.size() + 1, entry.first + ":") == 0 || source == entry.first) return &entry;
  return nullptr;
}

// The files of a comma-separated list, empty ones kept (they are refused).
std::vector<std::string> fileList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) items.push_back(item);
  return items;
}

Image selectChannels(const Image& all, const std::vector<std::string>& names) {
  std::vector<int> source;
  for (const std::string& name : names)
    source.push_back(int(std::find(all.channelNames.begin(), all.channelNames.end(), name) - all.channelNames.begin()));
  Image out(all.width, all.height, int(names.size()));
  out.channelNames = names;
  for (int y = 0; y < all.height; ++y)
    for (int x = 0; x < all.width; ++x)
      for (std::size_t k = 0; k < source.size(); ++k) out.at(x, y, int(k)) = all.at(x, y, source[k]);
  return out;
}

// The named inspection views: one picture, or a contact sheet of several.
DrawnFrame drawViews(const FrameOptions& frame, const MappedMesh& mapped, const render::RenderOptions& renderOptions,
                     const std::function<const analysis::Judgement&()>& judgement) {
  const analysis::Judgement* measured = frame.showsMeasures() ? &judgement() : nullptr;
  views::ViewOptions options;
  options.render = renderOptions;
  options.layoutFill = frame.layoutFill;
  options.layoutSize = frame.layoutSize;
  options.bleedLevel = frame.bleedLevel;
  options.checks = frame.checks;
  options.perPixel = frame.perPixel;

  DrawnFrame out;
  out.record = {{"texcoords", mapped.source}, {"views", nlohmann::json::array()}};
  std::vector<std::pair<std::string, Image>> tiles;
  for (const views::View view : frame.views) {
    const views::DrawnView drawn = views::drawViewAndLegend(view, mapped.viewInput(measured), options);
    tiles.emplace_back(views::toString(view),
                       drawn.legend.empty() ? drawn.image : views::withLegend(drawn.image, drawn.legend));
    out.record["views"].push_back(views::toString(view));
    out.record["legends"][views::toString(view)] = drawn.legend.lines();
    if (view == views::View::UvError) {
      const views::UvErrorMap error = views::uvErrorMap(mapped.viewInput(measured), options);
      out.record["uverror_texels"] = {
          {"max", error.max}, {"mean", error.mean}, {"pixels", error.pixels}, {"invalid_pixels", error.invalidPixels}};
    }
    if ((view == views::View::Weights || view == views::View::BlendZone) && !out.record.contains("blend_zone")) {
      out.record["blend_zone"] = blendZoneJson(views::blendZone(mapped.viewInput(measured), options));
    }
    if (view == views::View::MipLine) out.record["mip_line"] = mipLineJson(views::mipLine(mapped.viewInput(measured), options));
  }
  out.picture =
      tiles.size() == 1 ? tiles.front().second : views::contactSheet(tiles, std::min<int>(3, int(tiles.size())));
  out.record["width"] = out.picture.width;
  out.record["height"] = out.picture.height;
  return out;
}

}  // namespace

bool isCubeMapSource(const std::string& source) {
  return cubeFileSource(source) != nullptr || render::isProceduralCubeName(source);
}

std::vector<std::string> textureFiles(const std::string& source) {
  if (render::isProceduralName(source)) return {};
  const auto* cube = cubeFileSource(source);
  if (!cube) return {source};
  const std::string list = source.size() > cube->first.size() ? source.substr(cube->first.size() + 1) : "";
  std::vector<std::string> out = cube->second == CubeLayout::Faces ? fileList(list) : std::vector<std::string>{list};
  const std::size_t expected = cube->second == CubeLayout::Faces ? 6 : 1;
  if (out.size() != expected || std::any_of(out.begin(), out.end(), [](const std::string& f) { return f.empty(); }))
    throw UsageError("texture '" + source + "': expected " +
                     (expected == 6 ? "cubefaces:PX,NX,PY,NY,PZ,NZ (six image files)" : cube->first + ":FILE"));
  return out;
}

std::string resolveTextureFiles(const std::string& source,
                                const std::function<std::string(const std::string&)>& resolve) {
  const std::vector<std::string> list = textureFiles(source);
  if (list.empty()) return source;
  const auto* cube = cubeFileSource(source);
  std::string resolved = cube ? cube->first + ":" : "";
  for (std::size_t k = 0; k < list.size(); ++k) resolved += (k ? "," : "") + resolve(list[k]);
  return resolved;
}

BoundTexture loadTexture(const std::string& source, render::Filter filter) {
  BoundTexture bound;
  if (std::optional<render::CubeTexture> made = render::proceduralCubeTexture(source)) {
    bound.cube = std::move(*made);
  } else if (std::optional<render::Texture> flat = render::proceduralTexture(source)) {
    bound.flat = std::move(*flat);
  } else {
    // A texture's texel limit is checked from each file's header, before its pixels are read; a
    // cube map's faces share it (six files a sixth each, an atlas as one image).
    const std::vector<std::string> list = textureFiles(source);
    std::vector<Image> images;
    bool eightBit = true;
    for (const std::string& file : list) {
      io::ImageFile read = io::readTexture(file, render::kMaxTexels / std::int64_t(list.size()));
      eightBit = eightBit && read.eightBit;
      images.push_back(std::move(read.image));
    }
    const auto* cube = cubeFileSource(source);
    if (!cube)
      bound.flat = render::Texture::fromImage(images[0], eightBit);
    else if (cube->second == CubeLayout::Faces)
      bound.cube = render::CubeTexture::fromImages(images, list, eightBit);
    else
      bound.cube = render::CubeTexture::fromLayoutImage(images[0], cube->second, list[0], eightBit);
  }
  if (render::needsMipmaps(filter)) {
    if (bound.flat) bound.flat->buildMipmaps();
    if (bound.cube) bound.cube->buildMipmaps();
  }
  return bound;
}

bool FrameOptions::showsMeasures() const {
  return std::any_of(views.begin(), views.end(), [](views::View v) {
    return v != views::View::Checker && v != views::View::Uvgrid && v != views::View::UvError &&
           v != views::View::Weights && v != views::View::BlendZone;
  });
}

bool FrameOptions::needsExact() const {
  return perPixel || std::any_of(views.begin(), views.end(), views::needsExactMapping);
}

render::RenderOptions renderOptions(const FrameOptions& frame, const TextureOptions& texture,
                                    const BoundTexture& bound, const render::Camera& camera,
                                    const Mat4& worldFromObject) {
  render::RenderOptions options;
  options.camera = camera;
  options.worldFromObject = worldFromObject;
  options.derivatives = frame.derivatives;
  options.seamFix = frame.seamFix;
  options.raster = {frame.cull, frame.threads};
  options.samplesPerPixel = frame.samplesPerPixel;
  options.sampler = render::samplerFor(texture.filter, texture.wrap);
  options.env = texture.env;
  options.envColour = texture.envColour;
  options.background = frame.background;
  options.texture = bound.flat ? &*bound.flat : nullptr;
  options.cubeTexture = bound.cube ? &*bound.cube : nullptr;
  options.seamless = texture.seamless;
  options.lighting.twoSided = texture.twoSided;
  return options;
}

Image renderView(views::View view, const MappedMesh& mapped, const analysis::Judgement* judgement,
                 const views::ViewOptions& options) {
  const views::DrawnView drawn = views::drawViewAndLegend(view, mapped.viewInput(judgement), options);
  return drawn.legend.empty() ? drawn.image : views::withLegend(drawn.image, drawn.legend);
}

DrawnFrame drawFrame(const FrameOptions& frame, const MappedMesh& mapped, const render::RenderOptions& options,
                     const std::function<const analysis::Judgement&()>& judgement) {
  UVTK_CHECK(!frame.needsExact() || mapped.exact);  // the callers refuse the file's UVs before any work
  if (!frame.views.empty()) return drawViews(frame, mapped, options, judgement);

  render::RenderOptions withAovs = options;
  withAovs.aovs = !frame.aovs.empty();
  const render::Rendering rendering = render::render(mapped.mesh, mapped.texcoordSource(frame.perPixel, frame.baked), withAovs);
  DrawnFrame out;
  out.picture = rendering.colour;
  if (!frame.aovs.empty()) out.aovs = selectChannels(rendering.aovs, frame.aovs);
  out.record = {{"texcoords", mapped.source},
                {"uv", frame.perPixel ? "per-pixel" : frame.baked ? "baked" : "per-vertex"},
                {"derivatives", render::toString(options.derivatives)},
                {"seam_fix", render::toString(options.seamFix)},
                {"spp", options.samplesPerPixel},
                {"width", options.camera.width},
                {"height", options.camera.height},
                {"faces", mapped.mesh.faceCount()},
                {"faces_drawn", rendering.raster.drawn},
                {"faces_culled", rendering.raster.culled},
                {"faces_clipped", rendering.raster.clipped},
                {"covered_pixels", rendering.coveredPixels},
                {"milliseconds", {{"raster", rendering.rasterMs}, {"shade", rendering.shadeMs}}}};
  if (options.texture)
    out.record["texture"] = {{"kind", "2d"},
                             {"width", options.texture->width()},
                             {"height", options.texture->height()},
                             {"levels", options.texture->levelCount()},
                             {"seamless", false}};
  if (options.cubeTexture)
    out.record["texture"] = {{"kind", "cube"},
                             {"size", options.cubeTexture->size()},
                             {"levels", options.cubeTexture->levelCount()},
                             {"seamless", options.seamless}};
  return out;
}

nlohmann::json writeFrame(io::OutputSet& outputs, const FrameOptions& frame, const std::string& output,
                          const std::string& aovOutput, const MappedMesh& mapped,
                          const render::RenderOptions& options,
                          const std::function<const analysis::Judgement&()>& judgement) {
  DrawnFrame drawn = drawFrame(frame, mapped, options, judgement);
  const auto writeStart = std::chrono::steady_clock::now();
  io::writeImage(outputs, output, drawn.picture, io::PixelType::UInt8);
  if (drawn.aovs) io::writeImage(outputs, aovOutput, *drawn.aovs, io::PixelType::Float);
  drawn.record["output"] = output;
  if (!frame.views.empty()) return drawn.record;
  drawn.record["milliseconds"]["write"] = millisecondsSince(writeStart);
  if (drawn.aovs) drawn.record["aov_output"] = aovOutput;
  return drawn.record;
}

}  // namespace uvtk::inspect
