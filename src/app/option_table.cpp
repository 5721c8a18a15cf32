#include "app/option_table.h"

#include <stdexcept>

#include "app/cli_values.h"

namespace tg::app {

std::string OptionTable::Option::keyword() const {
  if (positional) return flag;
  std::string k = flag.substr(flag.find_first_not_of('-'));
  for (char& c : k)
    if (c == '-') c = '_';
  return k;
}

OptionTable::Option& OptionTable::arg(std::string_view spec) {
  Option o;
  std::size_t at = 0;
  while (at < spec.size()) {
    const std::size_t end = std::min(spec.find(' ', at), spec.size());
    if (end > at) {
      const std::string word(spec.substr(at, end - at));
      if (o.flag.empty()) o.flag = word;
      else o.metavars.push_back(word);
    }
    at = end + 1;
  }
  if (o.flag.empty()) throw std::logic_error("OptionTable::arg: empty spec");
  o.positional = o.flag[0] != '-';
  o.reload = reloadDefault_ || o.positional;
  if (find(o.flag)) throw std::logic_error("OptionTable::arg: " + o.flag + " defined twice");
  options_.push_back(std::move(o));
  return options_.back();
}

const OptionTable::Option* OptionTable::find(std::string_view name) const {
  for (const Option& o : options_)
    if (o.flag == name || (!o.positional && o.keyword() == name)) return &o;
  return nullptr;
}

void OptionTable::apply(const Option& opt, std::span<const std::string> values) {
  if (!opt.positional && values.size() != opt.arity()) {
    std::string want = std::to_string(opt.arity()) + (opt.arity() == 1 ? " value" : " values");
    if (opt.arity() == 0) want = "no value";
    throw UsageError(opt.flag + " takes " + want + " (" + std::to_string(values.size()) + " given)");
  }
  std::vector<const char*> argv{opt.flag.c_str()};
  for (const std::string& v : values) argv.push_back(v.c_str());
  if (opt.act) opt.act(OptionArgs(argv));
}

void addInputArg(OptionTable& table, std::string& input) {
  table.arg("INPUT").commandLineOnly().help("the input file; none: the built-in scene (where the command has one)").action([&input](OptionArgs a) {
    if (!input.empty()) throw UsageError("more than one INPUT: \"" + input + "\" and \"" + a[1] + "\"");
    input = a[1];
  });
}

}  // namespace tg::app
