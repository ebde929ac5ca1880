#include "harness/cli/args.hpp"
#include "harness/cli/commands.hpp"

#include <exception>
#include <filesystem>
#include <ostream>

namespace tritri::cli {

const char* const kExitStatusHelp =
    "Exit status: 0 ok; 1 findings (e.g. new failures against a baseline); 2 bad arguments or\n"
    "input (the message names the file, line and problem); 3 an internal error, a bug in tritri\n"
    "(the message says so, with the command line).\n";

namespace {

int internal_error(const Command& command, int argc, char** argv, const char* what, std::ostream& err) {
  err << "tritri " << command.name << ": internal error: " << what
      << " — this is a bug in tritri, please report it\n  while running: tritri " << command.name;
  for (int i = 0; i < argc; ++i) err << ' ' << argv[i];
  err << '\n';
  return kInternal;
}

}  // namespace

int run_command(const Command& command, int argc, char** argv, std::ostream& err) {
  try {
    return command.run(argc, argv);
  } catch (const UsageError& e) {
    err << "tritri " << command.name << ": " << e.what() << "\n(see 'tritri " << command.name << " --help')\n";
    return kUsage;
  } catch (const InputError& e) {
    err << "tritri " << command.name << ": " << e.what() << '\n';
    return kUsage;
  } catch (const std::filesystem::filesystem_error& e) {
    // A directory the user named (--out DIR) that cannot be made: it names the path.
    err << "tritri " << command.name << ": " << e.what() << '\n';
    return kUsage;
  } catch (const std::exception& e) {
    return internal_error(command, argc, argv, e.what(), err);
  } catch (...) {
    return internal_error(command, argc, argv, "an exception that is not a std::exception", err);
  }
}

}  // namespace tritri::cli
