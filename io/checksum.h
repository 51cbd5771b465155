// A file's checksum, so that a report names exactly the input it measured.
#pragma once

#include <string>

namespace uvtk::io {

// The SHA-256 of the file's bytes as 64 lowercase hex digits. Throws InputError if it cannot be read.
std::string sha256File(const std::string& path);

}  // namespace uvtk::io
