#pragma once
// The viewer's script language (`tensorglyph view --script`) as one table:
// each command's arguments, their count and what it does. The parser holds
// steps to its counts (app/view_script.h); `tensorglyph help script` and
// docs/script.md (generated at build time) print it.
#include <span>
#include <string>

namespace tg::app {

struct ScriptCommand {
  std::string verb;
  std::string args;  // the forms of its arguments, "" for none
  int minArgs, maxArgs;
  std::string help;  // the choices named where render's option names them
};

std::span<const ScriptCommand> scriptCommands();
// The row for `verb`, or null.
const ScriptCommand* scriptCommand(const std::string& verb);

// The language's reference: plain text for `help script`, or Markdown for docs/script.md.
std::string scriptReference(bool markdown);

}  // namespace tg::app
