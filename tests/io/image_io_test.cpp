#include "io/image_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <set>
#include <string>

#include "core/error.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

class ImageIoTest : public ScratchDirTest {
 protected:
  std::set<std::string> listing() const {
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir_)) names.insert(entry.path().filename());
    return names;
  }
};

// Distinct multiples of 1/255 in every channel of every pixel.
Image gradient(int width, int height, int channels) {
  Image image(width, height, channels);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float((i * 7) % 256) / 255.0f;
  return image;
}

template <typename Error, typename F>
std::string messageOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no exception of the expected type";
  return {};
}

void expectOneLineError(const std::string& message, const std::string& path) {
  EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
  EXPECT_NE(message.find("error:"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST_F(ImageIoTest, PngRoundTripKeepsValuesAndRowOrder) {
  const Image image = gradient(7, 5, 3);
  ASSERT_NE(image.at(2, 0, 1), image.at(2, 4, 1));  // the top and bottom rows differ
  writeImage(path("a.png"), image, PixelType::UInt8);

  const ImageFile file = readImage(path("a.png"));
  EXPECT_TRUE(file.eightBit);
  ASSERT_EQ(file.image.width, 7);
  ASSERT_EQ(file.image.height, 5);
  ASSERT_EQ(file.image.channels, 3);
  EXPECT_EQ(file.image.pixels, image.pixels);
  EXPECT_EQ(file.image.at(2, 0, 1), image.at(2, 0, 1));
  EXPECT_EQ(listing(), std::set<std::string>{"a.png"});  // no temporary left

  // Like AtomicFile: the mode of a newly created file, not mkstemp's 0600.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  struct stat info {};
  ASSERT_EQ(::stat(path("a.png").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0666 & ~mask);
}

TEST_F(ImageIoTest, UInt8RoundsAndClamps) {
  Image image(6, 1, 1);
  image.pixels = {0.5f / 255.0f + 1e-5f,
                  -0.25f,
                  1.5f,
                  std::numeric_limits<float>::quiet_NaN(),
                  -std::numeric_limits<float>::infinity(),
                  0.4f / 255.0f};
  writeImage(path("r.png"), image, PixelType::UInt8);
  const Image back = readImage(path("r.png")).image;
  const std::vector<float> expected = {1 / 255.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f};
  EXPECT_EQ(back.pixels, expected);
}

TEST_F(ImageIoTest, ExrRoundTripIsBitExactWithNames) {
  Image image(3, 2, 5);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(i) * 0.1f - 1.0f;
  image.at(0, 0, 2) = 1e20f;
  image.at(1, 0, 2) = std::numeric_limits<float>::infinity();
  image.at(2, 1, 0) = -3.25e-7f;
  image.channelNames = {"u", "v", "depth", "face", "lod"};
  writeImage(path("a.exr"), image, PixelType::Float);

  // EXR lists channels alphabetically.
  const ImageFile file = readImage(path("a.exr"));
  EXPECT_FALSE(file.eightBit);
  ASSERT_EQ(file.image.channels, 5);
  ASSERT_EQ(file.image.channelNames, (std::vector<std::string>{"depth", "face", "lod", "u", "v"}));
  for (int c = 0; c < 5; ++c) {
    const auto written = std::find(image.channelNames.begin(), image.channelNames.end(), file.image.channelNames[c]);
    const int source = int(written - image.channelNames.begin());
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 3; ++x) {
        const float expected = image.at(x, y, source), actual = file.image.at(x, y, c);
        EXPECT_EQ(std::memcmp(&expected, &actual, sizeof(float)), 0)
            << x << "," << y << " " << image.channelNames[source];
      }
  }
}

// A texture is grey, grey + alpha, RGB or RGBA: a fifth channel is refused from the header, as an
// input error naming the file and its channels (it was a usage error without the file's name).
TEST_F(ImageIoTest, ATextureOfMoreThanFourChannelsIsAnInputError) {
  Image image(2, 1, 5);
  image.channelNames = {"R", "G", "B", "A", "Z"};
  writeImage(path("five.exr"), image, PixelType::Float);
  EXPECT_EQ(readImage(path("five.exr")).image.channels, 5);
  try {
    readTexture(path("five.exr"));
    FAIL() << "a five-channel texture was read";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), path("five.exr") +
                                             ": error: image has 5 channels (R, G, B, A, Z); a texture takes 1 to 4 "
                                             "(grey, grey and alpha, RGB, RGBA)");
  }
  image = Image(2, 1, 4);
  image.channelNames = {"R", "G", "B", "A"};
  writeImage(path("four.exr"), image, PixelType::Float);
  EXPECT_EQ(readTexture(path("four.exr")).image.channels, 4);
}

TEST_F(ImageIoTest, TiffHoldsFloats) {
  Image image(2, 2, 2);
  image.pixels = {-1.0f, 0.5f, 1e20f, 2.0f, 3.0f, -4.0f, 0.125f, std::numeric_limits<float>::infinity()};
  writeImage(path("a.tif"), image, PixelType::Float);
  const ImageFile file = readImage(path("a.tif"));
  EXPECT_FALSE(file.eightBit);
  EXPECT_EQ(file.image.pixels, image.pixels);
}

TEST_F(ImageIoTest, OneAndFourChannelPngRoundTrip) {
  for (int channels : {1, 4}) {
    const Image image = gradient(4, 3, channels);  // alpha below 1 must not touch the colour
    const std::string file = path("c" + std::to_string(channels) + ".png");
    writeImage(file, image, PixelType::UInt8);
    const ImageFile back = readImage(file);
    EXPECT_TRUE(back.eightBit);
    ASSERT_EQ(back.image.channels, channels);
    EXPECT_EQ(back.image.pixels, image.pixels) << channels << " channels";
  }
}

TEST_F(ImageIoTest, UnreadableInputsAreInputErrors) {
  const std::string missing = path("missing.png");
  const std::string text = writeText("text.png", "this is not a PNG\nat all\n");
  for (const std::string& file : {missing, dir_.string(), text}) {
    const std::string message = messageOf<InputError>([&] { readImage(file); });
    expectOneLineError(message, file);
  }
  EXPECT_NE(messageOf<InputError>([&] { readImage(missing); }).find("No such file or directory"), std::string::npos);
}

TEST_F(ImageIoTest, RefusesImagesOverTheSizeLimit) {
  writeImage(path("wide.png"), Image(16385, 1, 1), PixelType::UInt8);
  EXPECT_NE(messageOf<InputError>([&] {
              readImage(path("wide.png"));
            }).find("image is 16385 x 1, larger than the 16384 x 16384 limit"),
            std::string::npos);
}

// The CRC that PNG chunks end with (ISO 3309), over the chunk type and data.
std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (unsigned char b : bytes) {
    crc ^= b;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::string bigEndian(std::uint32_t v) { return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; }

TEST_F(ImageIoTest, RefusesAHugeHeaderWithoutReadingPixels) {
  // A valid 1x1 PNG whose header then claims 20000 x 20000: refused before any allocation.
  writeImage(path("small.png"), Image(1, 1, 3), PixelType::UInt8);
  std::string png = readText(path("small.png"));
  const std::size_t ihdr = png.find("IHDR");
  ASSERT_EQ(ihdr, 12u);
  png.replace(ihdr + 4, 8, bigEndian(20000) + bigEndian(20000));
  png.replace(ihdr + 17, 4, bigEndian(crc32(png.substr(ihdr, 17))));
  const std::string file = writeText("huge.png", png);
  const std::string message = messageOf<InputError>([&] { readImage(file); });
  expectOneLineError(message, file);
  EXPECT_NE(message.find("20000 x 20000, larger than the 16384 x 16384 limit"), std::string::npos) << message;
}

TEST_F(ImageIoTest, RefusesMoreValuesThanTheLimitFromTheHeader) {
  // A 16384 x 16384 RGB header without pixels: 3 GiB as float, refused before anything is read.
  const std::string file = writeText("big.ppm", "P6\n16384 16384\n255\n");
  const std::string message = messageOf<InputError>([&] { readImage(file); });
  expectOneLineError(message, file);
  EXPECT_NE(message.find("image is 16384 x 16384 x 3 channels, 3 GiB as float, more than the 2 GiB limit"),
            std::string::npos)
      << message;

  writeImage(path("small.png"), gradient(4, 4, 3), PixelType::UInt8);
  EXPECT_EQ(readImage(path("small.png"), 48).image.pixels.size(), 48u);
  EXPECT_NE(messageOf<InputError>([&] { readImage(path("small.png"), 47); }).find("image is 4 x 4 x 3 channels"),
            std::string::npos);
}

TEST_F(ImageIoTest, ChecksAPngsChunksBeforeLibpngReadsIt) {
  writeImage(path("good.png"), gradient(8, 8, 3), PixelType::UInt8);
  const std::string png = readText(path("good.png"));
  const std::size_t idat = png.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  const auto messageFor = [&](const std::string& name, const std::string& bytes) {
    const std::string file = writeText(name, bytes);
    const std::string message = messageOf<InputError>([&] { readImage(file); });
    expectOneLineError(message, file);
    return message;
  };
  // The writer may put other chunks between IHDR and IDAT: the chunk's number is not asserted.
  const auto expectMessage = [](const std::string& message, const std::string& begin, const std::string& end) {
    EXPECT_EQ(message.rfind(begin, 0), 0u) << message;
    EXPECT_EQ(message.substr(message.size() - std::min(message.size(), end.size())), end) << message;
  };
  expectMessage(messageFor("cut.png", png.substr(0, idat + 10)),
                path("cut.png") + ": error: cannot read: truncated PNG (chunk ", ", IDAT, is cut off)");
  std::string flipped = png;
  flipped[idat + 6] = char(flipped[idat + 6] ^ 0x55);
  expectMessage(messageFor("crc.png", flipped), path("crc.png") + ": error: cannot read: corrupted PNG (chunk ",
                ", IDAT, fails its CRC)");
  // The check goes by the signature, not the extension.
  EXPECT_EQ(messageFor("cut.tif", png.substr(0, 30)),
            path("cut.tif") + ": error: cannot read: truncated PNG (chunk 0, IHDR, is cut off)");
  // The signature's CR LF turned into LF, as a text-mode transfer does: libpng would print a line of its own.
  std::string ascii = png;
  ascii.erase(4, 1);
  EXPECT_EQ(messageFor("ascii.png", ascii),
            path("ascii.png") +
                ": error: cannot read: corrupted PNG (its signature's line ends were changed, as by a text-mode transfer)");
  std::string noHeader = png;
  noHeader.replace(12, 4, "IHDX");
  EXPECT_EQ(messageFor("first.png", noHeader),
            path("first.png") + ": error: cannot read: corrupted PNG (the first chunk is not IHDR)");
}

TEST_F(ImageIoTest, WalksAnOpenExrsHeadersBeforeOpenExrReadsThem) {
  writeImage(path("good.exr"), gradient(4, 4, 3), PixelType::Float);
  const std::string exr = readText(path("good.exr"));
  const std::string attribute = std::string("compression\0compression\0", 24);
  const std::size_t at = exr.find(attribute);
  ASSERT_NE(at, std::string::npos);
  ASSERT_EQ(exr.substr(at + 24, 4), std::string("\1\0\0\0", 4));
  EXPECT_EQ(readImage(path("good.exr")).image.channels, 3);
  // A 1.7 GB value declared in a small file: OpenEXR would allocate it before finding the file short.
  std::string huge = exr;
  huge.replace(at + 24, 4, std::string("\x13\x00\x6e\x64", 4));
  const std::string hugeFile = writeText("huge.exr", huge);
  const std::string left = std::to_string(exr.size() - (at + 28));
  EXPECT_EQ(messageOf<InputError>([&] { readImage(hugeFile); }),
            hugeFile + ": error: cannot read: corrupted OpenEXR (header 0's attribute compression declares "
                       "1684930579 bytes, " + left + " are left in the file)");
  // The check goes by the magic number, not the extension.
  const std::string cut = writeText("cut.png", exr.substr(0, at + 20));
  EXPECT_EQ(messageOf<InputError>([&] { readImage(cut); }),
            cut + ": error: cannot read: truncated OpenEXR (header 0 is cut off)");
  // A data window beyond the limits, and tiles larger than an image may be: refused from the header,
  // before OpenEXR allocates a line or a tile by them (a 486-byte file's 196,609-pixel-wide line
  // timed the fuzzer out).
  const std::size_t window = exr.find(std::string("dataWindow\0box2i\0\x10\0\0\0", 21));
  ASSERT_NE(window, std::string::npos);
  std::string wide = exr;
  wide.replace(window + 21 + 8, 4, std::string("\x00\x00\x03\x00", 4));  // xMax 196608
  const std::string wideFile = writeText("wide.exr", wide);
  EXPECT_EQ(messageOf<InputError>([&] { readImage(wideFile); }),
            wideFile + ": error: image is 196609 x 4, larger than the 16384 x 16384 limit");
  std::string tiled = exr;
  tiled.insert(at, std::string("tiles\0tiledesc\0\x09\0\0\0\0\0\x01\0\0\0\x01\0\0", 28));  // 65536 x 65536
  const std::string tiledFile = writeText("tiles.exr", tiled);
  EXPECT_EQ(messageOf<InputError>([&] { readTexture(tiledFile, 1 << 18); }),
            tiledFile + ": error: tiles are 65536 x 65536, 4294967296 pixels, more than the limit of 262144");
  // A channel list declared shorter than it is: OpenEXR reads it to its end whatever the size, so a
  // walk by the declared sizes would lose step with OpenEXR's reading.
  const std::size_t list = exr.find(std::string("channels\0chlist\0", 16));
  ASSERT_NE(list, std::string::npos);
  const std::uint8_t listBytes = std::uint8_t(exr[list + 16]);
  std::string shortList = exr;
  shortList[list + 16] = char(listBytes - 4);
  const std::string shortFile = writeText("short.exr", shortList);
  EXPECT_EQ(messageOf<InputError>([&] { readImage(shortFile); }),
            shortFile + ": error: cannot read: corrupted OpenEXR (header 0's attribute channels is not a valid chlist of " +
                std::to_string(listBytes - 4) + " bytes)");
  // A preview whose pixels are the bytes declared reads (in the place of screenWindowWidth, which
  // is as long, so that the pixels' offsets stay); one claiming more pixels than it holds would
  // have OpenEXR allocate and read them past the attribute.
  const std::string width = std::string("screenWindowWidth\0float\0\x04\0\0\0\0\0\x80\x3f", 32);
  const std::size_t widthAt = exr.find(width);
  ASSERT_NE(widthAt, std::string::npos);
  const std::string preview = std::string("preview\0preview\0\x0c\0\0\0", 20);
  std::string withPreview = exr;
  withPreview.replace(widthAt, 32, preview + std::string("\x01\0\0\0\x01\0\0\0\x10\x20\x30\xff", 12));
  EXPECT_EQ(readImage(writeText("preview.exr", withPreview)).image.channels, 3);
  std::string badPreview = exr;
  badPreview.replace(widthAt, 32, preview + std::string("\x02\0\0\0\x02\0\0\0\x10\x20\x30\xff", 12));
  const std::string badPreviewFile = writeText("bad-preview.exr", badPreview);
  EXPECT_EQ(messageOf<InputError>([&] { readImage(badPreviewFile); }),
            badPreviewFile +
                ": error: cannot read: corrupted OpenEXR (header 0's attribute preview is not a valid preview of 12 bytes)");
  std::string longName = exr;
  longName.replace(at, 11, std::string(40, 'c'));
  const std::string longFile = writeText("long.exr", longName);
  EXPECT_EQ(messageOf<InputError>([&] { readImage(longFile); }),
            longFile + ": error: cannot read: corrupted OpenEXR (header 0 has a name longer than 31 characters)");
}

TEST_F(ImageIoTest, WriteErrors) {
  const Image image = gradient(2, 2, 3);
  const std::string nowhere = path("no/such/folder/a.png");
  expectOneLineError(messageOf<OutputError>([&] { writeImage(nowhere, image, PixelType::UInt8); }), nowhere);
  EXPECT_TRUE(listing().empty());

  EXPECT_THROW(writeImage(path("a.xyz"), image, PixelType::UInt8), UsageError);
  EXPECT_THROW(writeImage(path("a.png"), image, PixelType::Float), UsageError);
  EXPECT_THROW(writeImage(path("a.jpg"), image, PixelType::Float), UsageError);
  EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIoTest, FailedWriteLeavesTheTargetAlone) {
  const std::string target = writeText("keep.png", "old contents");
  // PNG holds at most four channels, so the writer fails after the temporary exists.
  const std::string message = messageOf<OutputError>([&] { writeImage(target, gradient(2, 2, 5), PixelType::UInt8); });
  expectOneLineError(message, target);
  EXPECT_NE(message.find("cannot write:"), std::string::npos) << message;
  EXPECT_EQ(readText(target), "old contents");
  EXPECT_EQ(listing(), std::set<std::string>{"keep.png"});

  writeImage(target, gradient(2, 2, 3), PixelType::UInt8);  // success replaces it
  EXPECT_EQ(readImage(target).image.pixels, gradient(2, 2, 3).pixels);
  EXPECT_EQ(listing(), std::set<std::string>{"keep.png"});
}

// The data URI is "data:image/png;base64," and encodePng's bytes in base64 (RFC 4648, padded),
// whose PNG reads back as the image. Sizes 1, 2 and 3 mod 3 of the last group all occur.
TEST_F(ImageIoTest, PngDataUriIsTheEncodedPngInBase64) {
  const std::string kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const std::string prefix = "data:image/png;base64,";
  std::set<std::size_t> tails;
  for (int width = 1; width <= 9 && tails.size() < 3; ++width) {
    const Image image = gradient(width, 2, 3);
    const std::string uri = pngDataUri(image), png = encodePng(image);
    ASSERT_EQ(uri.rfind(prefix, 0), 0u);
    const std::string digits = uri.substr(prefix.size());
    ASSERT_EQ(digits.size(), (png.size() + 2) / 3 * 4);
    std::string decoded;
    std::uint32_t bits = 0;
    int count = 0;
    for (char c : digits) {
      if (c == '=') break;
      const std::size_t value = kDigits.find(c);
      ASSERT_NE(value, std::string::npos) << c;
      bits = bits << 6 | std::uint32_t(value);
      if ((count += 6) >= 8) decoded += char(bits >> (count -= 8) & 255);
    }
    EXPECT_EQ(decoded, png);
    tails.insert(png.size() % 3);
    writeText("uri.png", decoded);
    EXPECT_EQ(readImage(path("uri.png")).image.pixels, image.pixels);
  }
  EXPECT_EQ(tails.size(), 3u);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
