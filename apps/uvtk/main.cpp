// uvtk: the command line. main only dispatches and maps errors to exit codes:
// 1 a check failed (uvtk check) or a bug, 2 usage, 3 bad input, 4 cannot write output.
#include <sys/resource.h>

#include <cstdio>
#include <exception>
#include <string>

#include "commands.h"
#include "core/error.h"
#include "core/progress.h"
#include "io/temporary_file.h"

int main(int argc, char** argv) {
  CLI::App app{"uvtk: texture coordinates for triangle meshes, and proof that they are right"};
  app.require_subcommand(1);
  uvtk::cli::addMapCommand(app);
  uvtk::cli::addTexgenCommand(app);
  uvtk::cli::addRenderCommand(app);
  uvtk::cli::addReportCommand(app);
  uvtk::cli::addCompareCommand(app);
  uvtk::cli::addBenchCommand(app);
  uvtk::cli::addRunCommand(app);
  uvtk::cli::addSchemaCommand(app);
  uvtk::cli::addMergeReportsCommand(app);
  uvtk::cli::addEvalCommand(app);
  uvtk::cli::addCheckCommand(app);
  uvtk::setProgressEnabled(true);  // a command with --quiet turns it off
  uvtk::io::installInterruptHandlers();
  uvtk::io::divertStdoutForOutputs();  // `-o -`: stdout carries the output, summaries go to stderr
  // Every staged output holds an open file until the command publishes them all: a scene of
  // thousands of outputs needs more than the usual soft limit of 1024.
  rlimit files{};
  if (::getrlimit(RLIMIT_NOFILE, &files) == 0 && files.rlim_cur < files.rlim_max) {
    files.rlim_cur = files.rlim_max;
    ::setrlimit(RLIMIT_NOFILE, &files);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);
    return status == 0 ? 0 : 2;
  } catch (const uvtk::CheckFailure&) {
    return 1;  // the command printed its verdict
  } catch (const std::exception& e) {
    const int status = uvtk::exitStatus(e);
    const std::string message = uvtk::errorMessage(e);
    // Input and output errors name their file themselves.
    if (status == 2) std::fprintf(stderr, "uvtk: error: %s\n", message.c_str());
    if (status == 3 || status == 4) std::fprintf(stderr, "%s\n", message.c_str());
    if (status == 1) std::fprintf(stderr, "uvtk: internal error: %s\n", message.c_str());
    return status;
  }
  return 0;
}
