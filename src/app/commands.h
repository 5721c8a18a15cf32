#pragma once
// The subcommands. Each returns the process exit code and throws
// UsageError, io::InputError or std::runtime_error for main to report.

#include <string>

namespace tg::app {

int cmdRender(int argc, const char** argv);
int cmdInfo(int argc, const char** argv);
int cmdSynth(int argc, const char** argv);
int cmdBench(int argc, const char** argv);
int cmdView(int argc, const char** argv);
// `help [TOPIC]`; `command` runs a subcommand by name, -1 for no such command.
int cmdHelp(int argc, const char** argv, int (*command)(const std::string&, int, const char**));

}  // namespace tg::app
