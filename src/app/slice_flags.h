#pragma once
// The command-line face of slice planes (render/slice_plane.h): --underlay,
// --plane, --plane-at and render::SliceParams' flags, whose help quotes the
// struct's defaults.
#include <memory>
#include <string>
#include <vector>

#include "app/scale/option_table.h"

#include "io/core/selection.h"
#include "io/field/tensor_field.h"
#include "render/renderer.h"
#include "view/underlay.h"

namespace tg::render {
class SlicePlane;
}

namespace tg::app {

struct SliceFlags {
  std::string underlay;  // a file, or fa|md|cl|cp (the field's own); empty: fa when planes are given
  // The underlay given in memory (Python's arrays), read instead of the file
  // `underlay` then names; with no placement of its own it lies on the
  // field's grid, whose shape it must have.
  std::shared_ptr<const io::ScalarVolume> underlayVolume;
  std::vector<render::PlaneSpec> planes;
  render::SliceParams params;
  std::string firstParameterFlag;  // an --underlay-* flag given, for validate()
  bool percentilesGiven = false;

  void addTo(OptionTable& ap);
  // UsageError for a parameter flag without a plane or an underlay.
  void validate() const;
  bool any() const { return !underlay.empty() || !planes.empty(); }
  // The underlay is one of the field's own scalars, not a file.
  bool fromField() const;
  // The planes to draw: those given, else the middle index plane along z.
  std::vector<render::PlaneSpec> planesFor(const render::UnderlayVolume& v) const;
};

// The underlay a render draws: the file (read guarded, io::readUnderlay) or
// the field's scalar on its grid, NaN where no tensor was kept. Call before
// the field's samples are released. Throws io::InputError naming the file;
// `command` begins the message where the field has no grid.
render::UnderlayVolume loadUnderlay(const SliceFlags& f, const io::TensorField& field, const char* command = "render");

// GL-free: throws UsageError for an index --plane outside the volume's grid
// (the range is known only once the volume is read) and io::InputError, as
// addSlicePlanes would, for an oblique plane that misses it; before any
// window opens or GL starts.
void checkPlanes(const SliceFlags& f, const render::UnderlayVolume& volume, const char* command);

// What a user would otherwise not see: one line each (without the command's
// name) for an underlay whose box does not overlap the glyphs' (another grid,
// other units, a wrong affine?), for a plane that passes beside the glyphs'
// box where the boxes do overlap, and for an index plane whose slice holds no
// finite value (all holes: masked voxels, or a --slice elsewhere).
std::vector<std::string> underlayWarnings(const SliceFlags& f, const render::UnderlayVolume& volume,
                                          const glm::dvec3& glyphLoWC, const glm::dvec3& glyphHiWC);

// Adds the planes as context items of `r` (nothing at all when f.any() is
// false). `maxAbsEigenvalue`: the glyphs', for the depth offset. Throws
// io::InputError for a plane outside the volume, naming the underlay.
// Returns the planes, in order, for the viewer to toggle and move.
std::vector<render::SlicePlane*> addSlicePlanes(render::GlyphRenderer& r, const gl::Api& gl, const gl::ShaderLibrary& lib, const SliceFlags& f,
                    render::UnderlayVolume volume, double maxAbsEigenvalue);

}  // namespace tg::app
