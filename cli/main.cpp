// sinsim — strapdown INS simulator and inertial-sensor error-model lab.
// Exit codes: 0 success, 1 bad input or failed run (message on stderr), 2 bad command line,
// 130 interrupted (Ctrl-C), 143 stopped by SIGTERM (the same clean stop).
#include <algorithm>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "cli/terminal.hpp"
#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/progress.hpp"
#include "common/read_file.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

int main(int argc, char** argv) {
#if defined(__GLIBC__)
  // A command allocates and frees record-sized buffers (channels, FFT work, Allan sums) many times.
  // glibc serves each beyond its dynamic threshold from a fresh mmap, whose pages fault in and are
  // zeroed again at every use: 38 % of a 2-h 1 kHz 6-channel fit's samples, 8 s of system time.
  // Heap them (up to 1 GiB; a worker thread's arena still maps those beyond 64 MiB) and keep freed
  // memory for the next: that fit 18-20 -> 11-14 s, `analyze` of it 12-15 -> 6-7 s, peak memory
  // +11-14 % (docs/benchmarks.md, "Allocator").
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, INT_MAX);
#endif
  // Beyond a file size limit (ulimit -f) a write fails with EFBIG and is reported with the file's
  // name, instead of SIGXFSZ killing the process without a word.
  std::signal(SIGXFSZ, SIG_IGN);
  // One command per process: an output never replaces a file the command read.
  sinsim::trackInputFiles();
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
  // An empty argument ("" from an unset shell variable) would read as 0 or as "not given" (CLI11
  // converts "" to a default): `--seed ""` ran with seed 0, `run ""` the default scenario.
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    const bool emptyValue = arg.empty() || (arg.rfind("--", 0) == 0 && arg.back() == '=');
    if (!emptyValue) continue;
    const std::string option = !arg.empty() ? arg.substr(0, arg.size() - 1)
                               : k > 1 && argv[k - 1][0] == '-' ? std::string(argv[k - 1])
                                                                : "argument " + std::to_string(k);
    std::cerr << "sinsim: error: " << option << ": an empty value on the command line\n";
    return 2;
  }
  // CLI11 reads an unsigned integer beyond 2^64 - 1 as 2^64 - 1 (and "-5" as 2^64 - 5): a seed, a
  // run index or a count must be the number given (`mc --runs -5` said "18446744073709551611 is
  // above the limit"). Both `--opt V` and `--opt=V`.
  static const char* const kUnsigned[] = {"--seed", "--run", "--runs", "--realisations",
                                          "--nav-runs", "--stop-after", "--threads"};
  for (int k = 1; k < argc; ++k) {
    std::string opt = argv[k], v;
    const std::size_t eq = opt.find('=');
    if (opt.rfind("--", 0) == 0 && eq != std::string::npos) {
      v = opt.substr(eq + 1);
      opt = opt.substr(0, eq);
    } else if (k + 1 < argc) {
      v = argv[k + 1];
    } else {
      continue;
    }
    if (std::find_if(std::begin(kUnsigned), std::end(kUnsigned),
                     [&](const char* o) { return opt == o; }) == std::end(kUnsigned))
      continue;
    errno = 0;
    char* end = nullptr;
    const unsigned long long x = std::strtoull(v.c_str(), &end, 10);
    (void)x;
    if (v.find_first_not_of("0123456789") != std::string::npos || errno == ERANGE) {
      // No bounds here: each option's own range (--runs from 1) is checked where it is used.
      std::cerr << "sinsim: error: " << opt << ": expected a whole number (digits only), got \""
                << v.substr(0, 40) << "\"\n";
      return 2;
    }
  }
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
    return sinsim::cli::interruptedExitCode();
  } catch (const sinsim::OptionError& e) {  // an option's value: a bad command line, as CLI11's
    std::cerr << "sinsim: error: " << sinsim::limits::messageText(e.what()) << "\n";
    return 2;
  } catch (const sinsim::Error& e) {
    std::cerr << "sinsim: error: " << sinsim::limits::messageText(e.text()) << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "sinsim: internal error: " << sinsim::limits::messageText(e.what()) << "\n";
    return 1;
  }
}
