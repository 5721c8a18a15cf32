// The command line front end of OptionTable: CLI11 does the parsing and the
// --help text; each option's values reach its action as they are met, in
// command-line order (trigger_on_parse), as the table promises.
#include <algorithm>
#include <cctype>
#include <climits>
#include <iterator>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/scale/cli_values.h"
#include "app/scale/option_table.h"

namespace tg::app {
namespace {

const OptionGroup* groupNamed(std::string_view name) {
  for (const OptionGroup& g : kOptionGroups)
    if (name == g.name) return &g;
  return nullptr;
}

// "--size W H" in --help, not CLI11's "--size TEXT x 2"; the usage line is
// the command's own; each task's group ends with its example.
class HelpFormatter : public CLI::Formatter {
 public:
  explicit HelpFormatter(std::string usage) : usage_(std::move(usage)) {}
  std::string make_option_opts(const CLI::Option* opt) const override {
    return opt->get_type_name().empty() ? std::string() : " " + opt->get_type_name();
  }
  std::string make_usage(const CLI::App*, std::string) const override { return "usage: " + usage_ + "\n"; }
  std::string make_group(std::string group, bool positional, std::vector<const CLI::Option*> opts) const override {
    std::string text = CLI::Formatter::make_group(group, positional, opts);
    if (const OptionGroup* g = groupNamed(group)) text += "  e.g. " + std::string(g->example) + "\n";
    return text;
  }

 private:
  std::string usage_;
};


// The options in --help order: the positional, then the task groups in
// kOptionGroups' order, then the command's own; within each, as declared.
std::vector<const OptionTable::Option*> helpOrder(const OptionTable& table) {
  auto rank = [](const OptionTable::Option& o) -> std::size_t {
    if (o.positional) return 0;
    for (std::size_t k = 0; k < std::size(kOptionGroups); ++k)
      if (o.group == kOptionGroups[k].name) return k + 1;
    return std::size(kOptionGroups) + 1;
  };
  std::vector<const OptionTable::Option*> v;
  for (const OptionTable::Option& o : table.options()) v.push_back(&o);
  std::stable_sort(v.begin(), v.end(), [&](auto* a, auto* b) { return rank(*a) < rank(*b); });
  return v;
}

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : " ") + w;
  return s;
}

// A word that names an option rather than a value: "-x", "--glpyh=box";
// "-0.5" is a value.
bool looksLikeFlag(std::string_view w) {
  return w.size() > 1 && w[0] == '-' && (std::isalpha(static_cast<unsigned char>(w[1])) || (w[1] == '-' && w.size() > 2));
}

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string nearestName(std::string_view word, std::span<const std::string> names) {
  std::string best;
  std::size_t bestDistance = 3;  // a suggestion within two edits
  for (const std::string& n : names) {
    const std::size_t d = editDistance(word, n);
    if (d < bestDistance) {
      bestDistance = d;
      best = n;
    }
  }
  return best;
}

namespace {

// CLI11 says "The following arguments were not expected: box --glpyh" (its
// words reversed) for a mistyped flag; a newcomer needs the flag named, and
// the one meant.
std::string unknownOption(const OptionTable& table, std::string_view word) {
  word = word.substr(0, word.find('='));
  std::vector<std::string> flags;
  for (const OptionTable::Option& o : table.options())
    if (!o.positional && !o.isHidden) flags.push_back(o.flag);
  const std::string best = nearestName(word, flags);
  std::string msg = "unknown option " + std::string(word);
  return best.empty() ? msg + "; see --help" : msg + "; did you mean " + best + "?";
}

}  // namespace

void parseCommandLine(const OptionTable& table, int argc, const char** argv) {
  CLI::App app;
  app.name(argc > 0 ? argv[0] : "tensorglyph");
  app.formatter(std::make_shared<HelpFormatter>(table.usage()));
  app.set_help_flag("-h,--help", "show this help and exit");
  bool markdown = false;
  app.add_flag("--help-markdown", markdown)->group("");
  app.get_formatter()->column_width(32);
  // Occurrences so far, by option: each trigger of a callback is one.
  std::vector<int> seen(table.options().size(), 0);
  std::size_t index = 0;
  for (const OptionTable::Option* o : helpOrder(table)) {
    int* count = &seen[index++];
    CLI::Option* c = nullptr;
    if (o->positional) {
      // Every extra positional reaches the action, which names the clash.
      c = app.add_option(o->flag, [o](const CLI::results_t& r) {
        for (const std::string& v : r) OptionTable::apply(*o, std::span<const std::string>(&v, 1));
        return true;
      });
      c->expected(1, INT_MAX);
    } else {
      const std::string names = o->shortFlag.empty() ? o->flag : o->shortFlag + "," + o->flag;
      c = app.add_option(names, [o, count](const CLI::results_t& r) {
        // A switch given "--stats=3", or too few values before the end.
        if (o->arity() == 0 && !(r.size() == 1 && r[0] == "true") && !r.empty())
          throw UsageError(o->flag + " takes no value");
        // "-o a.png -o b.png" wrote b.png alone; a switch twice means the same.
        if (++*count > 1 && o->arity() > 0 && !o->repeatable)
          throw UsageError(o->flag + " is given more than once; it takes one " +
                           (o->arity() == 1 ? o->metavars[0] : "set of values") + " (give it once)");
        OptionTable::apply(*o, o->arity() == 0 ? std::span<const std::string>() : std::span<const std::string>(r));
        return true;
      });
      c->expected(int(o->arity()));
      c->type_name(joined(o->metavars));
      c->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
      c->trigger_on_parse();
    }
    c->description(o->description());
    if (o->isHidden) c->group("");
    else if (o->positional) c->group("Input");
    else c->group(o->group.empty() ? std::string("Options") : o->group);
  }
  try {
    app.parse(argc, const_cast<char**>(argv));
    if (markdown) {
      std::fputs(markdownReference(table, table.usage().substr(0, table.usage().find('\n'))).c_str(), stdout);
      throw HelpShown{};
    }
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    throw HelpShown{};
  } catch (const CLI::ExtrasError& e) {
    for (const std::string& w : app.remaining())
      if (looksLikeFlag(w)) throw UsageError(unknownOption(table, w));
    throw UsageError(e.what());
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
}

std::string groupHelp(const OptionTable& table, const std::string& group) {
  std::string text;
  for (const OptionTable::Option* o : helpOrder(table)) {
    if (o->group != group || o->isHidden || o->positional) continue;
    std::string opts = o->shortFlag.empty() ? o->flag : o->shortFlag + ", " + o->flag;
    for (const std::string& m : o->metavars) opts += " " + m;
    char line[64];
    std::snprintf(line, sizeof line, "  %-30s ", opts.c_str());
    text += (opts.size() > 30 ? "  " + opts + "\n" + std::string(33, ' ') : std::string(line)) + o->description() + "\n";
  }
  if (text.empty()) return text;
  const OptionGroup* g = groupNamed(group);
  return group + ":\n" + text + (g ? "  e.g. " + std::string(g->example) + "\n" : std::string());
}

std::string markdownReference(const OptionTable& table, const std::string& title) {
  std::string md = "## " + title + "\n";
  std::string current = "\x01";
  for (const OptionTable::Option* o : helpOrder(table)) {
    if (o->isHidden) continue;
    const std::string group = o->positional ? "Input" : o->group.empty() ? "Options" : o->group;
    if (group != current) {
      current = group;
      md += "\n### " + group + "\n\n";
      if (const OptionGroup* g = groupNamed(group)) md += "Example: `" + std::string(g->example) + "`\n\n";
      md += "| option | values | range | default | what it does |\n|---|---|---|---|---|\n";
    }
    std::string help = o->helpText;
    for (std::size_t at = 0; (at = help.find('|', at)) != std::string::npos; at += 2) help.replace(at, 1, "\\|");
    const std::string flag = o->shortFlag.empty() ? o->flag : o->shortFlag + ", " + o->flag;
    const std::string range = o->numbers ? (o->list ? "each " : "") + o->numbers->text() : "";
    const std::string byDefault = o->defaultText.empty() ? "" : "`" + o->defaultText + "`";
    md += "| `" + flag + "` | " + (o->metavars.empty() ? "" : "`" + joined(o->metavars) + "`") + " | " + range +
          " | " + byDefault + " | " + help + (o->repeatable ? " (repeatable)" : "") + " |\n";
  }
  return md;
}

}  // namespace tg::app
