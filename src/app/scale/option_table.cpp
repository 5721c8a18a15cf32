#include "app/scale/option_table.h"

#include <algorithm>
#include <stdexcept>

#include "app/scale/cli_values.h"

namespace tg::app {

const OptionGroup kOptionGroups[7] = {
    {"input and selection", "tensorglyph render dti.nii.gz --mask brain.nii.gz --slice z:40 --stride 2 -o axial.png"},
    {"glyphs", "tensorglyph render --glyph superquadric --gamma 3 --scale-mode spacing --scale 0.8 -o sq.png"},
    {"colour", "tensorglyph render stress.vtu --color sign --legend --units MPa -o sign.png"},
    {"camera and views", "tensorglyph render --eye 10 -20 30 --look-at 0 0 0 --fov 20 -o view.png"},
    {"context", "tensorglyph render dti.nii.gz --underlay fa --plane z:40 --mesh brain.stl -o context.png"},
    {"depth cues", "tensorglyph render field.nrrd --ao --outlines --shadows -o cues.png"},
    {"output", "tensorglyph render field.nrrd --size 1920 1080 -o frame.exr --verbose"},
};

std::vector<std::string> choiceWords(std::string_view list) {
  std::vector<std::string> words;
  std::string w;
  const auto flush = [&] {
    if (!w.empty()) words.push_back(w);
    w.clear();
  };
  for (std::size_t k = 0; k < list.size(); ++k) {
    if (list.substr(k, 4) == " or ") {
      flush();
      k += 3;
    } else if (list[k] == ',' || list[k] == ' ') {
      flush();
    } else {
      w += list[k];
    }
  }
  flush();
  return words;
}

std::string OptionTable::Option::keyword() const {
  if (positional) return flag;
  std::string k = flag.substr(flag.find_first_not_of('-'));
  for (char& c : k)
    if (c == '-') c = '_';
  return k;
}

std::string OptionTable::Option::description() const {
  std::string note = numbers ? (list ? "each " : "") + numbers->text() : "";
  if (!defaultText.empty()) note += (note.empty() ? "" : "; ") + std::string("default ") + defaultText;
  if (note.empty()) return helpText;
  return helpText.empty() ? "(" + note + ")" : helpText + " [" + note + "]";
}

OptionTable::Option& OptionTable::arg(std::string_view spec) {
  Option o;
  std::size_t at = 0;
  while (at < spec.size()) {
    const std::size_t end = std::min(spec.find(' ', at), spec.size());
    if (end > at) {
      const std::string word(spec.substr(at, end - at));
      if (!o.flag.empty()) o.metavars.push_back(word);
      else if (const std::size_t comma = word.find(','); comma != std::string::npos && word[0] == '-') {
        o.shortFlag = word.substr(0, comma);
        o.flag = word.substr(comma + 1);
      } else o.flag = word;
    }
    at = end + 1;
  }
  if (o.flag.empty()) throw std::logic_error("OptionTable::arg: empty spec");
  o.positional = o.flag[0] != '-';
  o.reload = reloadDefault_ || o.positional;
  o.group = groupDefault_;
  if (find(o.flag)) throw std::logic_error("OptionTable::arg: " + o.flag + " defined twice");
  options_.push_back(std::move(o));
  return options_.back();
}

const OptionTable::Option* OptionTable::find(std::string_view name) const {
  for (const Option& o : options_)
    if (o.flag == name || (!o.shortFlag.empty() && o.shortFlag == name) || (!o.positional && o.keyword() == name))
      return &o;
  return nullptr;
}

void OptionTable::apply(const Option& opt, std::span<const std::string> values) {
  if (!opt.positional && values.size() != opt.arity()) {
    std::string want = std::to_string(opt.arity()) + (opt.arity() == 1 ? " value" : " values");
    if (opt.arity() == 0) want = "no value";
    throw UsageError(opt.flag + " takes " + want + " (" + std::to_string(values.size()) + " given)");
  }
  // An empty value is never a choice, a file or a number: taken as "not
  // given" it would draw silently without the mask, axes or input asked for
  // (`--mask "$UNSET"`). Free text (TEXT) may be empty.
  for (std::size_t k = 0; k < values.size(); ++k) {
    const std::string& name = opt.metavars.empty() ? std::string() : opt.metavars[std::min(k, opt.metavars.size() - 1)];
    if (values[k].empty() && name != "TEXT")
      throw UsageError(opt.flag + ": an empty value" +
                       (name.empty() || opt.positional ? std::string() : "; give " + name));
  }
  if (opt.numbers)
    for (const std::string& v : values) {
      if (!opt.list) {
        checkedNumber(opt.flag, v, *opt.numbers);
        continue;
      }
      for (std::size_t start = 0;;) {
        const std::size_t comma = v.find(',', start);
        checkedNumber(opt.flag, std::string_view(v).substr(start, comma - start), *opt.numbers);
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
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
