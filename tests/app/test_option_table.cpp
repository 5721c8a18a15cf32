// The option table (GL-free): one definition serves the command line and the
// Python keywords, so names, arity and stage must hold for both.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "app/cli_values.h"
#include "app/option_table.h"
#include "app/render_options.h"

namespace tg::app {
namespace {

TEST(OptionTable, SpecsGiveFlagValueNamesAndKeyword) {
  OptionTable t;
  const auto& size = t.arg("--size W H");
  EXPECT_EQ(size.flag, "--size");
  EXPECT_EQ(size.metavars, (std::vector<std::string>{"W", "H"}));
  EXPECT_EQ(t.arg("--fa-min F").keyword(), "fa_min");
  EXPECT_TRUE(t.arg("INPUT").positional);
  EXPECT_EQ(t.find("fa_min"), t.find("--fa-min"));
  EXPECT_THROW(t.arg("--size X"), std::logic_error);
}

TEST(OptionTable, ApplyChecksTheNumberOfValues) {
  OptionTable t;
  std::vector<std::string> seen;
  t.arg("--eye X Y Z").action([&](OptionArgs a) { seen.assign(a.begin(), a.end()); });
  const auto& eye = *t.find("--eye");
  EXPECT_THROW(OptionTable::apply(eye, std::vector<std::string>{"1", "2"}), UsageError);
  OptionTable::apply(eye, std::vector<std::string>{"1", "-2", "3e1"});
  EXPECT_EQ(seen, (std::vector<std::string>{"--eye", "1", "-2", "3e1"}));
}

TEST(OptionTable, CommandLineRunsActionsInOrderAndRefusesWhatItDoesNotKnow) {
  std::vector<std::string> order;
  std::string input;
  OptionTable t("test [INPUT]");
  addInputArg(t, input);
  t.arg("--plane SPEC").action([&](OptionArgs a) { order.push_back(a[1]); });
  t.arg("--stats").action([&](OptionArgs) { order.push_back("stats"); });
  const char* argv[] = {"test", "in.vtk", "--plane", "z:1", "--stats", "--plane", "x:-2"};
  parseCommandLine(t, 7, argv);
  EXPECT_EQ(input, "in.vtk");
  EXPECT_EQ(order, (std::vector<std::string>{"z:1", "stats", "x:-2"}));
  const char* unknown[] = {"test", "--bogus"};
  EXPECT_THROW(parseCommandLine(t, 2, unknown), UsageError);
  const char* valued[] = {"test", "--stats=3"};
  EXPECT_THROW(parseCommandLine(t, 2, valued), UsageError);
  const char* short_[] = {"test", "--plane"};
  EXPECT_THROW(parseCommandLine(t, 2, short_), UsageError);
}

// What the Python module's Renderer relies on: frame parameters do not
// reload; what changes the loaded glyphs does.
TEST(RenderOptions, FrameParametersDoNotReloadAndSelectionsDo) {
  RenderOptions o;
  OptionTable t;
  addRenderOptions(t, o);
  for (const char* frame : {"gamma", "fa_min", "scale", "scale_mode", "color", "eye", "fov", "ao", "outlines",
                            "shadows", "legend", "glyph", "iterations", "background"}) {
    ASSERT_NE(t.find(frame), nullptr) << frame;
    EXPECT_FALSE(t.find(frame)->reload) << frame;
  }
  for (const char* load : {"stride", "slice", "roi", "mask", "layout", "frame", "cl_min", "min_eigenvalue", "size",
                           "backend", "underlay", "plane", "mesh"}) {
    ASSERT_NE(t.find(load), nullptr) << load;
    EXPECT_TRUE(t.find(load)->reload) << load;
  }
  std::set<std::string> keywords;
  for (const auto& opt : t.options()) EXPECT_TRUE(keywords.insert(opt.keyword()).second) << opt.flag;
  for (const char* cliOnly : {"o", "repeat", "verbose", "pick"}) EXPECT_TRUE(t.find(cliOnly)->cliOnly) << cliOnly;
}

TEST(RenderOptions, KeywordsReachTheSameFieldsAsFlags) {
  RenderOptions fromFlags, fromKeywords;
  OptionTable a, b;
  addRenderOptions(a, fromFlags);
  addRenderOptions(b, fromKeywords);
  const char* argv[] = {"render", "--gamma", "1.5", "--size", "64", "48", "--fa-min", "0.25"};
  parseCommandLine(a, 8, argv);
  OptionTable::apply(*b.find("gamma"), std::vector<std::string>{"1.5"});
  OptionTable::apply(*b.find("size"), std::vector<std::string>{"64", "48"});
  OptionTable::apply(*b.find("fa_min"), std::vector<std::string>{"0.25"});
  EXPECT_EQ(fromFlags.gamma, fromKeywords.gamma);
  EXPECT_EQ(fromFlags.width, 64);
  EXPECT_EQ(fromKeywords.height, 48);
  EXPECT_EQ(fromFlags.faMin, fromKeywords.faMin);
  EXPECT_THROW(validateRenderOptions(fromKeywords, true), UsageError);  // no -o
  EXPECT_NO_THROW(validateRenderOptions(fromKeywords, false));
}

}  // namespace
}  // namespace tg::app
