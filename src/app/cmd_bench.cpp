#include <cstring>
#include <string>

#include "app/bench.h"
#include "app/cli_common.h"
#include "app/commands.h"

namespace tg::app {

int cmdBench(int argc, const char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h"))
    throw UsageError("usage: tensorglyph bench accuracy|scale ... -o CSV [options]; add --help for its options");
  const std::string which = argv[1];
  if (which == "accuracy") return benchAccuracy(argc - 1, argv + 1);
  if (which == "scale") return benchScale(argc - 1, argv + 1);
  throw UsageError("unknown benchmark \"" + which + "\"; choose accuracy or scale");
}

}  // namespace tg::app
