// What io asks of the image plugin (io/image_backend_oiio.cpp): OpenImageIO and the ~250 libraries
// it pulls in cost every process 0.3 s and 120 MB at start, so they live in a module that io opens
// on the first image read or write (io/image_plugin.h). Both sides are built together, so C++
// types cross the interface; our error classes do not: the plugin reports failures as false or
// null with OpenImageIO's message, io turns them into its errors.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace uvtk::io::backend {

// Checked against the plugin's, so that a stale plugin is refused rather than called.
constexpr int kVersion = 1;

enum class Stored { UInt8, UInt16, Other };  // every channel 8-bit, every channel 16-bit, else

struct Header {  // the first subimage, level 0
  int width = 0, height = 0, depth = 0, channels = 0;
  std::vector<std::string> channelNames;  // all of them, in OpenImageIO's order
  Stored stored = Stored::Other;
};

struct Reader;  // an open image file

struct Pixels {  // what a writer takes: interleaved, 8-bit or float
  int width = 0, height = 0, channels = 0;
  const std::vector<std::string>* channelNames = nullptr;  // may be empty
  bool isFloat = false;
  const void* data = nullptr;
};

struct Functions {
  int version;
  // Opens `path` (alpha unassociated) and reads its header; null with `error` on failure.
  Reader* (*open)(const std::string& path, Header& header, std::string& error);
  // The first `channels` channels of every pixel into `pixels`, 8- and 16-bit integers divided
  // by their maximum; false with `error` (maybe empty) on failure.
  bool (*read)(Reader* reader, int channels, float* pixels, std::string& error);
  void (*close)(Reader* reader);
  // The name of the format a file named `path` is written in ("png", "openexr", "tiff", ...);
  // empty when no writer takes its extension.
  std::string (*writerFormat)(const std::string& path);
  // Writes `pixels` into the file at `file` in the format `path`'s extension names (the file may
  // be a temporary without one); false with `error` on failure.
  bool (*write)(const std::string& path, const std::string& file, const Pixels& pixels, std::string& error);
  // `pixels` (8-bit) as a PNG file in memory; false with `error` on failure.
  bool (*encodePng)(const Pixels& pixels, std::string& bytes, std::string& error);
};

}  // namespace uvtk::io::backend

// The plugin's one exported symbol.
#define UVTK_IMAGE_BACKEND_ENTRY "uvtk_image_backend"
extern "C" const uvtk::io::backend::Functions* uvtk_image_backend();
