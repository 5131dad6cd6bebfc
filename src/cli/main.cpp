// SPDX-License-Identifier: BSD-3-Clause
// The `restitution` program: parses the command line, runs one subcommand, maps errors to exit statuses
// (2: bad usage or input, 1: numerical failure, 3: an output that cannot be written) with one line on stderr.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>

#include "cli/common/commands.hpp"
#include "cli/common/help_format.hpp"
#include "cli/common/io_error.hpp"
#include "cli/common/parse_errors.hpp"
#include "cli/common/stop_signals.hpp"
#include "restitution/errors.hpp"
#include "restitution/restitution.hpp"

namespace {

int run(int argc, char** argv) {
  using namespace restitution;
  CLI::App app{"restitution: coefficient of normal restitution of colliding viscoelastic spheres",
               "restitution"};
  // The version and commit of the library the program runs (docs/release.md), then its SUNDIALS build.
  app.set_version_flag("--version", std::string("restitution ") + library_version().version + "\ncommit " +
                                        library_version().commit + "\nSUNDIALS " +
                                        sundials_build_description());
  app.require_subcommand(1);
  app.formatter(std::make_shared<cli::WrappingHelpFormatter>());  // before the subcommands: they inherit it
  app.footer(
      "Exit status: 0 done, 1 numerical failure, 2 bad usage or input, 3 I/O failure (an output file or\n"
      "folder that cannot be created or written).");
  cli::Action chosen;
  cli::add_all_commands(app, chosen);
  cli::check_number_texts(app);

  std::string known;
  bool is_known = false;
  for (const CLI::App* sub : app.get_subcommands({})) {
    known += (known.empty() ? "" : ", ") + sub->get_name();
    is_known = is_known || (argc > 1 && sub->get_name() == argv[1]);
  }
  if (argc > 1 && argv[1][0] != '-' && !is_known) {
    std::fprintf(stderr, "restitution: error: unknown subcommand '%s' (known: %s)\n",
                 cli::one_line(argv[1]).c_str(), known.c_str());
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    std::fputs(app.help("", CLI::AppFormatMode::All).c_str(), stdout);
    return 0;
  } catch (const CLI::CallForVersion& e) {
    std::printf("%s\n", e.what());
    return 0;
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "restitution: error: %s\n", cli::describe_parse_error(app, e).c_str());
    return 2;
  }

  try {
    return chosen ? chosen() : 2;
  } catch (const cli::Interrupted& e) {
    std::fprintf(stderr, "restitution: %s: stopped, nothing half-written\n", e.what());
    return 128 + e.signal_number();
  } catch (const IoError& e) {  // cli::IoError is the library's IoError
    std::fprintf(stderr, "restitution: I/O error: %s\n", cli::one_line(e.what()).c_str());
    return 3;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the file system refuses (too long, a file where a folder must be): the output is not writable,
    // exit 3 like every other output failure (docs/cli.md), naming the path and the system's reason.
    std::fprintf(stderr, "restitution: I/O error: cannot write %s: %s\n", e.path1().string().c_str(),
                 e.code().message().c_str());
    return 3;
  } catch (const InvalidInput& e) {
    std::fprintf(stderr, "restitution: error: %s\n", cli::one_line(e.what()).c_str());
    return 2;
  } catch (const NumericalFailure& e) {
    std::fprintf(stderr, "restitution: numerical failure: %s\n", cli::one_line(e.what()).c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "restitution: failure: %s\n", cli::one_line(e.what()).c_str());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const int status = run(argc, argv);
    restitution::cli::flush_standard_output();  // a result (or help) that never reached stdout is no success
    return status;
  } catch (const restitution::IoError& e) {
    std::fprintf(stderr, "restitution: I/O error: %s\n", restitution::cli::one_line(e.what()).c_str());
    return 3;
  } catch (...) {  // the last line of defence: never an abort or a stack trace
    std::fputs("restitution: failure: unexpected error\n", stderr);
    return 1;
  }
}
