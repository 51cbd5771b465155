#include "core/error.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <new>

namespace uvtk {

int exitStatus(const std::exception& error) {
  if (dynamic_cast<const UsageError*>(&error)) return 2;
  if (dynamic_cast<const InputError*>(&error)) return 3;
  if (dynamic_cast<const OutputError*>(&error)) return 4;
  if (dynamic_cast<const std::bad_alloc*>(&error) || dynamic_cast<const std::length_error*>(&error)) return 3;
  if (dynamic_cast<const std::filesystem::filesystem_error*>(&error)) return 3;
  return 1;
}

namespace {

// Appends `c` escaped as in a JSON string.
void appendEscaped(std::string& out, char c) {
  switch (c) {
    case '\t': out += "\\t"; return;
    case '\r': out += "\\r"; return;
    case '\n': out += "\\n"; return;
    default: {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", unsigned(static_cast<unsigned char>(c)));
      out += code;
    }
  }
}

bool isControl(char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }

}  // namespace

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text)
    if (isControl(c) && c != '\n')
      appendEscaped(out, c);
    else
      out += c;
  return out;
}

std::string quotedName(std::string_view name) {
  std::string out = "\"";
  for (const char c : name) {
    if (c == '"' || c == '\\')
      out += '\\', out += c;
    else if (isControl(c))
      appendEscaped(out, c);
    else
      out += c;
  }
  return out + "\"";
}

std::string errorMessage(const std::exception& error) {
  if (dynamic_cast<const std::bad_alloc*>(&error))
    return "uvtk: error: out of memory: the work needs more memory than the machine has or ulimit -v allows";
  if (dynamic_cast<const std::length_error*>(&error))
    return "uvtk: error: out of memory: a size beyond what can be allocated (" + printable(error.what()) + ")";
  if (const auto* fs = dynamic_cast<const std::filesystem::filesystem_error*>(&error))
    return (fs->path1().empty() ? std::string("uvtk") : printable(fs->path1().string())) +
           ": error: " + printable(fs->code().message());
  return printable(error.what());
}

void throwWithStatus(int status, const std::string& message) {
  if (status == 2) throw UsageError(message);
  if (status == 3) throw InputError(message);
  if (status == 4) throw OutputError(message);
  throw std::runtime_error(message);
}

void checkFailed(const char* expression, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: internal error: check failed: %s\n", file, line, expression);
  std::abort();
}

}  // namespace uvtk
