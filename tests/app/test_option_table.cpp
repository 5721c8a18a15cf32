// The option table (GL-free): one definition serves the command line and the
// Python keywords, so names, arity and stage must hold for both.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/scale/cli_values.h"
#include "app/scale/option_table.h"
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
  t.arg("--plane SPEC").repeats().action([&](OptionArgs a) { order.push_back(a[1]); });
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

// Every option with values that takes a number declares its range, so that
// each surface (the command line, Python's keywords, the script) refuses
// what single precision cannot draw in the table's words; the options that
// take words are these.
TEST(RenderOptions, EveryNumericOptionDeclaresARange) {
  RenderOptions o;
  OptionTable t;
  addRenderOptions(t, o);
  const std::set<std::string> words = {"INPUT", "-o", "--glyph", "--color", "--array", "--layout", "--frame",
                                       "--mask", "--slice", "--scale-mode", "--sizes-from", "--magnitude", "--legend-corner",
                                       "--units", "--length-units", "--underlay", "--plane", "--underlay-colormap",
                                       "--mesh", "--mesh-mode", "--tracts", "--backend", "--color-array", "--colormap",
                                       "--view", "--orientation-letters", "--pipeline", "--sizes-from", "--tensor-axes"};
  for (const OptionTable::Option& opt : t.options()) {
    if (opt.arity() == 0 && !opt.positional) continue;
    if (words.count(opt.flag)) {
      EXPECT_FALSE(opt.numbers) << opt.flag;
      continue;
    }
    ASSERT_TRUE(opt.numbers) << opt.flag << " takes numbers but declares no range";
    for (const char* bad : {"nan", "inf", "1e300", "-1e300", "1e-40x"}) {
      const std::vector<std::string> values(opt.arity(), bad);
      EXPECT_THROW(OptionTable::apply(opt, values), UsageError) << opt.flag << " " << bad;
    }
    EXPECT_LE(opt.numbers->hi, kFloatMax) << opt.flag;
    EXPECT_GE(opt.numbers->lo, -kFloatMax) << opt.flag;
  }
}

// An empty value ("$UNSET" in a script) is refused, never taken as "not
// given": --mask "" would otherwise draw unmasked. Free text may be empty.
TEST(RenderOptions, EveryValueButFreeTextRefusesAnEmptyOne) {
  RenderOptions o;
  OptionTable t;
  addRenderOptions(t, o);
  bool sawText = false;
  for (const OptionTable::Option& opt : t.options()) {
    const std::size_t n = opt.positional ? 1 : opt.arity();
    for (std::size_t k = 0; k < n; ++k) {
      std::vector<std::string> values(n, "1");
      values[k] = "";
      if (!opt.positional && opt.metavars[k] == "TEXT") {
        sawText = true;
        EXPECT_NO_THROW(OptionTable::apply(opt, values)) << opt.flag;
        continue;
      }
      try {
        OptionTable::apply(opt, values);
        ADD_FAILURE() << opt.flag << " took an empty value " << k;
      } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find(opt.flag + ": an empty value"), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_TRUE(sawText);
}

// A declared default is one the option itself takes: as many values as it
// names, each within its range, and applying it leaves the frame as it was.
TEST(RenderOptions, DeclaredDefaultsAreValuesTheOptionTakesAndChangeNothing) {
  RenderOptions o;
  OptionTable t;
  addRenderOptions(t, o);
  std::size_t withDefaults = 0;
  for (const OptionTable::Option& opt : t.options()) {
    if (opt.defaultText.empty()) continue;
    ++withDefaults;
    std::vector<std::string> values;
    for (std::size_t at = 0; at < opt.defaultText.size();) {
      const std::size_t end = std::min(opt.defaultText.find(' ', at), opt.defaultText.size());
      values.push_back(opt.defaultText.substr(at, end - at));
      at = end + 1;
    }
    ASSERT_EQ(values.size(), opt.arity()) << opt.flag << " default \"" << opt.defaultText << "\"";
    RenderOptions given;
    OptionTable g;
    addRenderOptions(g, given);
    EXPECT_NO_THROW(OptionTable::apply(*g.find(opt.flag), values)) << opt.flag << " " << opt.defaultText;
    const auto& gs = given.field.read.selection;
    const auto& os = o.field.read.selection;
    EXPECT_TRUE(given.effects.ao == o.effects.ao && given.effects.outline == o.effects.outline &&
                given.shadow.params == o.shadow.params && given.mesh.params == o.mesh.params &&
                given.width == o.width && given.height == o.height && given.gamma == o.gamma &&
                given.maxIterations == o.maxIterations && given.epsilon == o.epsilon &&
                glm::distance(glm::dvec4(given.background), glm::dvec4(o.background)) < 1e-6 &&
                given.fov.value_or(render::CameraDesc{}.fovYDeg) == render::CameraDesc{}.fovYDeg &&
                gs.maskMin == os.maskMin && gs.confidenceMin == os.confidenceMin)
        << opt.flag << " " << opt.defaultText << " is not what the option stands at";
    EXPECT_NE(opt.description().find("default " + opt.defaultText), std::string::npos) << opt.description();
  }
  EXPECT_GE(withDefaults, 20u);
}

// The Python stubs' Literal types come from Option::choices: each name is
// one the option takes, and the refusal of another lists exactly them.
TEST(RenderOptions, DeclaredChoicesAreTheNamesEachOptionTakes) {
  EXPECT_EQ(choiceWords("dec, fa or array"), (std::vector<std::string>{"dec", "fa", "array"}));
  EXPECT_EQ(choiceWords("raster, cpu"), (std::vector<std::string>{"raster", "cpu"}));
  RenderOptions o;
  OptionTable t;
  addRenderOptions(t, o);
  std::size_t named = 0;
  for (const OptionTable::Option& opt : t.options()) {
    if (opt.choices.empty()) continue;
    ++named;
    ASSERT_EQ(opt.arity(), 1u) << opt.flag;
    for (const std::string& c : opt.choices) {
      RenderOptions given;
      OptionTable g;
      addRenderOptions(g, given);
      EXPECT_NO_THROW(OptionTable::apply(*g.find(opt.flag), std::vector<std::string>{c})) << opt.flag << " " << c;
    }
  }
  EXPECT_GE(named, 9u);
  for (const char* flag : {"--glyph", "--color", "--colormap", "--legend-corner", "--magnitude", "--mesh-mode",
                           "--scale-mode", "--sizes-from", "--backend"})
    EXPECT_FALSE(t.find(flag)->choices.empty()) << flag;
}

// The CLI's and Python's "did you mean": within two edits, else nothing.
TEST(OptionTable, NearestNameIsWithinTwoEdits) {
  const std::vector<std::string> names = {"--glyph", "--gamma", "--fa-min"};
  EXPECT_EQ(nearestName("--glpyh", names), "--glyph");
  EXPECT_EQ(nearestName("--fa-mni", names), "--fa-min");
  EXPECT_EQ(nearestName("--zzzzzz", names), "");
}

TEST(OptionTable, ARepeatedSingleValuedOptionIsRefusedAndRepeatableOnesAdd) {
  RenderOptions o;
  OptionTable t;
  addRenderOptions(t, o);
  for (std::vector<const char*> argv :
       {std::vector<const char*>{"render", "-o", "a.png", "-o", "b.png"},
        std::vector<const char*>{"render", "--size", "8", "8", "--size", "9", "9"},
        std::vector<const char*>{"render", "--glyph", "box", "--glyph", "ellipsoid"},
        std::vector<const char*>{"render", "--color", "fa", "--color", "dec"}}) {
    RenderOptions fresh;
    OptionTable again;
    addRenderOptions(again, fresh);
    try {
      parseCommandLine(again, int(argv.size()), argv.data());
      ADD_FAILURE() << argv[1] << " twice was accepted";
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()).find(std::string(argv[1]) + " is given more than once"), 0u) << e.what();
    }
  }
  const char* argv[] = {"render", "--plane", "z:1", "--plane", "x:2", "--mesh", "a.stl", "--mesh", "b.stl",
                        "--pick", "1", "2", "--pick", "3", "4", "--ao", "--ao", "-q"};
  parseCommandLine(t, int(std::size(argv)), argv);
  EXPECT_EQ(o.slices.planes.size(), 2u);
  EXPECT_EQ(o.mesh.files.size(), 2u);
  EXPECT_EQ(o.pick.pixels.size(), 2u);
  EXPECT_TRUE(o.quiet);
  for (const char* repeats : {"--plane", "--plane-at", "--mesh", "--pick"}) EXPECT_TRUE(t.find(repeats)->repeatable);
}

TEST(OptionTable, EveryRenderOptionBelongsToAHelpGroup) {
  RenderOptions o;
  OptionTable t;
  addRenderOptions(t, o);
  std::set<std::string> groups;
  for (const OptionGroup& g : kOptionGroups) groups.insert(g.name);
  std::set<std::string> used;
  for (const OptionTable::Option& opt : t.options()) {
    if (opt.positional) continue;
    EXPECT_TRUE(groups.count(opt.group)) << opt.flag << " is in no group (\"" << opt.group << "\")";
    used.insert(opt.group);
  }
  EXPECT_EQ(used, groups);  // and no group is empty
  for (const OptionGroup& g : kOptionGroups) {
    const std::string text = groupHelp(t, g.name);
    EXPECT_EQ(text.find(std::string(g.name) + ":\n"), 0u) << text;
    EXPECT_NE(text.find(g.example), std::string::npos) << text;
  }
}

TEST(NumberRange, TextAndChecksAgree) {
  EXPECT_EQ(ranges::kGamma.text(), "0..10000");
  EXPECT_EQ(ranges::kClampSpacings.text(), "0 (off) or 0.01..1e+06");
  EXPECT_EQ(rangeMessage("--gamma", ranges::kGamma), "--gamma must be within 0..10000");
  EXPECT_EQ(checkedNumber("--clamp", "0", ranges::kClampSpacings), 0.0);
  EXPECT_THROW(checkedNumber("--clamp", "0.001", ranges::kClampSpacings), UsageError);
  EXPECT_EQ(checkedNumber("--stride", "7", ranges::kStride), 7.0);
  EXPECT_THROW(checkedNumber("--stride", "2.5", ranges::kStride), UsageError);
  try {
    checkedNumber("--stride", "1e300", ranges::kStride);
    ADD_FAILURE();
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "--stride must be within 1..1e+06");
  }
}

TEST(Printable, ControlCharactersAreEscapedAndTheRestKept) {
  EXPECT_EQ(printable("a\nb\x1b[31m\t\r\x7f.nrrd"), "a\\nb\\x1b[31m\\t\\r\\x7f.nrrd");
  EXPECT_EQ(printable("caf\xc3\xa9 dir/x.vtk"), "caf\xc3\xa9 dir/x.vtk");  // UTF-8 stays
  // Bytes that are no UTF-8 (a binary header's, as a .trk's voxel order) are escaped.
  EXPECT_EQ(printable("order \"\xff\xfe\""), "order \"\\xff\\xfe\"");
  EXPECT_EQ(printable("\xc3(\xe2\x82\xac\xed\xa0\x80\xf0\x9f\x98\x80\xe2\x82"),
            "\\xc3(\xe2\x82\xac\\xed\\xa0\\x80\xf0\x9f\x98\x80\\xe2\\x82");
}

}  // namespace
}  // namespace tg::app
