#include "core/error.h"

#include <cstdio>
#include <cstdlib>

namespace uvtk {

int exitStatus(const std::exception& error) {
  if (dynamic_cast<const UsageError*>(&error)) return 2;
  if (dynamic_cast<const InputError*>(&error)) return 3;
  if (dynamic_cast<const OutputError*>(&error)) return 4;
  return 1;
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
