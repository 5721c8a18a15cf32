#include "render/renderer_profile.h"

namespace tg::render {

RendererProfile RendererProfile::of(std::string_view glRenderer) {
  if (glRenderer.find("llvmpipe") == std::string_view::npos) {
    // A GPU's vertex stage is parallel, and a per-frame pixel cull would be
    // a dependent dispatch; the rest is not measured there yet.
    return {};
  }
  RendererProfile p;
  // llvmpipe (2 cores; the scenes of tests/bench/peers.sh): the 40^3 point
  // load at 1024x768 (typical sprite 16 px) took 7-10% less CPU per frame as
  // oriented quads, at 1536x1152 (24 px) 17% less, at 768x576 (12 px) and
  // below the same or more; the helix at 512x512 (8 px) 55% more.
  p.orientedQuadMinPx = 14.0;
  // llvmpipe runs the vertex stage on one thread, eight glyphs at a time, so
  // a pass over all glyphs on every thread pays where most glyphs are
  // culled. 10^5 random superquadrics at 1920x1080, CPU per frame: at a
  // typical 0.24 px the cull kept 14% of the glyphs and the frame took
  // 120-126 ms against 135-145 without it (wall 180-189 against 207-230);
  // at 0.9 px it kept 77% and cost the same (275-331 against 313); at 1.9 px
  // it kept 98%.
  p.pixelCullMaxPx = 1.0;
  // Below it the pre-pass's vertex stage and depth pyramid cost more than
  // the few fragments it saves. 10^5 random superquadrics at 1920x1080, CPU
  // ms per frame with the pre-pass against without: typical 0.24 px 203-206
  // against 156-172, 0.9 px 456-537 against 363-371, 1.9 px 732-765 against
  // 534-610, 3.8 px 1166-1226 against 1108-1164, 7.6 px 1950-2219 against
  // 2475-2653 (the helix, 8 px, and the point load, 16 px, keep it: docs/performance.md).
  p.occlusionMinPx = 4.0;
  // llvmpipe bins a whole draw call (every glyph's interpolants: about 440
  // bytes a superquadric point sprite, 25 MB for the dt-helix) before it
  // rasterises any of it, so draws go in submissions of 4096 glyphs, at most
  // two queued, and its binning memory stays a few MB whatever the count.
  p.glyphsPerSubmit = 4096;
  return p;
}

}  // namespace tg::render
