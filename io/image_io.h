// Images through OpenImageIO: any format it reads (PNG, JPEG, EXR, TIFF, ...), 8-bit PNG or
// float EXR/TIFF written atomically.
#pragma once

#include <cstdint>
#include <string>

#include "core/image.h"

namespace uvtk::io {

class OutputSet;

struct ImageFile {
  Image image;            // values as stored: 8-bit and 16-bit integers scaled to [0, 1]
  bool eightBit = false;  // every channel was stored as 8-bit unsigned integers
};

// The most values (pixels x channels) readImage allocates by default: 2^29, 2 GiB as float.
constexpr std::int64_t kMaxImageValues = std::int64_t(1) << 29;

// Reads the first subimage with all its channels (up to 64) in OpenImageIO's order, which for
// EXR is R, G, B, A, then the rest alphabetically: EXR files do not record the order channels
// were written in, so find channels by name. Throws InputError "PATH: error: ..." for a missing,
// unreadable or undecodable file, an empty image, and one wider or taller than 16384 pixels or of
// more than `maxValues` values or `maxPixels` pixels, or whose floats need more memory than is
// available (core/memory.h): each refused from its header, never allocated.
ImageFile readImage(const std::string& path, std::int64_t maxValues = kMaxImageValues,
                    std::int64_t maxPixels = kMaxImageValues);

// readImage for a texture: also refuses, from the header, an image of more than 4 channels (a
// texture is grey, grey + alpha, RGB or RGBA), naming its channels.
ImageFile readTexture(const std::string& path, std::int64_t maxPixels = kMaxImageValues);

enum class PixelType { UInt8, Float };

// Throws the UsageError writeImage would for `path` and `type`, before any work is done.
void checkImageType(const std::string& path, PixelType type);

// Writes `image` to `path` in the format its extension names: UInt8 stores round(clamp(c, 0, 1)
// * 255); Float needs a format that holds floats (.exr, .tif, .tiff) and keeps non-finite values
// as they are. Channel names come from image.channelNames when given. Written as an output
// (io/temporary_file.h: a temporary beside it, then renamed); throws OutputError (nothing left
// behind) on failure and UsageError for an extension OpenImageIO cannot write or Float to an
// 8-bit-only format.
void writeImage(const std::string& path, const Image& image, PixelType type);
// The same, staged in `outputs`, which publishes it with the command's other outputs.
void writeImage(OutputSet& outputs, const std::string& path, const Image& image, PixelType type);

// The 8-bit PNG file `image` would be written as, in memory.
std::string encodePng(const Image& image);

// The PNG as a data URI ("data:image/png;base64,..."), for pages that embed their pictures.
std::string pngDataUri(const Image& image);

}  // namespace uvtk::io
