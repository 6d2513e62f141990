// Each subcommand lives in its own cmd_<name>.cpp and registers itself on the app.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace sinsim::cli {

/// The action a subcommand runs after parsing; returns the process exit code.
using Action = std::function<int()>;

// One line per subcommand (add yours here and in main.cpp).
void addAnalyzeCommand(CLI::App& app, Action& action);
void addDiagnoseCommand(CLI::App& app, Action& action);
void addFitCommand(CLI::App& app, Action& action);
void addRunCommand(CLI::App& app, Action& action);
void addMcCommand(CLI::App& app, Action& action);
void addSynthCommand(CLI::App& app, Action& action);

}  // namespace sinsim::cli
