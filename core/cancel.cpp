// The one cancellation flag of the process.
//
// The core library is linked statically, its symbols hidden, into each shared object that uses it
// (libuvtk.so, libuvtk_point.so, the Python module): each holds a copy of this file. So that the
// module's requestCancel() reaches the loops inside libuvtk.so, every copy uses the first exported
// uvtk_cancel_request the dynamic linker finds from it (the module's, which it exports; the
// libraries' are hidden), else its own: in a program linked statically, the one there is.
#include "core/cancel.h"

#include <dlfcn.h>

#include <atomic>

extern "C" {
__attribute__((visibility("default"))) std::atomic<bool> uvtk_cancel_request{false};
}

namespace uvtk {

namespace {

std::atomic<bool>& cancelRequest() {
  static std::atomic<bool>& request = *[] {
    void* exported = dlsym(RTLD_DEFAULT, "uvtk_cancel_request");
    return exported ? static_cast<std::atomic<bool>*>(exported) : &uvtk_cancel_request;
  }();
  return request;
}

}  // namespace

const char* Cancelled::what() const noexcept { return "cancelled"; }

void requestCancel() { cancelRequest().store(true); }

void clearCancel() { cancelRequest().store(false); }

bool cancelRequested() { return cancelRequest().load(); }

void throwIfCancelled() {
  if (cancelRequested()) throw Cancelled();
}

}  // namespace uvtk
