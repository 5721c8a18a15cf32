#pragma once
// OpenImageIO's ArgParse as the subcommands use it: errors become UsageError,
// and --help (which ArgParse prints itself) ends the command with status 0
// before anything is checked or loaded.
#include <OpenImageIO/argparse.h>

#include <string>

#include "app/cli_values.h"

namespace tg::app {

// The hidden positional INPUT; a second one is a usage error.
inline void addInputArg(OIIO::ArgParse& ap, std::string& input) {
  ap.arg("filename").hidden().action([&input](auto&, OIIO::cspan<const char*> a) {
    if (!input.empty()) throw UsageError("more than one INPUT: \"" + input + "\" and \"" + a[0] + "\"");
    input = a[0];
  });
}

inline void parseArgs(OIIO::ArgParse& ap, int argc, const char** argv) {
  if (ap.parse_args(argc, argv) < 0) throw UsageError(ap.geterror());
  if (ap.aborted()) throw HelpShown{};
}

}  // namespace tg::app
