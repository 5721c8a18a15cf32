#pragma once
// One definition of a command's options, read by two front ends: the command
// line (app/option_cli.cpp, through CLI11) and the Python module's keyword
// arguments (python/), so that names, arity, checks and help cannot drift.
// An option's action receives what ArgParse-style parsers pass: the flag
// itself, then exactly as many values as the option names.
#include <deque>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tg::app {

using OptionArgs = std::span<const char* const>;  // [0] the flag, then its values

class OptionTable {
 public:
  struct Option {
    std::string flag;                   // "--size", "-o"; for the positional, its name ("INPUT")
    std::vector<std::string> metavars;  // the values' names: {"W", "H"}; empty for a switch
    std::string helpText;
    std::function<void(OptionArgs)> act;
    bool isHidden = false;    // not in --help, not a Python keyword
    bool positional = false;  // the command's INPUT
    bool cliOnly = false;     // no Python keyword (-o, --repeat: the module has its own ways)
    // Changing it means loading or uploading again (the input, its selection,
    // the context); every other option changes only a frame's parameters.
    bool reload = false;

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
    std::size_t arity() const { return metavars.size(); }
    // "fa_min" for "--fa-min": the Python keyword.
    std::string keyword() const;
  };

  explicit OptionTable(std::string usage = {}) : usage_(std::move(usage)) {}
  // "--size W H": the flag, then the values' names. A spec without a leading
  // '-' is the positional INPUT. Throws std::logic_error for a repeated flag.
  Option& arg(std::string_view spec);
  // Options added from now on reload (Option::reloads) or not: a whole flag
  // group (the field's selection, meshes, slice planes) is marked at once.
  void setReloadsDefault(bool r) { reloadDefault_ = r; }
  bool reloadsDefault() const { return reloadDefault_; }
  void setUsage(std::string usage) { usage_ = std::move(usage); }
  const std::string& usage() const { return usage_; }
  // A deque: references handed out by arg() stay valid as options are added.
  const std::deque<Option>& options() const { return options_; }
  const Option* find(std::string_view flagOrKeyword) const;
  // Runs `opt`'s action on `values`, as if the command line had held them.
  // UsageError (naming the flag) when their number is not the option's.
  static void apply(const Option& opt, std::span<const std::string> values);

 private:
  std::string usage_;
  bool reloadDefault_ = false;
  std::deque<Option> options_;
};

// Parses argv[1..] (argv[0] is the command's name) into the table's actions,
// in command-line order. UsageError for unknown flags or a wrong number of
// values; after printing --help on stdout, throws HelpShown.
void parseCommandLine(const OptionTable& table, int argc, const char** argv);

// The hidden-from-Python positional INPUT; a second one is a usage error.
void addInputArg(OptionTable& table, std::string& input);

}  // namespace tg::app
