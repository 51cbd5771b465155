// uvtk: the command line. main only dispatches and maps errors to exit codes:
// 1 a check failed (uvtk check) or a bug, 2 usage, 3 bad input, 4 cannot write output.
#include <sys/resource.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "commands.h"
#include "core/error.h"
#include "core/memory.h"
#include "core/progress.h"
#include "help_examples.h"
#include "io/temporary_file.h"
#include "options/cli_values.h"

namespace {

// "; did you mean 'NAME'?" for the nearest of `names` to `typed`, or "".
std::string didYouMean(const std::string& typed, const std::vector<std::string>& names) {
  const std::string nearest = uvtk::nearestName(typed, names);
  return nearest.empty() ? "" : "; did you mean '" + nearest + "'?";
}

bool looksLikeOption(const std::string& argument) {
  // "-3" and "-.5" are negative numbers; "--" ends the options.
  return argument.size() >= 2 && argument[0] == '-' && argument != "--" &&
         !(std::isdigit(static_cast<unsigned char>(argument[1])) || argument[1] == '.');
}

// The message for the first argument that `app`, or a subcommand it ran, could not place: an
// option it does not have, or at the top a command that does not exist; "" when there is none.
// CLI11 reports a missing required option before such an argument, the less useful of the two.
std::string unplacedArgument(const CLI::App& app) {
  for (const std::string& argument : app.remaining(false)) {
    if (!looksLikeOption(argument)) continue;
    const std::string typed = argument.substr(0, argument.find('='));
    std::vector<std::string> names;
    for (const CLI::Option* option : app.get_options()) {
      for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
      for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    }
    // Compared without their dashes: "-quiet" finds "--quiet".
    const auto bare = [](const std::string& name) { return name.substr(std::min(name.find_first_not_of('-'), name.size())); };
    std::vector<std::string> bareNames;
    for (const std::string& name : names) bareNames.push_back(bare(name));
    const std::string nearest = uvtk::nearestName(bare(typed), bareNames);
    std::string hint;
    for (std::size_t i = 0; i < names.size() && !nearest.empty() && hint.empty(); ++i)
      if (bareNames[i] == nearest) hint = "; did you mean '" + names[i] + "'?";
    return "unknown option '" + typed + "'" + hint;
  }
  const std::vector<CLI::App*> ran = app.get_subcommands();
  if (app.get_parent() == nullptr && ran.empty() && !app.remaining(false).empty()) {
    const std::string typed = app.remaining(false).front();
    std::vector<std::string> commands;
    for (const CLI::App* command : app.get_subcommands({})) commands.push_back(command->get_name());
    return "unknown command '" + typed + "'" + didYouMean(typed, commands);
  }
  for (const CLI::App* command : ran)
    if (std::string message = unplacedArgument(*command); !message.empty()) return message;
  return "";
}

// CLI11's "Could not convert: --scale = abc" as uvtk words every refusal: the option, what it
// expects, what it found. Empty for other messages.
std::string conversionMessage(const std::string& what) {
  const std::string prefix = "Could not convert: ";
  const std::size_t equals = what.find(" = ");
  if (what.rfind(prefix, 0) != 0 || equals == std::string::npos) return "";
  const std::string option = what.substr(prefix.size(), equals - prefix.size());
  return option + ": expected a number, found '" + what.substr(equals + 3) + "'";
}

}  // namespace

int main(int argc, char** argv) {
  uvtk::setFreedMemory(uvtk::FreedMemory::GivenBack);  // a command of many meshes keeps it for reuse
  // Never destroyed (held by a static, so not a leak): taking every option and callback apart
  // took 0.15 ms of a small map, at the end of a process whose memory goes anyway.
  static CLI::App* const cli = new CLI::App{"uvtk: texture coordinates for triangle meshes, and proof that they are right"};
  CLI::App& app = *cli;
  app.require_subcommand(1);
  app.set_version_flag("--version", "uvtk " UVTK_VERSION, "Print the version and exit");
  // The command named first, alone; without one (--help, a typo) every command, to list them.
  const auto named = [&](const uvtk::cli::Command& c) { return argc > 1 && std::string(argv[1]) == c.name; };
  const bool one = std::any_of(std::begin(uvtk::cli::kCommands), std::end(uvtk::cli::kCommands), named);
  for (const uvtk::cli::Command& command : uvtk::cli::kCommands)
    if (!one || named(command)) command.add(app);
  // -q everywhere, for the commands that do not bring their own.
  for (CLI::App* command : app.get_subcommands({}))
    if (!command->get_option_no_throw("-q") && !command->get_option_no_throw("--quiet"))
      command->add_flag_callback(
          "-q,--quiet",
          [] {
            uvtk::setQuiet(true);
            uvtk::setProgressEnabled(false);
          },
          "No progress and no summary lines; errors are still printed");
  uvtk::cli::addHelpExamples(app);
  if (argc == 1) {  // no command: what there is to do, rather than "A subcommand is required"
    std::fputs(app.help().c_str(), stderr);
    return 2;
  }
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
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // One line, as every refusal (docs/robustness.md).
    std::string message = unplacedArgument(app);
    if (message.empty()) message = conversionMessage(e.what());
    if (message.empty()) message = e.what();
    std::fprintf(stderr, "uvtk: error: %s\n", message.c_str());
    return 2;
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
