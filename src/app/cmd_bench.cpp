#include <cstdio>
#include <cstring>
#include <string>

#include "app/bench.h"
#include "app/cli_common.h"
#include "app/commands.h"

namespace tg::app {

int cmdBench(int argc, const char** argv) {
  constexpr const char* kUsage = "usage: tensorglyph bench accuracy|scale ... -o CSV [options]; add --help for its options";
  if (argc >= 2 && (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h"))) {
    std::puts(kUsage);
    return 0;
  }
  if (argc < 2) throw UsageError(kUsage);
  const std::string which = argv[1];
  if (which == "accuracy") return benchAccuracy(argc - 1, argv + 1);
  if (which == "scale") return benchScale(argc - 1, argv + 1);
  throw UsageError("unknown benchmark \"" + which + "\"; choose accuracy or scale");
}

}  // namespace tg::app
