#pragma once
// The subcommands. Each returns the process exit code and throws
// UsageError, io::InputError or std::runtime_error for main to report.

namespace tg::app {

int cmdRender(int argc, const char** argv);
int cmdInfo(int argc, const char** argv);
int cmdSynth(int argc, const char** argv);
int cmdBench(int argc, const char** argv);
int cmdView(int argc, const char** argv);

}  // namespace tg::app
