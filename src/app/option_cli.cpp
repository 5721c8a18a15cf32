// The command line front end of OptionTable: CLI11 does the parsing and the
// --help text; each option's values reach its action as they are met, in
// command-line order (trigger_on_parse), as the table promises.
#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli_values.h"
#include "app/option_table.h"

namespace tg::app {
namespace {

// "--size W H" in --help, not CLI11's "--size TEXT x 2"; the usage line is
// the command's own.
class HelpFormatter : public CLI::Formatter {
 public:
  explicit HelpFormatter(std::string usage) : usage_(std::move(usage)) {}
  std::string make_option_opts(const CLI::Option* opt) const override {
    return opt->get_type_name().empty() ? std::string() : " " + opt->get_type_name();
  }
  std::string make_usage(const CLI::App*, std::string) const override { return "usage: " + usage_ + "\n"; }

 private:
  std::string usage_;
};

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

// CLI11 says "The following arguments were not expected: box --glpyh" (its
// words reversed) for a mistyped flag; a newcomer needs the flag named, and
// the one meant.
std::string unknownOption(const OptionTable& table, std::string_view word) {
  word = word.substr(0, word.find('='));
  std::string best;
  std::size_t bestDistance = 3;  // a suggestion within two edits
  for (const OptionTable::Option& o : table.options()) {
    if (o.positional || o.isHidden) continue;
    const std::size_t d = editDistance(word, o.flag);
    if (d < bestDistance) {
      bestDistance = d;
      best = o.flag;
    }
  }
  std::string msg = "unknown option " + std::string(word);
  return best.empty() ? msg + "; see --help" : msg + "; did you mean " + best + "?";
}

}  // namespace

void parseCommandLine(const OptionTable& table, int argc, const char** argv) {
  CLI::App app;
  app.name(argc > 0 ? argv[0] : "tensorglyph");
  app.formatter(std::make_shared<HelpFormatter>(table.usage()));
  app.set_help_flag("-h,--help", "show this help and exit");
  app.get_formatter()->column_width(32);
  for (const OptionTable::Option& opt : table.options()) {
    const OptionTable::Option* o = &opt;
    CLI::Option* c = nullptr;
    if (o->positional) {
      // Every extra positional reaches the action, which names the clash.
      c = app.add_option(o->flag, [o](const CLI::results_t& r) {
        for (const std::string& v : r) OptionTable::apply(*o, std::span<const std::string>(&v, 1));
        return true;
      });
      c->expected(1, INT_MAX);
    } else {
      c = app.add_option(o->flag, [o](const CLI::results_t& r) {
        // A switch given "--stats=3", or too few values before the end.
        if (o->arity() == 0 && !(r.size() == 1 && r[0] == "true") && !r.empty())
          throw UsageError(o->flag + " takes no value");
        OptionTable::apply(*o, o->arity() == 0 ? std::span<const std::string>() : std::span<const std::string>(r));
        return true;
      });
      c->expected(int(o->arity()));
      c->type_name(joined(o->metavars));
      c->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
      c->trigger_on_parse();
    }
    c->description(o->helpText);
    if (o->isHidden) c->group("");
  }
  try {
    app.parse(argc, const_cast<char**>(argv));
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

}  // namespace tg::app
