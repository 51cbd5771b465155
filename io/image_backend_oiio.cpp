// The image plugin: io/image_backend.h over OpenImageIO. Only calls into OpenImageIO live here;
// the checks, limits, rounding and messages stay in io/image_io.cpp.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <memory>

#include "io/image_backend.h"

namespace uvtk::io::backend {

struct Reader {
  std::unique_ptr<OIIO::ImageInput> input;
  Stored stored;
};

namespace {

Reader* openImage(const std::string& path, Header& header, std::string& error) {
  // Keep alpha as stored: by default PNG and TIFF readers premultiply colour by it.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = OIIO::ImageInput::open(path, &config);
  if (!input) {
    error = OIIO::geterror();
    return nullptr;
  }
  const OIIO::ImageSpec& spec = input->spec();
  header.width = spec.width;
  header.height = spec.height;
  header.depth = spec.depth;
  header.channels = spec.nchannels;
  header.channelNames.clear();
  for (int c = 0; c < spec.nchannels; ++c) header.channelNames.push_back(spec.channel_name(c));
  const auto storedAs = [&](OIIO::TypeDesc type) {
    return spec.format == type && std::all_of(spec.channelformats.begin(), spec.channelformats.end(),
                                              [&](OIIO::TypeDesc t) { return t == type; });
  };
  header.stored = storedAs(OIIO::TypeDesc::UINT8)    ? Stored::UInt8
                  : storedAs(OIIO::TypeDesc::UINT16) ? Stored::UInt16
                                                     : Stored::Other;
  return new Reader{std::move(input), header.stored};
}

// Integer pixels divided by their maximum here rather than by OpenImageIO, whose conversion
// multiplies by the reciprocal and so may differ from v / 255 in the last bit.
template <typename T>
bool readScaled(OIIO::ImageInput& in, int channels, float maximum, float* pixels) {
  const OIIO::ImageSpec& spec = in.spec();
  std::vector<T> stored(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(channels));
  if (!in.read_image(0, 0, 0, channels, OIIO::BaseTypeFromC<T>::value, stored.data())) return false;
  std::transform(stored.begin(), stored.end(), pixels, [&](T v) { return float(v) / maximum; });
  return true;
}

bool readPixels(Reader* reader, int channels, float* pixels, std::string& error) {
  OIIO::ImageInput& in = *reader->input;
  bool read = false;
  if (reader->stored == Stored::UInt8) {
    read = readScaled<std::uint8_t>(in, channels, 255.0f, pixels);
  } else if (reader->stored == Stored::UInt16) {
    read = readScaled<std::uint16_t>(in, channels, 65535.0f, pixels);
  } else {
    read = in.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels);
  }
  if (!read) error = in.geterror();
  return read;
}

void closeImage(Reader* reader) {
  if (reader->input) reader->input->close();
  delete reader;
}

std::unique_ptr<OIIO::ImageOutput> writerFor(const std::string& path, OIIO::Filesystem::IOProxy* proxy = nullptr) {
  auto out = OIIO::ImageOutput::create(path, proxy);
  if (!out) OIIO::geterror();  // drop OpenImageIO's own message so it is not printed at exit
  return out;
}

std::string writerFormat(const std::string& path) {
  const auto out = writerFor(path);
  return out ? out->format_name() : "";
}

OIIO::ImageSpec specOf(const Pixels& pixels) {
  OIIO::ImageSpec spec(pixels.width, pixels.height, pixels.channels,
                       pixels.isFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (pixels.channelNames && !pixels.channelNames->empty()) {
    spec.channelnames = *pixels.channelNames;
    const auto alpha = std::find(spec.channelnames.begin(), spec.channelnames.end(), "A");
    spec.alpha_channel = alpha == spec.channelnames.end() ? -1 : int(alpha - spec.channelnames.begin());
  }
  // Store alpha as given: by default PNG and TIFF writers divide colour by it.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  return spec;
}

bool writeImage(const std::string& path, const std::string& file, const Pixels& pixels, std::string& error) {
  auto out = writerFor(path);  // by the target's extension: `file` may have none
  if (!out) {
    error = "cannot write images of this type";
    return false;
  }
  const OIIO::ImageSpec spec = specOf(pixels);
  if (!out->open(file, spec)) {
    error = out->geterror();
    return false;
  }
  const bool written = out->write_image(spec.format, pixels.data);
  const bool closed = out->close();
  if (!written || !closed) error = out->geterror();
  return written && closed;
}

bool encodePng(const Pixels& pixels, std::string& bytes, std::string& error) {
  std::vector<unsigned char> buffer;
  OIIO::Filesystem::IOVecOutput memory(buffer);
  auto out = writerFor("memory.png", &memory);
  const OIIO::ImageSpec spec = specOf(pixels);
  if (!out || !out->open("memory.png", spec) || !out->write_image(spec.format, pixels.data) || !out->close()) {
    error = out ? out->geterror() : OIIO::geterror();
    return false;
  }
  bytes.assign(buffer.begin(), buffer.end());
  return true;
}

constexpr Functions kFunctions{kVersion, openImage, readPixels, closeImage, writerFormat, writeImage, encodePng};

}  // namespace

}  // namespace uvtk::io::backend

extern "C" __attribute__((visibility("default"))) const uvtk::io::backend::Functions* uvtk_image_backend() {
  return &uvtk::io::backend::kFunctions;
}
