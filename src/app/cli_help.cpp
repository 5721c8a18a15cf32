// `tensorglyph help [TOPIC]`: one task's options of `render` (the groups of
// --help), or a command's whole --help; without a topic, the topics.
#include <cctype>
#include <cstdio>
#include <string>
#include <string_view>

#include "app/commands.h"
#include "app/option_table.h"
#include "app/render_options.h"

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
  return s + "or a command: render, view, info, synth, bench; docs/cli.md has them all\n";
}

}  // namespace

int cmdHelp(int argc, const char** argv, int (*command)(const std::string&, int, const char**)) {
  if (argc < 2) {
    std::fputs(topics().c_str(), stdout);
    return 0;
  }
  if (argc > 2) throw UsageError("give one topic; " + topics().substr(0, topics().find('\n')));
  const std::string topic = argv[1];
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
