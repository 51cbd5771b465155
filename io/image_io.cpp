#include "io/image_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/memory.h"
#include "io/page_bytes.h"
#include "io/atomic_file.h"
#include "io/image_backend.h"
#include "io/image_plugin.h"

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

constexpr char kPngSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1A', '\n'};
constexpr char kExrMagic[4] = {'\x76', '\x2f', '\x31', '\x01'};

// A PNG (by its signature, whatever the extension) is checked chunk by chunk before OpenImageIO
// reads it: on a truncated or corrupted PNG, OpenImageIO 2.4's error handler returns to libpng,
// which then prints "libpng error: ..." on stderr beside our message, and the read leaks. Checked:
// each chunk's length fits the file, its CRC, IHDR first and IEND last. A deflate stream broken
// under valid CRCs still reaches libpng.
// `in` after the file's first 8 bytes, `head` (also the chunks' buffer), which begin as a PNG
// signature does.
void checkPngChunks(const std::string& path, std::istream& in, char* head) {
  // The signature's line ends changed (a text-mode transfer): libpng would print its own line.
  if (!std::equal(head + 4, head + 8, kPngSignature + 4))
    throw readFailure(path, "cannot read: corrupted PNG (its signature's line ends were changed, as by a text-mode transfer)");
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

// What a read may take: the caller's limits on values and pixels, and on channels (a texture's 4).
struct ReadLimits {
  std::int64_t maxValues, maxPixels;
  int maxChannels;
};

// The limits checked on a header's numbers: OpenImageIO's, or an OpenEXR header's before OpenEXR
// allocates by them. `channelNames` in the order the reader gives them.
void checkDimensions(const std::string& path, std::int64_t width, std::int64_t height,
                     const std::vector<std::string>& channelNames, const ReadLimits& limits) {
  if (width > kMaxSide || height > kMaxSide)
    throw readFailure(path, "image is " + std::to_string(width) + " x " + std::to_string(height) + ", larger than the " +
                                std::to_string(kMaxSide) + " x " + std::to_string(kMaxSide) + " limit");
  const std::int64_t channelCount = std::int64_t(channelNames.size());
  if (channelCount > limits.maxChannels) {
    std::string names;
    for (std::size_t c = 0; c < channelNames.size(); ++c) names += (c ? ", " : "") + channelNames[c];
    throw readFailure(path, "image has " + std::to_string(channelCount) + " channels (" + printable(names) +
                                "); a texture takes 1 to 4 (grey, grey and alpha, RGB, RGBA)");
  }
  const std::int64_t channels = std::min<std::int64_t>(channelCount, kMaxChannels);
  const std::int64_t pixelCount = width * height, values = pixelCount * channels;
  if (pixelCount > limits.maxPixels)
    throw readFailure(path, "image is " + std::to_string(width) + " x " + std::to_string(height) + ", " +
                                std::to_string(pixelCount) + " pixels, more than the limit of " +
                                std::to_string(limits.maxPixels));
  if (values > limits.maxValues) {
    std::ostringstream message;
    message << "image is " << width << " x " << height << " x " << channels << " channels, "
            << double(values) * sizeof(float) / double(1 << 30) << " GiB as float, more than the "
            << double(limits.maxValues) * sizeof(float) / double(1 << 30) << " GiB limit";
    throw readFailure(path, message.str());
  }
}

std::int32_t littleInt32(const std::string& bytes, std::size_t at) {
  return std::int32_t(std::uint32_t(std::uint8_t(bytes[at])) | std::uint32_t(std::uint8_t(bytes[at + 1])) << 8 |
                      std::uint32_t(std::uint8_t(bytes[at + 2])) << 16 | std::uint32_t(std::uint8_t(bytes[at + 3])) << 24);
}

// Whether `value` is exactly one value of the OpenEXR attribute type `type`, as OpenEXR 3.1 reads
// it: a type of fixed size is read whole and a channel list up to its end whatever size the file
// declares, and a preview's or a string vector's own sizes are allocated, so each must agree with
// the declared one. Types it does not know (and strings) are read as their declared bytes.
bool holdsExrValue(const std::string& type, const std::string& value) {
  static const std::pair<const char*, std::size_t> kFixedSizes[] = {
      {"box2i", 16},    {"box2f", 16},    {"chromaticities", 32}, {"compression", 1}, {"double", 8}, {"envmap", 1},
      {"float", 4},     {"int", 4},       {"keycode", 28},        {"lineOrder", 1},   {"m33f", 36},  {"m33d", 72},
      {"m44f", 64},     {"m44d", 128},    {"rational", 8},        {"tiledesc", 9},    {"timecode", 8}, {"v2i", 8},
      {"v2f", 8},       {"v2d", 16},      {"v3i", 12},            {"v3f", 12},        {"v3d", 24},   {"deepImageState", 1}};
  for (const auto& [name, size] : kFixedSizes)
    if (type == name) return value.size() == size;
  const std::size_t size = value.size();
  if (type == "chlist") {  // (name, 0, 16 bytes)*, 0
    std::size_t at = 0;
    while (at < size && value[at] != '\0') {
      const std::size_t end = value.find('\0', at);
      if (end == std::string::npos || end - at > 255) return false;
      at = end + 17;
    }
    return at + 1 == size;
  }
  if (type == "preview") {  // width, height, then 4 bytes a pixel (counted without overflow)
    if (size < 8 || (size - 8) % 4 != 0) return false;
    const std::uint64_t width = std::uint32_t(littleInt32(value, 0)), height = std::uint32_t(littleInt32(value, 4));
    const std::uint64_t pixels = (size - 8) / 4;
    return width == 0 || height == 0 ? pixels == 0 : pixels % width == 0 && pixels / width == height;
  }
  if (type == "stringvector") {  // (length, characters)*
    for (std::size_t at = 0; at < size;) {
      if (size - at < 4 || littleInt32(value, at) < 0 || std::size_t(littleInt32(value, at)) > size - at - 4) return false;
      at += 4 + std::size_t(littleInt32(value, at));
    }
    return true;
  }
  if (type == "floatvector") return size % 4 == 0;
  return true;
}

// An OpenEXR file (by its magic number) has its headers walked before OpenImageIO reads it:
// OpenEXR 3.1 allocates by the numbers it finds before it checks them, so a 1 KB file declaring a
// 1.7 GB string took 2.5 s and 1.8 GB, and a 486-byte one a data window 196,609 pixels wide a
// line buffer that timed the fuzzer out (CI, 2026-12-07). Checked in every part's header: each
// attribute's name and type end and its value fits in the file; the data window and channels keep
// the read's limits (checkDimensions; the channels named R, G, B, A first, as OpenImageIO orders
// them); and a tile holds no more pixels than an image may.
// `in` after the file's first 8 bytes, `head`: OpenEXR's magic number and version field.
void checkExrHeaders(const std::string& path, std::istream& in, const char* head, const ReadLimits& limits) {
  const std::uint32_t flags = std::uint32_t(std::uint8_t(head[5])) << 8 | std::uint32_t(std::uint8_t(head[6])) << 16;
  const bool multipart = (flags & 0x1000) != 0;
  const std::size_t maxName = (flags & 0x400) != 0 ? 255 : 31;
  in.seekg(0, std::ios::end);
  const std::int64_t fileSize = std::int64_t(in.tellg());
  in.seekg(8);
  const auto cutOff = [&](int part) {
    return readFailure(path, "cannot read: truncated OpenEXR (header " + std::to_string(part) + " is cut off)");
  };
  const auto corrupted = [&](int part, const std::string& what) {
    return readFailure(path, "cannot read: corrupted OpenEXR (header " + std::to_string(part) + what + ")");
  };
  // A name or type: up to maxName characters and a zero; empty at the end of a header.
  const auto readName = [&](int part) {
    std::string name;
    for (char c; in.get(c);) {
      if (c == '\0') return name;
      if (name.size() == maxName)
        throw corrupted(part, " has a name longer than " + std::to_string(maxName) + " characters");
      name += c;
    }
    throw cutOff(part);
  };
  for (int part = 0;; ++part) {
    std::optional<std::array<std::int64_t, 2>> window, tile;  // width and height
    std::vector<std::string> channels;
    for (std::string name = readName(part); !name.empty(); name = readName(part)) {
      const std::string type = readName(part);
      char size[4];
      if (!in.read(size, 4)) throw cutOff(part);
      const std::int64_t bytes = littleInt32(std::string(size, 4), 0);
      const std::int64_t left = fileSize - std::int64_t(in.tellg());
      if (bytes < 0 || bytes > left)
        throw corrupted(part, "'s attribute " + printable(name) + " declares " + std::to_string(bytes) + " bytes, " +
                                  std::to_string(left) + " are left in the file");
      std::string value(std::size_t(bytes), '\0');
      if (!in.read(value.data(), bytes)) throw cutOff(part);
      if (!holdsExrValue(type, value))
        throw corrupted(part, "'s attribute " + printable(name) + " is not a valid " + printable(type) + " of " +
                                  std::to_string(bytes) + " bytes");
      if (name == "dataWindow" && type == "box2i") {  // xMin, yMin, xMax, yMax
        window = {{std::int64_t(littleInt32(value, 8)) - littleInt32(value, 0) + 1,
                   std::int64_t(littleInt32(value, 12)) - littleInt32(value, 4) + 1}};
      } else if (name == "tiles" && type == "tiledesc") {  // xSize, ySize (unsigned), mode
        tile = {{std::int64_t(std::uint32_t(littleInt32(value, 0))), std::int64_t(std::uint32_t(littleInt32(value, 4)))}};
      } else if (name == "channels" && type == "chlist") {  // each channel: its name, a zero and 16 bytes
        for (std::size_t at = 0; value[at] != '\0'; at = value.find('\0', at) + 17)
          channels.push_back(value.substr(at, value.find('\0', at) - at));
      }
    }
    // A window that is empty or inverted OpenEXR refuses itself.
    if (window && (*window)[0] > 0 && (*window)[1] > 0) {
      const auto rank = [](const std::string& c) {
        return c.size() == 1 ? std::string("RGBA").find(c[0]) : std::string::npos;
      };
      std::stable_sort(channels.begin(), channels.end(),
                       [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
      checkDimensions(path, (*window)[0], (*window)[1], channels, limits);
    }
    if (tile && (*tile)[0] * (*tile)[1] > limits.maxPixels)
      throw readFailure(path, "tiles are " + std::to_string((*tile)[0]) + " x " + std::to_string((*tile)[1]) + ", " +
                                  std::to_string((*tile)[0] * (*tile)[1]) + " pixels, more than the limit of " +
                                  std::to_string(limits.maxPixels));
    // A multi-part file's headers end with an empty one.
    if (!multipart || in.peek() == 0) return;
    if (in.peek() == std::char_traits<char>::eof()) throw cutOff(part + 1);
  }
}

// The checks of a PNG's or an OpenEXR's own header, by the file's first bytes whatever its
// extension, from one opening of the file.
void checkFormatHeaders(const std::string& path, const ReadLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  char head[8];
  if (!in.read(head, 8)) return;  // shorter than either signature: OpenImageIO says what it is
  if (std::equal(head, head + 4, kPngSignature)) checkPngChunks(path, in, head);
  if (std::equal(head, head + 4, kExrMagic)) checkExrHeaders(path, in, head, limits);
}

std::uint8_t toUInt8(float c) {
  if (!(c > 0.0f)) return 0;  // also NaN
  if (c >= 1.0f) return 255;
  return static_cast<std::uint8_t>(std::lround(static_cast<double>(c) * 255.0));
}

// The image plugin, or `fail(reason)` thrown: the error class of the caller's operation.
template <typename Fail>
const backend::Functions& plugin(Fail fail) {
  std::string error;
  const backend::Functions* functions = imagePlugin(error);
  if (!functions) throw fail(error);
  return *functions;
}

// The plugin and the format of `path`'s writer; throws UsageError when there is none or it cannot
// hold `type`.
const backend::Functions& writerFor(const std::string& path, PixelType type) {
  const backend::Functions& functions = plugin([&](const std::string& why) { return writeError(path, why); });
  const std::string format = functions.writerFormat(path);
  if (format.empty()) throw UsageError(path + ": error: cannot write images of this type");
  // OpenImageIO has no query for float support; writers of other formats silently convert.
  if (type == PixelType::Float && format != "openexr" && format != "tiff")
    throw UsageError(path + ": error: cannot write float pixels to a " + format + " file (use .exr, .tif or .tiff)");
  return functions;
}

}  // namespace

namespace {

ImageFile readLimited(const std::string& path, const ReadLimits& limits) {
  checkReadable(path);
  checkFormatHeaders(path, limits);
  const backend::Functions& functions =
      plugin([&](const std::string& why) { return readFailure(path, "cannot read: " + why); });
  backend::Header spec;  // the first subimage, level 0
  std::string error;
  const std::unique_ptr<backend::Reader, void (*)(backend::Reader*)> in(functions.open(path, spec, error),
                                                                        functions.close);
  if (!in) throw readFailure(path, "cannot read: " + oneLine(error));

  if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1 || spec.channels <= 0)
    throw readFailure(path, "image is empty or not two-dimensional (" + std::to_string(spec.width) + " x " +
                                std::to_string(spec.height) + " x " + std::to_string(spec.depth) + ", " +
                                std::to_string(spec.channels) + " channels)");
  checkDimensions(path, spec.width, spec.height, spec.channelNames, limits);
  const int channels = std::min(spec.channels, kMaxChannels);
  const std::int64_t values = std::int64_t(spec.width) * spec.height * channels;
  // Within the limit, a small compressed file may still decode to more than this process may take.
  const std::uint64_t bytes = std::uint64_t(values) * sizeof(float);
  const std::optional<std::uint64_t> available = availableMemory();
  if (available && bytes > *available)
    throw readFailure(path, "image is " + std::to_string(spec.width) + " x " + std::to_string(spec.height) + " x " +
                                std::to_string(channels) + " channels, " + formatBytes(bytes) +
                                " as float, more than the " + formatBytes(*available) + " of memory available");

  ImageFile file;
  file.image = Image(spec.width, spec.height, channels);
  file.image.channelNames.assign(spec.channelNames.begin(), spec.channelNames.begin() + channels);
  file.eightBit = spec.stored == backend::Stored::UInt8;
  if (!functions.read(in.get(), channels, file.image.pixels.data(), error))
    throw readFailure(path, "cannot read: " + oneLine(error, "the pixels are missing or corrupt"));
  return file;
}

}  // namespace

ImageFile readImage(const std::string& path, std::int64_t maxValues, std::int64_t maxPixels) {
  return readLimited(path, {maxValues, maxPixels, std::numeric_limits<int>::max()});
}

ImageFile readTexture(const std::string& path, std::int64_t maxPixels) {
  return readLimited(path, {kMaxImageValues, maxPixels, 4});
}

void checkImageType(const std::string& path, PixelType type) { writerFor(path, type); }

namespace {

// `image` as the plugin writes it; for UInt8 its pixels rounded into `rounded` by our own rounding
// rather than OpenImageIO's conversion, so that NaN and the halfway cases are defined.
backend::Pixels pixelsFor(const Image& image, PixelType type, std::vector<std::uint8_t>& rounded) {
  backend::Pixels pixels{image.width, image.height, image.channels, &image.channelNames, type == PixelType::Float,
                         image.pixels.data()};
  if (type == PixelType::UInt8) {
    rounded.resize(image.pixels.size());
    std::transform(image.pixels.begin(), image.pixels.end(), rounded.begin(), toUInt8);
    pixels.data = rounded.data();
  }
  return pixels;
}

}  // namespace

void writeImage(OutputSet& outputs, const std::string& path, const Image& image, PixelType type) {
  UVTK_CHECK(image.width > 0 && image.height > 0 && image.channels > 0);
  UVTK_CHECK(image.pixels.size() == image.index(0, image.height));
  UVTK_CHECK(image.channelNames.empty() || int(image.channelNames.size()) == image.channels);

  const backend::Functions& functions = writerFor(path, type);

  std::vector<std::uint8_t> rounded;
  const backend::Pixels pixels = pixelsFor(image, type, rounded);

  const TemporaryFile& staged = outputs.stage(path);
  std::string error;
  // The format by the target's extension: the temporary's path may have none.
  if (!functions.write(path, staged.path(), pixels, error)) throw writeError(staged.shownName(), oneLine(error));
}

void writeImage(const std::string& path, const Image& image, PixelType type) {
  OutputSet outputs;
  writeImage(outputs, path, image, type);
  outputs.publish();
}

std::string encodePng(const Image& image) {
  UVTK_CHECK(image.width > 0 && image.height > 0 && image.channels > 0);
  const backend::Functions& functions =
      plugin([](const std::string& why) { return OutputError("error: cannot encode a PNG: " + why); });
  std::vector<std::uint8_t> rounded;
  std::string bytes, error;
  if (!functions.encodePng(pixelsFor(image, PixelType::UInt8, rounded), bytes, error))
    throw std::runtime_error("OpenImageIO: cannot encode a PNG in memory: " + oneLine(error));
  return bytes;
}

std::string pngDataUri(const Image& image) { return "data:image/png;base64," + base64(encodePng(image)); }

}  // namespace uvtk::io
