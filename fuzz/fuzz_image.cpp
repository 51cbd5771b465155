// libFuzzer target: the image-texture path (OpenImageIO's readers, our checks, the texture and its
// mipmaps). The first byte chooses the file's extension, which picks OpenImageIO's reader first;
// the rest is the file, read as the CLI reads a texture (io::readTexture: 1 to 4 channels).
// Textures are limited to 2^18 pixels (2^20 values) here: the default 2^29 would let a 30-byte
// header allocate 2 GiB (the fuzzer's memory limit), and at 2^22 values a valid 195-byte image's
// mipmaps took longer than the fuzzer's 1 s under the sanitizers (CI, 2026-11-24). The limit
// itself is tested in tests/io.
#include "core/error.h"
#include "io/image_io.h"
#include "render/texture.h"
#include "scratch_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kExtensions[] = {"png", "jpg", "exr", "tif", "ppm", "bmp", "tga", "hdr"};
  const std::string path =
      uvtk::fuzz::writeInput(std::string("texture.") + kExtensions[data[0] % 8], data + 1, size - 1);
  try {
    const uvtk::io::ImageFile file = uvtk::io::readTexture(path, std::int64_t(1) << 18);
    uvtk::render::Texture texture = uvtk::render::Texture::fromImage(file.image, file.eightBit);
    texture.buildMipmaps();
  } catch (const uvtk::InputError&) {
    // the expected way to refuse an image
  }
  return 0;
}
