// `tensorglyph help [TOPIC]`: one task's options of `render` (the groups of
// --help), or a command's whole --help; without a topic, the topics.
#include <cctype>
#include <cstdio>
#include <string>
#include <utility>
#include <string_view>

#include "app/commands.h"
#include "app/scale/option_table.h"
#include "app/render_options.h"
#include "app/script_commands.h"
#include "io/core/format_table.h"

namespace tg::app {
namespace {

// "camera", "camera and views", "Camera": the group a topic names.
const OptionGroup* topicGroup(std::string_view topic) {
  std::string t(topic);
  for (char& c : t) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (t == "color") t = "colour";
  for (const OptionGroup& g : kOptionGroups) {
    const std::string_view name = g.name;
    if (t == name || t == name.substr(0, name.find(' '))) return &g;
  }
  return nullptr;
}

std::string topics() {
  std::string s = "topics (the groups of 'tensorglyph render --help'):\n";
  for (const OptionGroup& g : kOptionGroups) s += std::string("  ") + g.name + "\n";
  return s + "formats: the input formats, what each is read as, and whether its module loads here\n" +
         "script: the viewer's script language (view --script; --markdown: as docs/script.md)\n" +
         "or a command: render, view, info, synth, bench; docs/cli.md has them all\n";
}

// One line per row of the format table (io/core/format_table.h), with what its
// module needs on this machine: a missing module is found here, not at the
// first file.
std::string formatsHelp() {
  static const std::pair<unsigned, const char*> kUses[] = {{io::kTensorUse, "input"},
                                                           {io::kScalarUse, "--mask/--underlay"},
                                                           {io::kSurfaceUse, "--mesh"},
                                                           {io::kVolumeMeshUse, "--mesh (outer surface)"},
                                                           {io::kFemUse, "--mesh-from-input"},
                                                           {io::kTractUse, "--tracts"}};
  static const std::pair<unsigned, const char*> kOptions[] = {{io::kLayoutOption, "--layout"},
                                                              {io::kFrameOption, "--frame"},
                                                              {io::kArrayOption, "--array"},
                                                              {io::kConfidenceOption, "--confidence-min"}};
  std::string s = "input formats: extensions; what a file can be given as; the options that apply; its module\n";
  for (const io::InputFormatRow& row : io::inputFormats()) {
    std::string line = std::string("  ") + row.name + ":";
    for (const std::string& e : row.extensions) line += " " + e;
    std::string uses, options;
    for (const auto& [bit, name] : kUses)
      if (row.uses & bit) uses += (uses.empty() ? "" : ", ") + std::string(name);
    for (const auto& [bit, name] : kOptions)
      if (row.options & bit) options += (options.empty() ? "" : ", ") + std::string(name);
    line += "; as " + uses + "; " + (options.empty() ? "no format options" : options);
    const std::string module = row.module;
    if (module.empty()) line += "; read by tensorglyph itself";
    else if (const std::string problem = io::moduleProblem(module); problem.empty())
      line += "; module " + module + " (loads)";
    else line += "; module " + module + " NOT AVAILABLE: " + problem;
    s += line + "\n";
  }
  return s;
}

}  // namespace

int cmdHelp(int argc, const char** argv, int (*command)(const std::string&, int, const char**)) {
  if (argc < 2) {
    std::fputs(topics().c_str(), stdout);
    return 0;
  }
  const std::string topic = argv[1];
  if (topic == "script" && (argc == 2 || (argc == 3 && std::string_view(argv[2]) == "--markdown"))) {
    std::fputs(scriptReference(argc == 3).c_str(), stdout);
    return 0;
  }
  if (argc > 2) throw UsageError("give one topic; " + topics().substr(0, topics().find('\n')));
  if (topic == "formats") {
    std::fputs(formatsHelp().c_str(), stdout);
    return 0;
  }
  if (const OptionGroup* g = topicGroup(topic)) {
    RenderOptions o;
    OptionTable table(kRenderUsage);
    addRenderOptions(table, o);
    std::fputs(groupHelp(table, g->name).c_str(), stdout);
    return 0;
  }
  const char* helpArgs[] = {argv[1], "--help"};
  if (const int code = command(topic, 2, helpArgs); code >= 0) return code;
  throw UsageError("unknown topic \"" + topic + "\"; run 'tensorglyph help' for the topics");
}

}  // namespace tg::app
