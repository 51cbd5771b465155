// Error vocabulary. The library throws and never exits; the CLI's main is the only catcher.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace uvtk {

// A wrong command-line option or API argument (exit status 2).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Malformed or impossible input data; the message reads "FILE:LINE: error: ..." (exit status 3).
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An output that cannot be written (exit status 4).
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A check that ran to its end and found the data outside its tolerance, after printing its
// report (`uvtk check`; exit status 1, without the "internal error" of other status-1 exceptions).
struct CheckFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The exit status an error stands for, as above. Exceptions of the standard library that a user's
// input or machine can cause are classed too: std::bad_alloc and std::length_error (more memory
// than there is, or than a size can hold) and std::filesystem::filesystem_error (a path the system
// refused, e.g. too long; sites that write translate theirs to OutputError) are bad input, 3.
// 1 for any other exception (a bug).
int exitStatus(const std::exception& error);

// The one line that reports `error`: its message with control characters escaped (a NUL or an
// escape sequence in a file name must neither cut nor garble it); the standard library's
// exceptions above in uvtk's words ("FILE: error: REASON", "uvtk: error: out of memory ...").
std::string errorMessage(const std::exception& error);

// `text` with its control characters but the line feed (which separates the lines of a message
// listing several problems) escaped as in JSON (\u0000, \t, \r, \u001b); for messages.
std::string printable(std::string_view text);

// `name` as a JSON string: in double quotes, with quotes, backslashes and every control character
// escaped. How a message shows a file name that may hold anything, a NUL included.
std::string quotedName(std::string_view name);

// Throws the error class whose exit status is `status` (1: std::runtime_error) with `message`: how
// a command that carried on past failures ends with the worst one's status.
[[noreturn]] void throwWithStatus(int status, const std::string& message);

// Always-on check of a programmer's invariant; failing means a bug in uvtk, not bad input.
[[noreturn]] void checkFailed(const char* expression, const char* file, int line);

}  // namespace uvtk

#define UVTK_CHECK(expr) ((expr) ? (void)0 : ::uvtk::checkFailed(#expr, __FILE__, __LINE__))
