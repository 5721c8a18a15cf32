#include "app/tract_flags.h"

#include <cstdio>

#include "app/scale/cli_values.h"
#include "app/scale/option_ranges.h"
#include "io/core/format_table.h"

namespace tg::app {

void TractFlags::addTo(OptionTable& ap) {
  using Args = OptionArgs;
  const render::TractParams d;
  auto given = [this](const char* flag) {
    if (firstParameterFlag.empty()) firstParameterFlag = flag;
  };
  const std::string group = ap.groupDefault();
  ap.setGroup("context");
  ap.arg("--tracts FILE")
      .help("draw streamlines with the glyphs, as tubes through the same depth buffer: " +
            io::extensionList(io::kTractUse) + " (MRtrix, TrackVis in RAS+ mm as nibabel reads it, VTK polylines)")
      .repeats().action([this](Args a) { files.emplace_back(a[1]); });
  ap.arg("--tract-color R G B")
      .help("one colour for every tract; without it each is coloured by its local direction (|x| red, |y| green, "
            "|z| blue, in world axes)")
      .range(ranges::kUnit).action([this, given](Args a) {
        given("--tract-color");
        params.byDirection = false;
        for (int k = 0; k < 3; ++k) params.color[k] = float(parseDouble(a[0], a[1 + std::size_t(k)]));
      });
  ap.arg("--tract-width W")
      .help("tube diameter in world units (mm for DTI); never thinner than a pixel on screen")
      .range(ranges::kTractWidth).byDefault(formatNumber(d.widthWC)).action([this, given](Args a) {
        given("--tract-width");
        params.widthWC = float(parseDouble(a[0], a[1]));
      });
  ap.setGroup(group);
}

void TractFlags::validate() const {
  if (!firstParameterFlag.empty() && !any()) throw UsageError(firstParameterFlag + " needs --tracts");
  for (const std::string& f : files)
    if (const std::string p = io::tractExtensionProblem(f); !p.empty()) throw UsageError("--tracts: " + f + ": " + p);
}

std::vector<NamedPath> TractFlags::inputs() const {
  std::vector<NamedPath> v;
  for (const std::string& f : files) v.push_back({"--tracts", f});
  return v;
}

std::vector<io::TractData> TractFlags::read(const char* command) const {
  std::vector<io::TractData> tracts;
  for (const std::string& f : files) {
    io::TractData t = io::readTracts(f);
    if (render::drawableStreamlines(t.starts) == 0)
      throw io::InputError("readTracts: " + t.path + ": nothing to draw: no streamline has two or more points" +
                           (t.skippedNonFinite ? " (" + std::to_string(t.skippedNonFinite) +
                                                     " skipped for a NaN/Inf point)"
                                               : std::string()));
    if (!t.warning.empty())
      std::fprintf(stderr, "tensorglyph %s: %s: %s\n", command, printable(t.path).c_str(), printable(t.warning).c_str());
    if (t.skippedNonFinite)
      std::fprintf(stderr, "tensorglyph %s: %s: %zu streamlines skipped: a point is NaN/Inf or beyond single precision\n",
                   command, printable(t.path).c_str(), t.skippedNonFinite);
    tracts.push_back(std::move(t));
  }
  return tracts;
}

void addTracts(render::GlyphRenderer& r, const gl::Api& gl, const gl::ShaderLibrary& lib,
               const std::vector<io::TractData>& tracts, const render::TractParams& params) {
  for (const io::TractData& t : tracts) {
    const std::string name = t.path.substr(t.path.find_last_of('/') + 1);
    r.addContext(std::make_unique<render::TractItem>(gl, lib, "tracts " + name, t.positionsWC, t.starts, params));
  }
}

void growByTracts(const std::vector<io::TractData>& tracts, glm::dvec3& lo, glm::dvec3& hi) {
  for (const io::TractData& t : tracts)
    for (std::size_t i = 0; i < t.pointCount(); ++i) {
      const glm::dvec3 p(t.positionsWC[3 * i], t.positionsWC[3 * i + 1], t.positionsWC[3 * i + 2]);
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
}

}  // namespace tg::app
