// Bytes carried inside a web page: base64 text (RFC 4648) and zlib streams (RFC 1950), which a
// browser's DecompressionStream("deflate") reads back.
#pragma once

#include <string>
#include <string_view>

namespace uvtk::io {

// `bytes` as base64, with '=' padding.
std::string base64(std::string_view bytes);

// `bytes` compressed as one zlib stream (level 6).
std::string zlibCompressed(std::string_view bytes);

}  // namespace uvtk::io
