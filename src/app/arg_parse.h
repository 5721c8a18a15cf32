#pragma once
// OpenImageIO's ArgParse as the subcommands use it: errors become UsageError,
// and --help (which ArgParse prints itself) ends the command with status 0
// before anything is checked or loaded.
#include <OpenImageIO/argparse.h>

#include "app/cli_values.h"

namespace tg::app {

inline void parseArgs(OIIO::ArgParse& ap, int argc, const char** argv) {
  if (ap.parse_args(argc, argv) < 0) throw UsageError(ap.geterror());
  if (ap.aborted()) throw HelpShown{};
}

}  // namespace tg::app
