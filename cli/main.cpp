// sinsim — strapdown INS simulator and inertial-sensor error-model lab.
// Exit codes: 0 success, 1 bad input or failed run (message on stderr), 2 bad command line,
// 130 interrupted (Ctrl-C).
#include <csignal>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "cli/terminal.hpp"
#include "common/error.hpp"
#include "common/progress.hpp"

int main(int argc, char** argv) {
  // Beyond a file size limit (ulimit -f) a write fails with EFBIG and is reported with the file's
  // name, instead of SIGXFSZ killing the process without a word.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"sinsim: strapdown INS simulator and inertial-sensor error-model lab"};
  app.require_subcommand(0, 1);
  sinsim::cli::Action action;
  // Subcommand registrations go here.
  sinsim::cli::addAnalyzeCommand(app, action);
  sinsim::cli::addDiagnoseCommand(app, action);
  sinsim::cli::addFitCommand(app, action);
  sinsim::cli::addRunCommand(app, action);
  sinsim::cli::addMcCommand(app, action);
  sinsim::cli::addSynthCommand(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (!action) {
    std::cout << app.help();
    return 0;
  }
  const std::string command = app.get_subcommands().front()->get_name();
  try {
    sinsim::cli::LongWork work(command);
    return action();
  } catch (const sinsim::Interrupted&) {
    // Every writer is atomic and was unwound: nothing half-written is left behind.
    std::cerr << sinsim::cli::interruptedMessage(command) << "no output was written\n";
    return 130;
  } catch (const sinsim::Error& e) {
    std::cerr << "sinsim: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "sinsim: internal error: " << e.what() << "\n";
    return 1;
  }
}
