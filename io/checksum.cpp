#include "io/checksum.h"

#include <openssl/evp.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/plugin.h"

namespace uvtk::io {

namespace {

// OpenSSL's digest functions, from libcrypto opened on the first checksum: linked, it costs every
// process 1.5 MB and 1.8 ms at start (docs/benchmarks.md, "Start-up"), and only reports use it.
struct Crypto {
  EVP_MD_CTX* (*newContext)();
  void (*freeContext)(EVP_MD_CTX*);
  const EVP_MD* (*sha256)();
  int (*init)(EVP_MD_CTX*, const EVP_MD*, ENGINE*);
  int (*update)(EVP_MD_CTX*, const void*, std::size_t);
  int (*final)(EVP_MD_CTX*, unsigned char*, unsigned int*);
  std::string error;  // why it could not be loaded; empty when it was
};

Crypto load() {
  Crypto crypto{};
  OpenedLibrary library(UVTK_LIBCRYPTO);
  library.bind(crypto.newContext, "EVP_MD_CTX_new");
  library.bind(crypto.freeContext, "EVP_MD_CTX_free");
  library.bind(crypto.sha256, "EVP_sha256");
  library.bind(crypto.init, "EVP_DigestInit_ex");
  library.bind(crypto.update, "EVP_DigestUpdate");
  library.bind(crypto.final, "EVP_DigestFinal_ex");
  crypto.error = library.error();
  return crypto;
}

}  // namespace

std::string sha256File(const std::string& path) {
  static const Crypto crypto = load();
  if (!crypto.error.empty()) throw std::runtime_error("cannot load OpenSSL for SHA-256: " + crypto.error);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw InputError(path + ": error: cannot open the file to checksum it");
  std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> context(crypto.newContext(), crypto.freeContext);
  if (!context || crypto.init(context.get(), crypto.sha256(), nullptr) != 1)
    throw std::runtime_error("OpenSSL: cannot start a SHA-256 digest");
  std::vector<unsigned char> buffer(1 << 16);
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), file.get())) > 0) crypto.update(context.get(), buffer.data(), n);
  if (std::ferror(file.get())) throw InputError(path + ": error: read failed while computing its checksum");
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  crypto.final(context.get(), digest, &length);
  static const char* kHex = "0123456789abcdef";
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) hex += {kHex[digest[i] >> 4], kHex[digest[i] & 15]};
  return hex;
}

}  // namespace uvtk::io
