// glTF 2.0 reading: tinygltf parses the JSON and loads the buffers (data: URIs, external files,
// the GLB's BIN chunk); everything it does not check is checked here, before any byte is read.
//
// Decisions where the format leaves room:
// - What is read: the default scene (`scene`, else scene 0), its nodes walked depth first from the
//   roots, each node's transform (matrix, or T * R * S) composed in double; with no scenes at all,
//   every mesh once, untransformed. A node reached twice (a cycle, or a child of two parents) is an
//   error: the node graph must be a forest. A mesh used by several nodes is read once per node.
// - Primitives of mode TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN become triangles (strips with
//   alternating winding, as the spec numbers them); points and lines are skipped and counted. Each
//   primitive instance brings its own vertices: nothing is welded across primitives.
// - A node whose world matrix has a negative determinant reverses the winding of its triangles
//   (glTF 2.0, 3.7.4): our triangles stay counter-clockwise seen from the front.
// - Attributes: POSITION (required), NORMAL (through the inverse transpose, renormalised) and
//   TEXCOORD_0 as (u, 1 - v): glTF's v runs down the image, ours up. Morph targets, skins,
//   materials, images and the other TEXCOORD_n are ignored.
// - KHR_mesh_quantization's component types are read when the file declares the extension; any
//   required extension but it and KHR_texture_transform (which moves no vertex) is an error.
// - Sparse accessors and accessors without a bufferView (all zeros) are refused.
// - External buffers are files relative to the glTF's folder; `..` may lead out of it (common in
//   asset folders), absolute paths and URIs with a scheme (http:, file:) are refused. Only base64
//   data: URIs are decoded.
// - The scene's mesh instances may hold at most 64 vertices and indices per input byte (at least
//   2^20): every instance gets its own vertices, so a small file of many nodes could otherwise ask
//   for any amount of memory; and that expanded count is checked against the memory available
//   (128 bytes each, what a map of it takes at its peak) before a vertex is read.
// - An external buffer file's size is compared with its byteLength before it is read.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS  // our file callbacks below are the only way to the file system
#include <fstream>      // which tinygltf's writer needs but, without its file system, does not include
#include <tiny_gltf.h>

#include "io/gltf_reader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "core/memory.h"
#include "io/face_lists.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "glTF buffers are little-endian; read with memcpy");

namespace uvtk::io {
namespace {

constexpr std::size_t kMaxQuoted = 40;
// tinygltf copies `extras` and `extensions` recursively: deeper JSON is refused before it parses.
constexpr int kMaxJsonDepth = 256;
// Scene graphs nest a few levels, skeletons a few hundred.
constexpr std::size_t kMaxNodeDepth = 1000;
constexpr std::uint64_t kMinInstancedElements = std::uint64_t{1} << 20;
constexpr std::uint64_t kInstancedElementsPerByte = 64;
// What a vertex or index of the expanded scene costs a map at its peak (mesh, corners, measures,
// output text): 108 bytes measured on a GLB of 3000 primitives sharing one accessor; rounded up.
constexpr std::uint64_t kMapBytesPerElement = 128;
// The quaternion's length may differ from 1 by the tolerance of the Khronos validator.
constexpr double kUnitTolerance = 0.00769;
constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;
constexpr std::uint32_t kChunkBin = 0x004E4942;
constexpr Triangle kNoCorners = {-1, -1, -1};

std::string quote(std::string_view token) {
  if (token.size() > kMaxQuoted) return "'" + std::string(token.substr(0, kMaxQuoted)) + "...'";
  return "'" + std::string(token) + "'";
}

InputError fileError(const std::string& name, const std::string& what) { return InputError(name + ": error: " + what); }
InputError pointerError(const std::string& name, const std::string& pointer, const std::string& what) {
  return InputError(name + ": " + pointer + ": error: " + what);
}
InputError byteError(const std::string& name, std::size_t byte, const std::string& what) {
  return InputError(name + ": byte " + std::to_string(byte) + ": error: " + what);
}

std::string hex32(std::uint32_t value) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string text = "0x";
  for (int shift = 28; shift >= 0; shift -= 4) text += kHex[(value >> shift) & 15];
  return text;
}

std::uint32_t u32At(std::string_view bytes, std::size_t at) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + at, 4);
  return value;
}

// ---- The GLB container, checked whole before tinygltf sees it ----

struct GlbJson {
  std::size_t offset = 0, length = 0;
};

GlbJson checkGlb(std::string_view bytes, const std::string& name) {
  const std::size_t size = bytes.size();
  if (size < 12) throw byteError(name, size, "expected a 12-byte GLB header, found end of file");
  if (u32At(bytes, 0) != kGlbMagic) throw byteError(name, 0, "expected the GLB magic 'glTF', found " + hex32(u32At(bytes, 0)));
  if (u32At(bytes, 4) != 2) throw byteError(name, 4, "expected GLB version 2, found " + std::to_string(u32At(bytes, 4)));
  const std::size_t length = u32At(bytes, 8);
  if (length > size)
    throw byteError(name, size, "expected " + std::to_string(length - size) + " more bytes (the GLB header's length is " +
                                    std::to_string(length) + "), found end of file");
  if (length < size)
    throw byteError(name, length, "expected end of file (the GLB header's length is " + std::to_string(length) +
                                      "), found " + std::to_string(size - length) + " more bytes");
  GlbJson json;
  for (std::size_t at = 12, chunk = 0; at < size; ++chunk) {
    if (size - at < 8) throw byteError(name, size, "expected an 8-byte chunk header, found end of file");
    const std::size_t chunkLength = u32At(bytes, at);
    const std::uint32_t type = u32At(bytes, at + 4);
    if (chunk == 0 && type != kChunkJson)
      throw byteError(name, at + 4, "expected the first chunk to be of type JSON (0x4E4F534A), found " + hex32(type));
    if (chunk == 1 && type != kChunkBin)
      throw byteError(name, at + 4, "expected the second chunk to be of type BIN (0x004E4942), found " + hex32(type));
    if (chunk > 1 && (type == kChunkBin || type == kChunkJson))
      throw byteError(name, at + 4, "expected at most one " + std::string(type == kChunkBin ? "BIN" : "JSON") + " chunk, found another");
    if (chunkLength == 0) throw byteError(name, at, "expected a chunk length above 0, found 0");
    if (chunkLength % 4 != 0) throw byteError(name, at, "expected a chunk length that is a multiple of 4, found " + std::to_string(chunkLength));
    if (chunkLength > size - at - 8)
      throw byteError(name, size, "expected the chunk's " + std::to_string(chunkLength) + " bytes, found end of file after " +
                                      std::to_string(size - at - 8));
    if (chunk == 0) json = {at + 8, chunkLength};
    at += 8 + chunkLength;
  }
  if (json.length == 0) throw byteError(name, 12, "expected a JSON chunk, found end of file");
  return json;
}

// tinygltf turns `extras` and `extensions` into its own values recursively; the text is scanned
// for its nesting first (brackets outside strings), so that no input can exhaust the stack.
void checkJsonDepth(std::string_view json, const std::string& name, bool binary, std::size_t offset) {
  int depth = 0;
  bool inString = false, escaped = false;
  std::size_t line = 1;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '\n') ++line;
    if (inString) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '{' || c == '[') {
      if (++depth > kMaxJsonDepth) {
        const std::string what = "expected JSON nested at most " + std::to_string(kMaxJsonDepth) + " levels deep, found deeper";
        if (binary) throw byteError(name, offset + i, what);
        throw InputError(name + ":" + std::to_string(line) + ": error: " + what);
      }
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
}

// ---- File access for tinygltf: external buffers, relative to the glTF's folder only ----

struct FileAccess {
  std::string folder;   // empty: no file may be read
  std::string uri;      // the decoded URI of the last buffer file asked for
  std::string refusal;  // why it was not read, when we refused it
  // What the buffer file's size is compared with before a byte of it is read: tinygltf compares
  // only after reading it whole, so a 72-byte glTF naming a 3 GiB file would cost 3 GB first.
  std::string_view json;                     // the document
  const tinygltf::Model* model = nullptr;    // buffers are parsed in order: the next is the one asked for
  std::optional<std::vector<std::uint64_t>> byteLengths;  // "buffers"/i/"byteLength", read on first need
};

// Each buffer's byteLength, by a parse that keeps only the "buffers" member (0 where absent or not a
// count: tinygltf refuses those itself).
std::vector<std::uint64_t> bufferByteLengths(std::string_view json) {
  using Json = nlohmann::json;
  const Json::parser_callback_t keepBuffers = [](int depth, Json::parse_event_t event, Json& parsed) {
    return !(event == Json::parse_event_t::key && depth == 1 && parsed != "buffers");
  };
  const Json document = Json::parse(json.begin(), json.end(), keepBuffers, false);
  std::vector<std::uint64_t> lengths;
  if (!document.is_object() || !document.contains("buffers") || !document["buffers"].is_array()) return lengths;
  for (const Json& buffer : document["buffers"]) {
    const Json* length = buffer.is_object() && buffer.contains("byteLength") ? &buffer["byteLength"] : nullptr;
    lengths.push_back(length && length->is_number_unsigned() ? length->get<std::uint64_t>() : 0);
  }
  return lengths;
}

bool hasScheme(const std::string& uri) {
  const std::size_t colon = uri.find(':');
  return colon != std::string::npos && colon < uri.find('/');
}

// tinygltf asks for JoinPath(folder, uri) and then JoinPath(".", uri): only the first is ours.
bool fileExists(const std::string& path, void* user) {
  FileAccess& access = *static_cast<FileAccess*>(user);
  if (!access.refusal.empty()) return false;
  std::string prefix = access.folder;
  if (!prefix.empty() && prefix.back() != '/') prefix += '/';
  if (path.compare(0, prefix.size(), prefix) != 0) return false;
  const std::string uri = path.substr(prefix.size());
  access.uri = uri;
  std::error_code error;
  if (uri.empty()) {
    access.refusal = "expected a 'uri' (a GLB's first buffer may use its BIN chunk instead), found none";
  } else if (uri.find('\0') != std::string::npos) {
    access.refusal = "expected a file name, found a NUL byte in the uri";
  } else if (uri.front() == '/') {
    access.refusal = "expected a relative uri or a base64 data: uri, found the absolute path " + quote(uri);
  } else if (hasScheme(uri)) {
    access.refusal = "expected a relative uri or a base64 data: uri, found " + quote(uri);
  } else if (access.folder.empty()) {
    access.refusal = "cannot read the buffer file " + quote(uri) + ": the input has no folder to find it in";
  } else if (!std::filesystem::is_regular_file(path, error)) {
    const bool exists = std::filesystem::exists(path, error);
    access.refusal = "cannot read the buffer file " + quote(uri) + ": " +
                     (exists ? std::string("not a regular file") : std::generic_category().message(ENOENT));
  }
  return access.refusal.empty();
}

std::string expandFilePath(const std::string& path, void*) { return path; }  // no ~ or $VARIABLES

// Reads exactly the file's size: tinygltf then compares it with the buffer's byteLength.
bool readWholeFile(std::vector<unsigned char>* out, std::string*, const std::string& path, void* user) {
  FileAccess& access = *static_cast<FileAccess*>(user);
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (!in || error) {
    const int code = errno ? errno : error.value();
    access.refusal = "cannot read the buffer file " + quote(access.uri) + ": " + std::generic_category().message(code);
    return false;
  }
  if (!access.byteLengths) access.byteLengths = bufferByteLengths(access.json);
  const std::size_t index = access.model ? access.model->buffers.size() : 0;
  if (index < access.byteLengths->size() && size != (*access.byteLengths)[index]) {
    access.refusal = "expected " + std::to_string((*access.byteLengths)[index]) + " bytes (its byteLength) in " +
                     quote(access.uri) + ", found " + std::to_string(size);
    return false;
  }
  out->resize(static_cast<std::size_t>(size));
  in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size));
  if (static_cast<std::uintmax_t>(in.gcount()) != size) {
    access.refusal = "cannot read the buffer file " + quote(access.uri) + ": it has fewer bytes than its size said";
    return false;
  }
  return true;
}

// uvtk reads no image: each is accepted and left undecoded.
bool ignoreImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

std::string afterMarker(const std::string& text, const std::string& marker) {
  const std::size_t at = text.find(marker);
  if (at == std::string::npos) return "";
  std::size_t end = at + marker.size();
  while (end < text.size() && text[end] >= '0' && text[end] <= '9') ++end;
  return text.substr(at + marker.size(), end - at - marker.size());
}

// tinygltf's error text as one of our lines: a JSON pointer where the failing element is known.
InputError loadError(const std::string& name, std::string err, const FileAccess& access, const tinygltf::Model& model,
                     bool binary, std::size_t jsonOffset) {
  // Buffers are parsed in order and kept, so the failing buffer is the next one.
  const std::string buffer = "/buffers/" + std::to_string(model.buffers.size());
  if (!access.refusal.empty()) return pointerError(name, buffer, access.refusal);
  if (err.find("File size mismatch") != std::string::npos)
    return pointerError(name, buffer,
                        "expected " + afterMarker(err, "requestedBytes ") + " bytes (its byteLength) in " + quote(access.uri) +
                            ", found " + afterMarker(err, "but got "));
  if (err.find("File is empty") != std::string::npos)
    return pointerError(name, buffer, "expected its byteLength in " + quote(access.uri) + ", found an empty file");
  if (err.find("Failed to decode 'uri' : ") != std::string::npos)
    return pointerError(name, buffer + "/uri", "expected base64 data of exactly its byteLength, found other data");
  if (err.find("Invalid `byteLength'. Must be equal or less than binary size") != std::string::npos)
    return pointerError(name, buffer + "/byteLength",
                        "expected at most " + afterMarker(err, "binary size = ") + " (the BIN chunk's length), found " +
                            afterMarker(err, "`byteLength' = "));
  if (err.find("Invalid binary data in `Buffer', or GLB with empty BIN chunk") != std::string::npos)
    return pointerError(name, buffer, "expected a 'uri' or a BIN chunk, found neither");
  // nlohmann's parse errors: "[json.exception.parse_error.101] parse error at line L, column C: WHAT".
  if (err.rfind("[json.exception.", 0) == 0) {
    const std::size_t close = err.find("] ");
    if (close != std::string::npos) err = err.substr(close + 2);
    const std::string line = afterMarker(err, "parse error at line ");
    const std::size_t colon = err.find(": ");
    if (!line.empty() && colon != std::string::npos) {
      std::string what = err.substr(colon + 2);
      if (what.size() > 200) what = what.substr(0, 200) + "...";
      const std::string column = afterMarker(err, ", column ");
      if (binary)
        return byteError(name, jsonOffset, "invalid JSON in the JSON chunk at line " + line + ", column " + column + ": " + what);
      return InputError(name + ":" + line + ": error: invalid JSON at column " + column + ": " + what);
    }
    return fileError(name, "invalid JSON: " + (err.size() > 200 ? err.substr(0, 200) + "..." : err));
  }
  // Anything else: its lines joined, cut to a readable length.
  std::string text;
  for (const char c : err) text += c == '\n' ? std::string("; ") : std::string(1, c);
  while (!text.empty() && (text.back() == ' ' || text.back() == ';')) text.pop_back();
  if (text.size() > 200) text = text.substr(0, 200) + "...";
  return fileError(name, text.empty() ? "tinygltf could not load the file" : text);
}

// ---- Accessors ----

const char* componentName(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "DOUBLE";
    default: return "an unknown component type";
  }
}

const char* typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "an unknown type";
  }
}

enum class Use { position, normal, texcoord, indices };

// The element types each use accepts (glTF 2.0 3.7.2.1, and KHR_mesh_quantization's table).
bool accepts(Use use, int type, int component, bool normalized, bool quantized) {
  using C = int;
  const C f = TINYGLTF_COMPONENT_TYPE_FLOAT, b = TINYGLTF_COMPONENT_TYPE_BYTE, ub = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
          s = TINYGLTF_COMPONENT_TYPE_SHORT, us = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  const bool small = component == b || component == ub || component == s || component == us;
  switch (use) {
    case Use::position: return type == TINYGLTF_TYPE_VEC3 && (component == f || (quantized && small));
    case Use::normal: return type == TINYGLTF_TYPE_VEC3 && (component == f || (quantized && normalized && (component == b || component == s)));
    case Use::texcoord:
      return type == TINYGLTF_TYPE_VEC2 &&
             (component == f || (normalized && (component == ub || component == us)) || (quantized && small));
    case Use::indices:
      return type == TINYGLTF_TYPE_SCALAR && !normalized &&
             (component == ub || component == us || component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  }
  return false;
}

std::string expectedOf(Use use) {
  switch (use) {
    case Use::position: return "a VEC3 accessor of FLOAT (with KHR_mesh_quantization also of BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT)";
    case Use::normal: return "a VEC3 accessor of FLOAT (with KHR_mesh_quantization also of normalized BYTE or SHORT)";
    case Use::texcoord:
      return "a VEC2 accessor of FLOAT, normalized UNSIGNED_BYTE or normalized UNSIGNED_SHORT (with KHR_mesh_quantization "
             "also of BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT)";
    case Use::indices: return "a SCALAR accessor of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, not normalized";
  }
  return "";
}

// An accessor's elements, checked to lie within their bufferView and buffer.
struct AccessorView {
  int index = -1;
  const unsigned char* data = nullptr;
  std::size_t count = 0, stride = 0;
  int componentType = 0, components = 0;
  bool normalized = false;
};

class ModelReader {
 public:
  ModelReader(const tinygltf::Model& model, const std::string& name) : model_(model), name_(name) {
    const auto declared = [&](const std::vector<std::string>& list) {
      return std::find(list.begin(), list.end(), "KHR_mesh_quantization") != list.end();
    };
    quantized_ = declared(model.extensionsUsed) || declared(model.extensionsRequired);
  }

  // `pointer` names the reference (e.g. "/meshes/0/primitives/1/attributes/POSITION").
  AccessorView accessor(int index, Use use, const std::string& pointer) const {
    const std::size_t accessorCount = model_.accessors.size();
    if (index < 0 || static_cast<std::size_t>(index) >= accessorCount)
      throw pointerError(name_, pointer, "expected an accessor index in " + range(accessorCount) + ", found " + std::to_string(index));
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    const std::string at = "/accessors/" + std::to_string(index);
    if (a.sparse.isSparse) throw pointerError(name_, at + "/sparse", "sparse accessors are not supported");
    if (!accepts(use, a.type, a.componentType, a.normalized, quantized_))
      throw pointerError(name_, pointer,
                         "expected " + expectedOf(use) + ", found accessor " + std::to_string(index) + ": " + typeName(a.type) +
                             " of " + (a.normalized ? "normalized " : "") + componentName(a.componentType));
    if (a.bufferView == -1)
      throw pointerError(name_, at, "expected a bufferView, found none (an accessor without one holds zeros; uvtk reads none)");
    const std::size_t viewCount = model_.bufferViews.size();
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= viewCount)
      throw pointerError(name_, at + "/bufferView", "expected a bufferView index in " + range(viewCount) + ", found " + std::to_string(a.bufferView));
    if (a.count == 0) throw pointerError(name_, at + "/count", "expected at least 1 element, found 0");
    const std::size_t v = static_cast<std::size_t>(a.bufferView);
    const tinygltf::BufferView& view = model_.bufferViews[v];
    const std::string viewAt = "/bufferViews/" + std::to_string(v);
    const std::size_t bufferCount = model_.buffers.size();
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= bufferCount)
      throw pointerError(name_, viewAt + "/buffer", "expected a buffer index in " + range(bufferCount) + ", found " + std::to_string(view.buffer));
    const std::vector<unsigned char>& buffer = model_.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
      throw pointerError(name_, viewAt,
                         "expected its " + std::to_string(view.byteLength) + " bytes from byteOffset " + std::to_string(view.byteOffset) +
                             " within buffer " + std::to_string(view.buffer) + " (" + std::to_string(buffer.size()) +
                             " bytes), found them past its end");
    AccessorView result;
    result.index = index;
    result.componentType = a.componentType;
    result.components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    result.normalized = a.normalized;
    result.count = a.count;
    const std::size_t elementSize =
        static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType))) *
        static_cast<std::size_t>(result.components);
    result.stride = view.byteStride == 0 ? elementSize : view.byteStride;
    if (result.stride < elementSize)
      throw pointerError(name_, viewAt + "/byteStride",
                         "expected at least " + std::to_string(elementSize) + " (the element size of accessor " +
                             std::to_string(index) + "), found " + std::to_string(result.stride));
    // offset + stride (count - 1) + elementSize <= byteLength, without overflow.
    const std::size_t length = view.byteLength;
    if (a.byteOffset > length || length - a.byteOffset < elementSize ||
        (a.count - 1) > (length - a.byteOffset - elementSize) / result.stride)
      throw pointerError(name_, at,
                         "expected its " + std::to_string(a.count) + " elements of " + std::to_string(elementSize) +
                             " bytes within bufferView " + std::to_string(v) + " (" + std::to_string(length) + " bytes" +
                             (a.byteOffset > 0 ? " from byteOffset " + std::to_string(a.byteOffset) : std::string()) +
                             "), found them past its end");
    result.data = buffer.data() + view.byteOffset + a.byteOffset;
    return result;
  }

  // Component k of element i as a number (normalized types as the spec maps them to [-1, 1]).
  double component(const AccessorView& view, std::size_t i, int k) const {
    const unsigned char* p = view.data + i * view.stride;
    switch (view.componentType) {
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const double c = static_cast<std::int8_t>(p[k]);
        return view.normalized ? std::max(c / 127.0, -1.0) : c;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return view.normalized ? p[k] / 255.0 : p[k];
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t c;
        std::memcpy(&c, p + 2 * k, 2);
        return view.normalized ? std::max(c / 32767.0, -1.0) : c;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t c;
        std::memcpy(&c, p + 2 * k, 2);
        return view.normalized ? c / 65535.0 : c;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t c;
        std::memcpy(&c, p + 4 * k, 4);
        return c;
      }
      default: {
        float c;
        std::memcpy(&c, p + 4 * k, 4);
        if (!std::isfinite(c))
          throw pointerError(name_, "/accessors/" + std::to_string(view.index),
                             "expected finite numbers, found " + std::string(std::isnan(c) ? "nan" : "inf") + " in element " +
                                 std::to_string(i));
        return c;
      }
    }
  }

  Vec3 vec3(const AccessorView& view, std::size_t i) const {
    return {component(view, i, 0), component(view, i, 1), component(view, i, 2)};
  }

  static std::string range(std::size_t count) {
    return count == 0 ? "an empty list" : "0.." + std::to_string(count - 1);
  }

 private:
  const tinygltf::Model& model_;
  const std::string& name_;
  bool quantized_ = false;
};

// ---- The scene ----

struct Instance {
  int node = -1;  // -1: a mesh of a file without scenes
  int mesh = -1;
  Mat4 world = Mat4::Identity();
};

Mat4 localMatrix(const tinygltf::Node& node, const std::string& at, const std::string& name) {
  const auto checkSize = [&](const std::vector<double>& values, std::size_t size, const char* key) {
    if (!values.empty() && values.size() != size)
      throw pointerError(name, at + "/" + key, "expected " + std::to_string(size) + " numbers, found " + std::to_string(values.size()));
  };
  checkSize(node.matrix, 16, "matrix");
  if (!node.matrix.empty()) {
    const Mat4 m = Eigen::Map<const Mat4>(node.matrix.data());  // column-major, as glTF's
    if (m(3, 0) != 0.0 || m(3, 1) != 0.0 || m(3, 2) != 0.0 || m(3, 3) != 1.0)
      throw pointerError(name, at + "/matrix", "expected an affine matrix (last row 0 0 0 1), found another last row");
    return m;
  }
  checkSize(node.translation, 3, "translation");
  checkSize(node.rotation, 4, "rotation");
  checkSize(node.scale, 3, "scale");
  Mat4 m = Mat4::Identity();
  if (!node.rotation.empty()) {
    const Eigen::Quaterniond q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    const double length = q.norm();
    if (!(std::abs(length - 1.0) <= kUnitTolerance))
      throw pointerError(name, at + "/rotation", "expected a unit quaternion, found one of length " + std::to_string(length));
    m.topLeftCorner<3, 3>() = q.normalized().toRotationMatrix();
  }
  if (!node.scale.empty())
    for (int c = 0; c < 3; ++c) m.col(c) *= node.scale[static_cast<std::size_t>(c)];
  if (!node.translation.empty())
    for (int r = 0; r < 3; ++r) m(r, 3) = node.translation[static_cast<std::size_t>(r)];
  return m;
}

std::vector<Instance> sceneInstances(const tinygltf::Model& model, const std::string& name) {
  std::vector<Instance> instances;
  const std::size_t meshCount = model.meshes.size(), nodeCount = model.nodes.size(), sceneCount = model.scenes.size();
  if (model.scenes.empty()) {
    for (std::size_t m = 0; m < meshCount; ++m) instances.push_back({-1, static_cast<int>(m), Mat4::Identity()});
    return instances;
  }
  if (model.defaultScene != -1 && (model.defaultScene < 0 || static_cast<std::size_t>(model.defaultScene) >= sceneCount))
    throw pointerError(name, "/scene", "expected a scene index in " + ModelReader::range(sceneCount) + ", found " + std::to_string(model.defaultScene));
  const std::size_t s = model.defaultScene == -1 ? 0 : static_cast<std::size_t>(model.defaultScene);
  struct Pending {
    int node;
    int parent;  // -1: a root of the scene
    std::size_t slot;
    std::size_t depth;
    Mat4 parentWorld;
  };
  std::vector<Pending> stack;
  const std::vector<int>& roots = model.scenes[s].nodes;
  for (std::size_t k = roots.size(); k-- > 0;) stack.push_back({roots[k], -1, k, 1, Mat4::Identity()});
  std::vector<char> visited(nodeCount, 0);
  while (!stack.empty()) {
    const Pending p = stack.back();
    stack.pop_back();
    const std::string reference = p.parent < 0 ? "/scenes/" + std::to_string(s) + "/nodes/" + std::to_string(p.slot)
                                               : "/nodes/" + std::to_string(p.parent) + "/children/" + std::to_string(p.slot);
    if (p.node < 0 || static_cast<std::size_t>(p.node) >= nodeCount)
      throw pointerError(name, reference, "expected a node index in " + ModelReader::range(nodeCount) + ", found " + std::to_string(p.node));
    const std::size_t n = static_cast<std::size_t>(p.node);
    if (visited[n])
      throw pointerError(name, reference,
                         "node " + std::to_string(n) + " is reached a second time (a cycle, or a child of two parents); uvtk reads node trees");
    visited[n] = 1;
    if (p.depth > kMaxNodeDepth)
      throw pointerError(name, reference, "expected nodes nested at most " + std::to_string(kMaxNodeDepth) + " deep, found deeper");
    const tinygltf::Node& node = model.nodes[n];
    const std::string at = "/nodes/" + std::to_string(n);
    const Mat4 world = p.parentWorld * localMatrix(node, at, name);
    if (node.mesh != -1) {
      if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= meshCount)
        throw pointerError(name, at + "/mesh", "expected a mesh index in " + ModelReader::range(meshCount) + ", found " + std::to_string(node.mesh));
      instances.push_back({p.node, node.mesh, world});
    }
    for (std::size_t k = node.children.size(); k-- > 0;) stack.push_back({node.children[k], p.node, k, p.depth + 1, world});
  }
  return instances;
}

bool isTriangleMode(int mode) {
  return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

// Appends one triangle's corner attributes: the table is created (with -1 for every earlier
// triangle) by the first primitive that has the attribute.
void appendCorners(std::vector<Triangle>& table, std::size_t triangleIndex, bool has, const Triangle& corners) {
  if (table.empty() && !has) return;
  if (table.size() < triangleIndex) table.resize(triangleIndex, kNoCorners);
  table.push_back(has ? corners : kNoCorners);
}

// A primitive's accessors, checked once per mesh, before any instance is read.
struct PrimitiveViews {
  bool triangles = false;  // false: points or lines, skipped
  int mode = TINYGLTF_MODE_TRIANGLES;
  AccessorView positions, normals, texcoords, indices;
  bool hasNormals = false, hasTexcoords = false, hasIndices = false;
};

std::vector<PrimitiveViews> meshViews(const ModelReader& reader, const tinygltf::Model& model, int m, const std::string& name) {
  const std::vector<tinygltf::Primitive>& primitives = model.meshes[static_cast<std::size_t>(m)].primitives;
  std::vector<PrimitiveViews> views(primitives.size());
  for (std::size_t p = 0; p < primitives.size(); ++p) {
    const tinygltf::Primitive& primitive = primitives[p];
    PrimitiveViews& v = views[p];
    const std::string at = "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p);
    v.mode = primitive.mode;
    if (primitive.mode >= 0 && primitive.mode <= 3) continue;
    if (!isTriangleMode(primitive.mode))
      throw pointerError(name, at + "/mode", "expected a primitive mode in 0..6, found " + std::to_string(primitive.mode));
    v.triangles = true;
    const auto attribute = [&](const char* key) {
      const auto found = primitive.attributes.find(key);
      return found == primitive.attributes.end() ? -2 : found->second;
    };
    if (attribute("POSITION") == -2) throw pointerError(name, at + "/attributes", "expected a POSITION attribute, found none");
    v.positions = reader.accessor(attribute("POSITION"), Use::position, at + "/attributes/POSITION");
    const auto sameCount = [&](const AccessorView& view, const char* key) {
      if (view.count != v.positions.count)
        throw pointerError(name, at + "/attributes/" + key,
                           "expected " + std::to_string(v.positions.count) + " elements (the POSITION count), found " +
                               std::to_string(view.count));
    };
    v.hasNormals = attribute("NORMAL") != -2;
    v.hasTexcoords = attribute("TEXCOORD_0") != -2;
    if (v.hasNormals) sameCount(v.normals = reader.accessor(attribute("NORMAL"), Use::normal, at + "/attributes/NORMAL"), "NORMAL");
    if (v.hasTexcoords)
      sameCount(v.texcoords = reader.accessor(attribute("TEXCOORD_0"), Use::texcoord, at + "/attributes/TEXCOORD_0"), "TEXCOORD_0");
    v.hasIndices = primitive.indices != -1;
    if (v.hasIndices) v.indices = reader.accessor(primitive.indices, Use::indices, at + "/indices");
    const std::size_t n = v.hasIndices ? v.indices.count : v.positions.count;
    if (primitive.mode == TINYGLTF_MODE_TRIANGLES ? n % 3 != 0 : n < 3)
      throw pointerError(name, at + (v.hasIndices ? "/indices" : "/attributes/POSITION"),
                         primitive.mode == TINYGLTF_MODE_TRIANGLES
                             ? "expected a multiple of 3 vertices for TRIANGLES, found " + std::to_string(n)
                             : "expected at least 3 vertices for a triangle strip or fan, found " + std::to_string(n));
  }
  return views;
}

// A mesh's lists in extras.uvtk (io/face_lists.h): its faces, 0-based, in the order of its
// triangle primitives; a list is empty when absent or not an array of whole numbers.
ListedFaces listedFaces(const tinygltf::Value& extras) {
  ListedFaces lists;
  if (!extras.IsObject() || !extras.Has("uvtk")) return lists;
  const tinygltf::Value& uvtk = extras.Get("uvtk");
  for (std::size_t i = 0; i < kFaceLists.size(); ++i) {
    const std::string key(kFaceLists[i].gltfKey);
    if (!uvtk.IsObject() || !uvtk.Has(key)) continue;
    const tinygltf::Value& list = uvtk.Get(key);
    if (!list.IsArray()) continue;
    std::vector<std::size_t>& faces = lists[i];
    faces.reserve(list.ArrayLen());
    for (std::size_t j = 0; j < list.ArrayLen(); ++j) {
      const tinygltf::Value& face = list.Get(int(j));
      const double number = face.IsNumber() ? face.GetNumberAsDouble() : -1.0;
      if (!(number >= 0.0 && number < 0x1p53 && number == std::floor(number))) {
        faces.clear();
        break;
      }
      faces.push_back(static_cast<std::size_t>(number));
    }
  }
  return lists;
}

ReadMeshResult readModel(const tinygltf::Model& model, const std::string& name, std::size_t inputBytes) {
  if (model.asset.version.rfind("2.", 0) != 0)
    throw pointerError(name, "/asset/version", "expected a glTF version 2.x, found " + quote(model.asset.version));
  for (std::size_t i = 0; i < model.extensionsRequired.size(); ++i) {
    const std::string& extension = model.extensionsRequired[i];
    if (extension != "KHR_mesh_quantization" && extension != "KHR_texture_transform")
      throw pointerError(name, "/extensionsRequired/" + std::to_string(i),
                         "the file requires the extension " + quote(extension) +
                             ", which uvtk does not read (it reads KHR_mesh_quantization; KHR_texture_transform moves no vertex)");
  }
  const std::vector<Instance> instances = sceneInstances(model, name);

  // Every instance gets its own vertices: the total is bounded by the input's size before reading.
  ModelReader reader(model, name);
  std::vector<std::vector<PrimitiveViews>> views(model.meshes.size());
  std::vector<char> viewed(model.meshes.size(), 0);
  std::uint64_t elements = 0;
  for (const Instance& instance : instances) {
    const std::size_t m = static_cast<std::size_t>(instance.mesh);
    if (!viewed[m]) views[m] = meshViews(reader, model, instance.mesh, name);
    viewed[m] = 1;
    for (const PrimitiveViews& v : views[m])
      if (v.triangles) elements += v.positions.count + (v.hasIndices ? v.indices.count : 0);
  }
  for (const tinygltf::Buffer& buffer : model.buffers) inputBytes += buffer.data.size();
  const std::uint64_t limit = std::max(kMinInstancedElements, kInstancedElementsPerByte * inputBytes);
  if (elements > limit)
    throw fileError(name, "expected at most " + std::to_string(limit) + " vertices and indices in all mesh instances of the scene (" +
                              std::to_string(kInstancedElementsPerByte) + " per input byte), found " + std::to_string(elements));
  // Instancing makes the mesh far larger than the file: the memory check of the file's size cannot
  // see it, so the expanded size is checked here, before a vertex is read.
  const std::optional<std::uint64_t> available = availableMemory();
  if (available && elements * kMapBytesPerElement > *available)
    throw fileError(name, "its scene holds " + std::to_string(elements) + " vertices and indices once instanced, which need about " +
                              formatBytes(elements * kMapBytesPerElement) + " of memory, more than the " +
                              formatBytes(*available) + " available");

  Mesh mesh;
  MeshWarnings warnings;
  std::vector<std::size_t> marked;  // faces of uvtk's lists (io/face_lists.h)
  std::vector<std::uint32_t> indices;
  for (const Instance& instance : instances) {
    const Eigen::Matrix3d linear = instance.world.topLeftCorner<3, 3>();
    const bool flip = linear.determinant() < 0.0;
    const Eigen::Matrix3d normalMatrix = linear.inverse().transpose();
    const std::vector<PrimitiveViews>& primitives = views[static_cast<std::size_t>(instance.mesh)];
    const std::size_t firstFace = mesh.triangles.size();
    for (std::size_t p = 0; p < primitives.size(); ++p) {
      const PrimitiveViews& primitive = primitives[p];
      if (!primitive.triangles) {
        ++warnings.skippedPrimitives;
        continue;
      }
      const std::string at = "/meshes/" + std::to_string(instance.mesh) + "/primitives/" + std::to_string(p);
      const AccessorView& positions = primitive.positions;
      const AccessorView& normals = primitive.normals;
      const AccessorView& texcoords = primitive.texcoords;
      const bool hasNormals = primitive.hasNormals, hasTexcoords = primitive.hasTexcoords;
      const std::size_t count = positions.count;
      indices.clear();
      if (primitive.hasIndices) {
        const AccessorView& view = primitive.indices;
        indices.reserve(view.count);
        for (std::size_t i = 0; i < view.count; ++i) {
          const double index = reader.component(view, i, 0);
          if (index >= static_cast<double>(count))
            throw pointerError(name, at + "/indices",
                               "expected vertex indices below " + std::to_string(count) + " (the POSITION count), found " +
                                   std::to_string(static_cast<std::uint64_t>(index)) + " at element " + std::to_string(i));
          indices.push_back(static_cast<std::uint32_t>(index));
        }
      } else {
        indices.resize(count);
        for (std::size_t i = 0; i < count; ++i) indices[i] = static_cast<std::uint32_t>(i);
      }
      const std::size_t n = indices.size();

      if (count > static_cast<std::size_t>(INT_MAX) - mesh.positions.size())
        throw fileError(name, "expected at most " + std::to_string(INT_MAX) + " vertices in all, found more");
      const int base = static_cast<int>(mesh.positions.size());
      const int texcoordBase = static_cast<int>(mesh.texcoords.size()), normalBase = static_cast<int>(mesh.normals.size());
      for (std::size_t i = 0; i < count; ++i) {
        const Vec3 q = (instance.world * reader.vec3(positions, i).homogeneous()).head<3>();
        if (!q.allFinite())
          throw pointerError(name, instance.node >= 0 ? "/nodes/" + std::to_string(instance.node) : at,
                             "its transform takes element " + std::to_string(i) + " of accessor " + std::to_string(positions.index) +
                                 " beyond the range of a double");
        mesh.positions.push_back(q);
        if (hasNormals) {
          const Vec3 normal = normalMatrix * reader.vec3(normals, i);
          const double length = normal.norm();
          mesh.normals.push_back(length > 0.0 && std::isfinite(length) ? Vec3(normal / length) : Vec3::Zero());
        }
        if (hasTexcoords) mesh.texcoords.emplace_back(reader.component(texcoords, i, 0), 1.0 - reader.component(texcoords, i, 1), 0.0);
      }

      const auto addTriangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        Triangle t = {static_cast<int>(a), static_cast<int>(b), static_cast<int>(c)};
        if (flip) std::swap(t[1], t[2]);
        const std::size_t f = mesh.triangles.size();
        mesh.triangles.push_back({base + t[0], base + t[1], base + t[2]});
        appendCorners(mesh.cornerTexcoords, f, hasTexcoords, {texcoordBase + t[0], texcoordBase + t[1], texcoordBase + t[2]});
        appendCorners(mesh.cornerNormals, f, hasNormals, {normalBase + t[0], normalBase + t[1], normalBase + t[2]});
      };
      // glTF 2.0 3.7.2.1: strips p_i = {v_i, v_{i+(1+i%2)}, v_{i+(2-i%2)}}, fans p_i = {v_{i+1}, v_{i+2}, v_0}.
      if (primitive.mode == TINYGLTF_MODE_TRIANGLES) {
        for (std::size_t i = 0; i + 2 < n; i += 3) addTriangle(indices[i], indices[i + 1], indices[i + 2]);
      } else if (primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 0; i + 2 < n; ++i)
          addTriangle(indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]);
      } else {
        for (std::size_t i = 0; i + 2 < n; ++i) addTriangle(indices[i + 1], indices[i + 2], indices[0]);
      }
    }
    applyFaceLists(mesh, firstFace, mesh.triangles.size() - firstFace,
                   listedFaces(model.meshes[static_cast<std::size_t>(instance.mesh)].extras), marked);
  }
  if (mesh.triangles.empty())
    throw fileError(name, "expected at least one triangle primitive in the scene, found none" +
                              (warnings.skippedPrimitives > 0
                                   ? " (" + std::to_string(warnings.skippedPrimitives) +
                                         (warnings.skippedPrimitives == 1 ? " primitive" : " primitives") +
                                         " of points or lines skipped)"
                                   : std::string()));
  // Corner tables created by a late primitive reach the end; those of early ones must, too.
  if (mesh.hasTexcoords()) mesh.cornerTexcoords.resize(mesh.triangles.size(), kNoCorners);
  if (mesh.hasNormals()) mesh.cornerNormals.resize(mesh.triangles.size(), kNoCorners);
  if (!mesh.listedFaceFlags.empty()) mesh.listedFaceFlags.resize(mesh.triangles.size(), 0);

  ReadMeshResult result;
  const MeshWarnings checked = checkMesh(mesh);
  result.warnings = warnings;
  result.warnings.degenerateFaces = checked.degenerateFaces;
  result.warnings.unreferencedVertices = checked.unreferencedVertices;
  result.warnings.listedInvalidUvFaces = marked.size();
  result.mesh = std::move(mesh);
  result.listedInvalidUvFaces = std::move(marked);
  return result;
}

}  // namespace

ReadMeshResult readGltf(std::string_view bytes, const std::string& name, const std::string& folder, bool binary) {
  GlbJson json{0, bytes.size()};
  if (binary) json = checkGlb(bytes, name);
  if (json.length > UINT_MAX) throw fileError(name, "expected at most 4 GiB of JSON, found more");
  checkJsonDepth(bytes.substr(json.offset, json.length), name, binary, json.offset);

  tinygltf::Model model;
  FileAccess access{folder, "", "", bytes.substr(json.offset, json.length), &model, std::nullopt};
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&ignoreImage, nullptr);
  loader.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, nullptr, &access});
  std::string err, warn;  // tinygltf's warnings are about what uvtk does not read (images, unknown keys)
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const bool loaded =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, static_cast<unsigned int>(bytes.size()), folder)
             : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()), folder);
  if (!loaded) throw loadError(name, err, access, model, binary, json.offset);
  return readModel(model, name, bytes.size());
}

ReadMeshResult readGltf(std::istream& in, const std::string& path) {
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw fileError(path, "cannot read: input/output error");
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  const bool binary = extension == ".glb" || bytes.rfind("glTF", 0) == 0;
  std::string folder = std::filesystem::path(path).parent_path().string();
  if (folder.empty()) folder = ".";
  return readGltf(bytes, path, folder, binary);
}

}  // namespace uvtk::io
