// Runs the `uvtk` program as a user does, in a scratch folder: exit status and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "scratch_dir.h"

namespace uvtk {

struct CliRun {
  int status;       // the exit status, or -1 when the program did not exit normally
  std::string err;  // what it printed on stderr
};

class CliTest : public ScratchDirTest {
 protected:
  CliRun uvtk(const std::string& arguments) const {
    const std::string errFile = path("stderr.txt");
    const std::string command = std::string(UVTK_BINARY) + " " + arguments + " 2> " + errFile + " > /dev/null";
    const int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, readText(errFile)};
  }
};

}  // namespace uvtk
