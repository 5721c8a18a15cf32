#pragma once
// One definition of a command's options, read by two front ends: the command
// line (app/scale/option_cli.cpp, through CLI11) and the Python module's keyword
// arguments (python/), so that names, arity, checks and help cannot drift.
// An option's action receives what ArgParse-style parsers pass: the flag
// itself, then exactly as many values as the option names.
#include <deque>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/scale/option_ranges.h"

namespace tg::app {

using OptionArgs = std::span<const char* const>;  // [0] the flag, then its values

// The names of a list as messages write it: "a, b or c" -> {a, b, c}.
std::vector<std::string> choiceWords(std::string_view list);

class OptionTable {
 public:
  struct Option {
    std::string flag;                   // "--size", "-o"; for the positional, its name ("INPUT")
    std::string shortFlag;              // "-q" for "-q,--quiet"; usually none
    std::vector<std::string> metavars;  // the values' names: {"W", "H"}; empty for a switch
    std::string helpText;
    std::function<void(OptionArgs)> act;
    bool isHidden = false;    // not in --help, not a Python keyword
    bool positional = false;  // the command's INPUT
    bool cliOnly = false;     // no Python keyword (-o, --repeat: the module has its own ways)
    // Changing it means loading or uploading again (the input, its selection,
    // the context); every other option changes only a frame's parameters.
    bool reload = false;
    // Given more than once on a command line: each occurrence adds one
    // (--plane, --mesh, --pick). Any other option with values is refused
    // twice, rather than the last silently winning.
    bool repeatable = false;
    // Every value is a number within this range (a comma-separated list of
    // them where `list`): checked before the action runs, for every surface.
    std::optional<NumberRange> numbers;
    bool list = false;
    std::string group;  // the --help section (kOptionGroups); "" for a command's own
    // The values the option stands at when not given, as it takes them
    // ("1.5", "0 0 0 1", "opaque"), read from the options' own structs
    // where the table is built; "" where the default is not one value (it
    // follows the data or another option: the help text says how).
    std::string defaultText;
    // The names its one value is one of ("ellipsoid", "superquadric", ...),
    // where it takes a name from a fixed list: the Python stubs' Literal.
    // The action still refuses another, in its own words.
    std::vector<std::string> choices;

    Option& help(std::string h) {
      helpText = std::move(h);
      return *this;
    }
    Option& action(std::function<void(OptionArgs)> f) {
      act = std::move(f);
      return *this;
    }
    Option& hidden() {
      isHidden = true;
      return *this;
    }
    Option& commandLineOnly() {
      cliOnly = true;
      return *this;
    }
    Option& reloads() {
      reload = true;
      return *this;
    }
    Option& repeats() {
      repeatable = true;
      return *this;
    }
    Option& range(const NumberRange& r) {
      numbers = r;
      return *this;
    }
    Option& rangeList(const NumberRange& r) {
      numbers = r;
      list = true;
      return *this;
    }
    Option& byDefault(std::string valueText) {
      defaultText = std::move(valueText);
      return *this;
    }
    // The list as messages write it: "a, b or c" (the one home of the names).
    Option& oneOf(std::string_view names) {
      choices = choiceWords(names);
      return *this;
    }
    Option& inGroup(std::string g) {
      group = std::move(g);
      return *this;
    }
    std::size_t arity() const { return metavars.size(); }
    // "fa_min" for "--fa-min": the Python keyword.
    std::string keyword() const;
    // The help text with the range and default the option declares, as
    // --help, docs/cli.md and the Python docstrings show it:
    // "superquadric sharpness [0..10000; default 3]".
    std::string description() const;
  };

  explicit OptionTable(std::string usage = {}) : usage_(std::move(usage)) {}
  // "--size W H": the flag, then the values' names; "-q,--quiet": a short
  // flag too. A spec without a leading '-' is the positional INPUT. Throws
  // std::logic_error for a repeated flag.
  Option& arg(std::string_view spec);
  // Options added from now on reload (Option::reloads) or not: a whole flag
  // group (the field's selection, meshes, slice planes) is marked at once.
  void setReloadsDefault(bool r) { reloadDefault_ = r; }
  bool reloadsDefault() const { return reloadDefault_; }
  // Options added from now on belong to this --help group (Option::group).
  void setGroup(std::string g) { groupDefault_ = std::move(g); }
  const std::string& groupDefault() const { return groupDefault_; }
  void setUsage(std::string usage) { usage_ = std::move(usage); }
  const std::string& usage() const { return usage_; }
  // A deque: references handed out by arg() stay valid as options are added.
  const std::deque<Option>& options() const { return options_; }
  const Option* find(std::string_view flagOrKeyword) const;
  // Runs `opt`'s action on `values`, as if the command line had held them.
  // UsageError (naming the flag) when their number is not the option's, or
  // a value is not a number within its range.
  static void apply(const Option& opt, std::span<const std::string> values);

 private:
  std::string usage_;
  bool reloadDefault_ = false;
  std::string groupDefault_;
  std::deque<Option> options_;
};

// The --help sections, in order, each with an example; an option's group
// names one of them (or is "" for a command's own options).
struct OptionGroup {
  const char* name;
  const char* example;
};
extern const OptionGroup kOptionGroups[7];

// Parses argv[1..] (argv[0] is the command's name) into the table's actions,
// in command-line order. UsageError for unknown flags, a wrong number of
// values, or an option that is not repeatable given twice; after printing
// --help (or, for --help-markdown, the reference docs/cli.md holds) on
// stdout, throws HelpShown.
void parseCommandLine(const OptionTable& table, int argc, const char** argv);

// The reference of `table`'s options in Markdown, grouped as --help is:
// flag, values, range and help text of each, under `title`.
std::string markdownReference(const OptionTable& table, const std::string& title);
// The --help text of one group's options (its example last); "" when the
// table has none of that group.
std::string groupHelp(const OptionTable& table, const std::string& group);

// The name of `names` nearest `word` within two edits (the first of equals),
// or "": the "did you mean" of the CLI's unknown flags and Python's keywords.
std::string nearestName(std::string_view word, std::span<const std::string> names);

// The hidden-from-Python positional INPUT; a second one is a usage error.
void addInputArg(OptionTable& table, std::string& input);

}  // namespace tg::app
