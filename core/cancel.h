// A request to stop long work early, for the whole process: the Python module makes it when the
// user presses Ctrl-C during a call. parallelFor stops handing out indices once it is made and then
// throws Cancelled; long loops outside parallelFor call throwIfCancelled() between chunks. Nothing
// requests it in the command line (its signal handlers end the process), so there it never fires.
#pragma once

#include <exception>

namespace uvtk {

// Work given up because a cancellation was requested; what it was writing is discarded as on any
// exception (outputs are staged: docs/robustness.md).
class Cancelled : public std::exception {
 public:
  const char* what() const noexcept override;
};

void requestCancel();
// Withdraws the request, once the work it stopped has returned.
void clearCancel();
bool cancelRequested();
// Throws Cancelled when a cancellation is requested.
void throwIfCancelled();

}  // namespace uvtk
