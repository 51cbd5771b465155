#include "io/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "io/atomic_file.h"

namespace uvtk::io {

namespace {

constexpr int kMaxSide = 16384;
constexpr int kMaxChannels = 64;

// OpenImageIO's messages may span several lines; ours are one line each. Some of its readers fail
// without a message: then `silent` says what failed.
std::string oneLine(const std::string& message, const char* silent = "unknown OpenImageIO error") {
  std::istringstream lines(message);
  std::string line, joined;
  while (std::getline(lines, line)) {
    const auto begin = line.find_first_not_of(" \t\r");
    if (begin == std::string::npos) continue;
    const auto end = line.find_last_not_of(" \t\r");
    if (!joined.empty()) joined += "; ";
    joined += line.substr(begin, end - begin + 1);
  }
  return joined.empty() ? silent : joined;
}

InputError readFailure(const std::string& path, const std::string& what) {
  return InputError(path + ": error: " + what);
}

// OpenImageIO reports a missing file or a folder vaguely; the system says it plainly.
void checkReadable(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) throw readFailure(path, std::string("cannot open: ") + std::strerror(errno));
  struct stat info {};
  const bool isDirectory = ::fstat(fd, &info) == 0 && S_ISDIR(info.st_mode);
  ::close(fd);
  if (isDirectory) throw readFailure(path, "cannot open: Is a directory");
}

// A PNG (by its signature, whatever the extension) is checked chunk by chunk before OpenImageIO
// reads it: on a truncated or corrupted PNG, OpenImageIO 2.4's error handler returns to libpng,
// which then prints "libpng error: ..." on stderr beside our message, and the read leaks. Checked:
// each chunk's length fits the file, its CRC, IHDR first and IEND last. A deflate stream broken
// under valid CRCs still reaches libpng.
void checkPngChunks(const std::string& path) {
  static constexpr char kSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1A', '\n'};
  std::ifstream in(path, std::ios::binary);
  char head[8];
  if (!in.read(head, 8) || !std::equal(head, head + 8, kSignature)) return;
  const auto bigEndian = [](const char* p) {
    return std::uint32_t(std::uint8_t(p[0])) << 24 | std::uint32_t(std::uint8_t(p[1])) << 16 |
           std::uint32_t(std::uint8_t(p[2])) << 8 | std::uint32_t(std::uint8_t(p[3]));
  };
  std::vector<char> block(1 << 16);
  for (int chunk = 0;; ++chunk) {
    const std::string which = "chunk " + std::to_string(chunk);
    if (!in.read(head, 8)) throw readFailure(path, "cannot read: truncated PNG (" + which + " is cut off)");
    const std::string type(head + 4, 4);
    if (chunk == 0 && type != "IHDR")
      throw readFailure(path, "cannot read: corrupted PNG (the first chunk is not IHDR)");
    uLong crc = crc32(crc32(0, nullptr, 0), reinterpret_cast<const Bytef*>(head + 4), 4);
    for (std::uint32_t left = bigEndian(head); left > 0;) {
      const std::uint32_t n = std::min<std::uint32_t>(left, std::uint32_t(block.size()));
      if (!in.read(block.data(), n))
        throw readFailure(path, "cannot read: truncated PNG (" + which + ", " + type + ", is cut off)");
      crc = crc32(crc, reinterpret_cast<const Bytef*>(block.data()), n);
      left -= n;
    }
    char stored[4];
    if (!in.read(stored, 4))
      throw readFailure(path, "cannot read: truncated PNG (" + which + ", " + type + ", is cut off)");
    if (crc != bigEndian(stored))
      throw readFailure(path, "cannot read: corrupted PNG (" + which + ", " + type + ", fails its CRC)");
    if (type == "IEND") return;
  }
}

// Integer pixels divided by their maximum here rather than by OpenImageIO, whose conversion
// multiplies by the reciprocal and so may differ from v / 255 in the last bit.
template <typename T>
bool readScaled(OIIO::ImageInput& in, int channels, float maximum, std::vector<float>& pixels) {
  std::vector<T> stored(pixels.size());
  if (!in.read_image(0, 0, 0, channels, OIIO::BaseTypeFromC<T>::value, stored.data())) return false;
  std::transform(stored.begin(), stored.end(), pixels.begin(), [&](T v) { return float(v) / maximum; });
  return true;
}

std::uint8_t toUInt8(float c) {
  if (!(c > 0.0f)) return 0;  // also NaN
  if (c >= 1.0f) return 255;
  return static_cast<std::uint8_t>(std::lround(static_cast<double>(c) * 255.0));
}

// The writer for `path`'s format; throws UsageError when there is none or it cannot hold `type`.
std::unique_ptr<OIIO::ImageOutput> writerFor(const std::string& path, PixelType type) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    OIIO::geterror();  // drop OpenImageIO's own message so it is not printed at exit
    throw UsageError(path + ": error: cannot write images of this type");
  }
  // OpenImageIO has no query for float support; writers of other formats silently convert.
  const std::string format = out->format_name();
  if (type == PixelType::Float && format != "openexr" && format != "tiff")
    throw UsageError(path + ": error: cannot write float pixels to a " + format + " file (use .exr, .tif or .tiff)");
  return out;
}

}  // namespace

namespace {

ImageFile readLimited(const std::string& path, std::int64_t maxValues, std::int64_t maxPixels, int maxChannels) {
  checkReadable(path);
  checkPngChunks(path);
  // Keep alpha as stored: by default PNG and TIFF readers premultiply colour by it.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) throw readFailure(path, "cannot read: " + oneLine(OIIO::geterror()));

  const OIIO::ImageSpec spec = in->spec();  // the first subimage, level 0
  if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1 || spec.nchannels <= 0)
    throw readFailure(path, "image is empty or not two-dimensional (" + std::to_string(spec.width) + " x " +
                                std::to_string(spec.height) + " x " + std::to_string(spec.depth) + ", " +
                                std::to_string(spec.nchannels) + " channels)");
  if (spec.width > kMaxSide || spec.height > kMaxSide)
    throw readFailure(path, "image is " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                                ", larger than the " + std::to_string(kMaxSide) + " x " + std::to_string(kMaxSide) +
                                " limit");

  if (spec.nchannels > maxChannels) {
    std::string names;
    for (int c = 0; c < spec.nchannels; ++c) names += (c ? ", " : "") + std::string(spec.channel_name(c));
    throw readFailure(path, "image has " + std::to_string(spec.nchannels) + " channels (" + printable(names) +
                                "); a texture takes 1 to 4 (grey, grey and alpha, RGB, RGBA)");
  }
  const int channels = std::min(spec.nchannels, kMaxChannels);
  const std::int64_t pixelCount = std::int64_t(spec.width) * spec.height, values = pixelCount * channels;
  if (pixelCount > maxPixels)
    throw readFailure(path, "image is " + std::to_string(spec.width) + " x " + std::to_string(spec.height) + ", " +
                                std::to_string(pixelCount) + " pixels, more than the limit of " +
                                std::to_string(maxPixels));
  if (values > maxValues) {
    std::ostringstream message;
    message << "image is " << spec.width << " x " << spec.height << " x " << channels << " channels, "
            << double(values) * sizeof(float) / double(1 << 30) << " GiB as float, more than the "
            << double(maxValues) * sizeof(float) / double(1 << 30) << " GiB limit";
    throw readFailure(path, message.str());
  }

  ImageFile file;
  file.image = Image(spec.width, spec.height, channels);
  for (int c = 0; c < channels; ++c) file.image.channelNames.push_back(spec.channel_name(c));
  const auto storedAs = [&](OIIO::TypeDesc type) {
    return spec.format == type && std::all_of(spec.channelformats.begin(), spec.channelformats.end(),
                                              [&](OIIO::TypeDesc t) { return t == type; });
  };
  file.eightBit = storedAs(OIIO::TypeDesc::UINT8);
  std::vector<float>& pixels = file.image.pixels;
  bool read = false;
  if (file.eightBit) {
    read = readScaled<std::uint8_t>(*in, channels, 255.0f, pixels);
  } else if (storedAs(OIIO::TypeDesc::UINT16)) {
    read = readScaled<std::uint16_t>(*in, channels, 65535.0f, pixels);
  } else {
    read = in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data());
  }
  if (!read) throw readFailure(path, "cannot read: " + oneLine(in->geterror(), "the pixels are missing or corrupt"));
  in->close();
  return file;
}

}  // namespace

ImageFile readImage(const std::string& path, std::int64_t maxValues, std::int64_t maxPixels) {
  return readLimited(path, maxValues, maxPixels, std::numeric_limits<int>::max());
}

ImageFile readTexture(const std::string& path, std::int64_t maxPixels) {
  return readLimited(path, kMaxImageValues, maxPixels, 4);
}

void checkImageType(const std::string& path, PixelType type) { writerFor(path, type); }

namespace {

// The spec of `image` stored as `type`; for UInt8 also its rounded pixels, by our own rounding
// rather than OpenImageIO's conversion, so that NaN and the halfway cases are defined.
OIIO::ImageSpec specFor(const Image& image, PixelType type, std::vector<std::uint8_t>& rounded) {
  const OIIO::TypeDesc pixelType = type == PixelType::UInt8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
  if (type == PixelType::UInt8) {
    rounded.resize(image.pixels.size());
    std::transform(image.pixels.begin(), image.pixels.end(), rounded.begin(), toUInt8);
  }
  OIIO::ImageSpec spec(image.width, image.height, image.channels, pixelType);
  if (!image.channelNames.empty()) {
    spec.channelnames = image.channelNames;
    const auto alpha = std::find(spec.channelnames.begin(), spec.channelnames.end(), "A");
    spec.alpha_channel = alpha == spec.channelnames.end() ? -1 : int(alpha - spec.channelnames.begin());
  }
  // Store alpha as given: by default PNG and TIFF writers divide colour by it.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  return spec;
}

}  // namespace

void writeImage(OutputSet& outputs, const std::string& path, const Image& image, PixelType type) {
  UVTK_CHECK(image.width > 0 && image.height > 0 && image.channels > 0);
  UVTK_CHECK(image.pixels.size() == image.index(0, image.height));
  UVTK_CHECK(image.channelNames.empty() || int(image.channelNames.size()) == image.channels);

  auto out = writerFor(path, type);  // by the target's extension: the temporary's path may have none

  std::vector<std::uint8_t> rounded;
  const OIIO::ImageSpec spec = specFor(image, type, rounded);
  const void* pixels = type == PixelType::UInt8 ? static_cast<const void*>(rounded.data()) : image.pixels.data();
  const OIIO::TypeDesc pixelType = spec.format;

  const TemporaryFile& staged = outputs.stage(path);
  if (!out->open(staged.path(), spec)) throw writeError(staged.shownName(), oneLine(out->geterror()));
  const bool written = out->write_image(pixelType, pixels);
  const bool closed = out->close();
  if (!written || !closed) throw writeError(staged.shownName(), oneLine(out->geterror()));
}

void writeImage(const std::string& path, const Image& image, PixelType type) {
  OutputSet outputs;
  writeImage(outputs, path, image, type);
  outputs.publish();
}

std::string encodePng(const Image& image) {
  UVTK_CHECK(image.width > 0 && image.height > 0 && image.channels > 0);
  std::vector<std::uint8_t> rounded;
  const OIIO::ImageSpec spec = specFor(image, PixelType::UInt8, rounded);
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  auto out = OIIO::ImageOutput::create("memory.png", &memory);
  if (!out || !out->open("memory.png", spec) || !out->write_image(OIIO::TypeDesc::UINT8, rounded.data()) ||
      !out->close())
    throw std::runtime_error("OpenImageIO: cannot encode a PNG in memory: " + OIIO::geterror());
  return std::string(bytes.begin(), bytes.end());
}

std::string pngDataUri(const Image& image) {
  return "data:image/png;base64," + OIIO::Strutil::base64_encode(encodePng(image));
}

}  // namespace uvtk::io
