// tensorglyph: exact GPU tensor glyphs. Dispatches to a subcommand.
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "app/cli_common.h"
#include "app/commands.h"
#include "io/field/tensor_field.h"

namespace {

constexpr const char* kUsage =
    "usage: tensorglyph <command> [options]\n"
    "  render [INPUT] -o OUT   render glyphs to an image (no INPUT: the built-in scene)\n"
    "  view [INPUT]            interactive window (GLFW, Dear ImGui); --script FILE for demos and tests\n"
    "  info INPUT              grid, counts, eigenvalue ranges, skipped tensors\n"
    "  synth KIND -o OUT       write a synthetic field (helix, boussinesq, extremes, random, ...)\n"
    "  bench accuracy [INPUT]  superquadric march: error against the reference vs frame time\n"
    "  bench scale             frame time against glyph count, ray casting vs a tessellated mesh\n"
    "  help [TOPIC]            one task's options (input, glyphs, colour, camera, context, depth, output),\n"
    "                          formats, or script (the viewer's script language)\n"
    "Run 'tensorglyph <command> --help' for a command's options; docs/cli.md has them all.\n";

// The subcommand `cmd`, or -1 where there is none.
int command(const std::string& cmd, int argc, const char** argv) {
  using namespace tg::app;
  if (cmd == "render") return cmdRender(argc, argv);
  if (cmd == "view") return cmdView(argc, argv);
  if (cmd == "info") return cmdInfo(argc, argv);
  if (cmd == "synth") return cmdSynth(argc, argv);
  if (cmd == "bench") return cmdBench(argc, argv);
  if (cmd == "help") return cmdHelp(argc, argv, command);
  return -1;
}

// One line on stderr, whatever the message quotes (tg::app::printable).
void report(const std::string& cmd, const std::exception& e) {
  std::fprintf(stderr, "tensorglyph %s: %s\n", cmd.c_str(), tg::app::printable(e.what()).c_str());
}

}  // namespace

int main(int argc, const char** argv) {
  // Past `ulimit -f` a write fails with EFBIG, which each writer reports with
  // the file's name, instead of the process dying with a partial file.
  std::signal(SIGXFSZ, SIG_IGN);
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const std::string cmd = argv[1];
  try {
    if (const int code = command(cmd, argc - 1, argv + 1); code >= 0) return code;
    std::fprintf(stderr, "tensorglyph: unknown command \"%s\"; run 'tensorglyph --help'\n", tg::app::printable(cmd).c_str());
    return 2;
  } catch (const tg::app::HelpShown&) {
    return 0;
  } catch (const tg::app::UsageError& e) {
    report(cmd, e);
    return 2;
  } catch (const tg::io::InputError& e) {
    report(cmd, e);
    return 1;
  } catch (const std::exception& e) {
    report(cmd, e);
    return 1;
  }
}
