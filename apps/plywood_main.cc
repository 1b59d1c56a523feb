// plywood: the command line of the Plywood testbed. `plywood --help` lists the commands,
// `plywood COMMAND --help` their flags with defaults and an example.
// Exit codes: 0 success, 1 a failure during the run, 2 bad input (config, files, usage).

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "apps/command.h"
#include "apps/mesa_threads.h"
#include "apps/owner_umask.h"
#include "apps/stack_limit.h"
#include "apps/standard_streams.h"
#include "render/mesa_driver.h"
#include "sim/config/config_error.h"
#include "sim/runner/out_of_memory.h"

namespace plywood::apps {
namespace {

constexpr const char* kDescription =
    "plywood " PLYWOOD_VERSION
    ": a MuJoCo testbed for mobile-robot perception (simulated P3-DX and Magellan Pro in plywood "
    "rooms, scored against ground truth)";

constexpr const char* kFooter =
    "Exit codes: 0 success, 1 a failure during a run, 2 bad input (config, files, usage).\n"
    "Examples:\n"
    "  plywood run experiments/default.yaml\n"
    "  plywood run --help";

// The innermost command given: `generate` in `plywood worlds generate ...`, else `app` itself.
const CLI::App* Innermost(const CLI::App& app) {
  const CLI::App* at = &app;
  while (!at->get_subcommands().empty()) at = at->get_subcommands().front();
  return at;
}

// Where a parse error happened, for the one line that reports it: "run: ", "worlds generate: "
// or "".
std::string Where(const CLI::App& app) {
  std::string where;
  for (const CLI::App* at = &app; !at->get_subcommands().empty();) {
    at = at->get_subcommands().front();
    where += (where.empty() ? "" : " ") + at->get_name();
  }
  return where.empty() ? "" : where + ": ";
}

// The first word the innermost command did not take that looks like a flag ("" if none).
std::string UnknownOption(const CLI::App& app) {
  for (const std::string& word : WordsNotTaken(*Innermost(app))) {
    if (word.size() > 1 && word.starts_with('-')) return word;
  }
  return "";
}

std::string SeeHelp(const std::string& where) {
  return " (see plywood " + (where.empty() ? "" : where.substr(0, where.size() - 2) + " ") +
         "--help)";
}

// CLI11 would report a stray top-level word or flag as a missing subcommand; name it instead.
void CheckFirstArgument(const std::vector<Command>& commands, const std::string& first) {
  if (first == "-h" || first == "--help" || first == "--version") return;
  if (first.starts_with('-')) throw UsageError("unknown option " + first + SeeHelp(""));
  std::string names;
  for (const Command& command : commands) {
    if (command.cli->get_name() == first) return;
    names += (names.empty() ? "" : ", ") + command.cli->get_name();
  }
  throw UsageError("unknown command '" + first + "'; commands: " + names + SeeHelp(""));
}

// Each command takes only its own flags and positionals: the first stray word is named.
void RejectExtras(const CLI::App& app, const Command& command) {
  const std::vector<std::string> extras = WordsNotTaken(*Innermost(app));
  if (extras.empty() || command.takes_any_arguments) return;
  const std::string where = Where(app);
  if (extras.front().starts_with('-')) {
    throw UsageError(where + "unknown option " + extras.front() + SeeHelp(where));
  }
  throw UsageError(where + "unexpected argument '" + extras.front() + "'" + SeeHelp(where));
}

int Main(int argc, char** argv) {
  CLI::App app(kDescription, "plywood");
  app.set_version_flag("--version", "plywood " PLYWOOD_VERSION);
  app.require_subcommand(1);
  app.get_formatter()->column_width(36);
  app.footer(kFooter);
  const std::vector<Command> commands = {
      AddRunCommand(app),   AddBenchCommand(app), AddReplayCommand(app), AddScoreCommand(app),
      AddSweepCommand(app), AddTrainCommand(app), AddWorldsCommand(app), AddViewCommand(app)};
  // Stray words are named by RejectExtras (a command's subcommands too: `worlds generate`).
  for (const Command& command : commands) {
    command.cli->allow_extras();
    for (CLI::App* sub : command.cli->get_subcommands([](CLI::App*) { return true; })) {
      sub->allow_extras();
    }
  }

  if (argc < 2) {
    std::fputs(app.help().c_str(), stderr);
    return 2;
  }
  if (std::string(argv[1]) == "help") {  // "plywood help" as in earlier versions
    std::fputs(app.help().c_str(), stdout);
    return 0;
  }
  try {
    CheckFirstArgument(commands, argv[1]);
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // A mistyped flag is the likelier culprit than what it leaves missing: `worlds generate room
    // --cuont 5 ...` said "--count is required", never naming --cuont.
    const std::string where = Where(app);
    if (const std::string unknown = UnknownOption(app); !unknown.empty()) {
      throw UsageError(where + "unknown option " + unknown + SeeHelp(where));
    }
    throw UsageError(where + e.what() + SeeHelp(where));
  }
  for (const Command& command : commands) {
    if (!command.cli->parsed()) continue;
    RejectExtras(app, command);
    render::RequireTheReproducibleMesaDriver();
    RequireAStackLimitPlywoodRunsIn();
    RequireAUmaskThatLeavesTheOwnerItsFiles();
    return command.run();
  }
  throw UsageError("no command given" + SeeHelp(""));
}

}  // namespace
}  // namespace plywood::apps

namespace {

// One line whatever the message carries: a flag's value or a file name may hold a line break.
std::string OneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

// `message`, and, when it says a file was not found, why while the current folder is gone (deleted
// since the shell entered it): "runs/e-seed1: No such file or directory" and "../e.yaml: No such
// file or directory" (the file there all along) named the path, not the cause. Not for a line
// that starts with an absolute path: that file (and what it names, resolved beside it) is not
// looked for in the current folder, so its being gone is not why.
std::string WithTheCurrentFolder(const std::string& message) {
  std::error_code gone;
  static_cast<void>(std::filesystem::current_path(gone));
  const bool not_found = message.find("No such file") != std::string::npos ||
                         message.find("no such") != std::string::npos;
  if (!not_found || gone != std::errc::no_such_file_or_directory || message.starts_with('/')) {
    return message;
  }
  return message +
         " (the current folder was deleted, so no relative path can be found in it: cd "
         "to a folder that exists)";
}

// The command's exit code, its error (if any) said on one line.
int RunCommand(int argc, char** argv) {
  try {
    return plywood::apps::Main(argc, argv);
  } catch (const plywood::sim::ConfigError& e) {
    std::fprintf(stderr, "plywood: %s\n", WithTheCurrentFolder(e.what()).c_str());
    return 2;
  } catch (const std::invalid_argument& e) {  // UsageError too
    std::fprintf(stderr, "plywood: %s\n", WithTheCurrentFolder(OneLine(e.what())).c_str());
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    // A name the file system refuses (over PATH_MAX, a link loop) reaching a std::filesystem call
    // without an error_code read "plywood: error: filesystem error: status: File name too long
    // [PATH]", exit 1: the path and the reason, and a bad name is bad input (exit 2).
    const std::error_code code = e.code();
    const std::string path = e.path1().empty() ? "" : e.path1().string() + ": ";
    std::fprintf(stderr, "plywood: %s\n",
                 WithTheCurrentFolder(OneLine(path + code.message())).c_str());
    const bool bad_name =
        code == std::errc::filename_too_long || code == std::errc::too_many_symbolic_link_levels ||
        code == std::errc::not_a_directory || code == std::errc::no_such_file_or_directory;
    return bad_name ? 2 : 1;
  } catch (const std::bad_alloc&) {
    // Read "plywood: error: std::bad_alloc": the limit that caused it is named when one is set.
    std::fprintf(stderr, "plywood: error: out of memory (std::bad_alloc)%s\n",
                 plywood::sim::MemoryLimitNote().c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plywood: error: %s\n", WithTheCurrentFolder(OneLine(e.what())).c_str());
    return 1;
  } catch (...) {  // a plug-in's algorithm may throw anything; uncaught, it aborted plywood
    std::fputs(
        "plywood: error: an exception that is not a std::exception ended the run (thrown by a "
        "plug-in's algorithm?)\n",
        stderr);
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f) would kill plywood with SIGXFSZ, without a word, mid-write;
  // ignored, the write fails with EFBIG and the writer names the file. Children (sweep runs,
  // ffmpeg) inherit it.
  std::signal(SIGXFSZ, SIG_IGN);
  plywood::apps::PrepareStandardStreams();
  plywood::apps::KeepMesaFromWaitingOnThreadsItCannotStart();
  return plywood::apps::FinishStandardStreams(RunCommand(argc, argv));
}
