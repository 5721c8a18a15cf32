#pragma once
// The flag groups `render` and `view` share, registered and checked in one
// place so that the two commands cannot drift: the field and its selection,
// legend, depth cues, shadows, slice planes, meshes, tracts and the built-in look.
#include <string>

#include "app/effect_flags.h"
#include "app/field_flags.h"
#include "app/legend_flags.h"
#include "app/look_flags.h"
#include "app/mesh_flags.h"
#include "app/shadow_flags.h"
#include "app/slice_flags.h"
#include "app/tract_flags.h"

namespace tg::app {

struct SceneFlags {
  FieldFlags field;
  LegendFlags legend;
  EffectFlags effects;
  ShadowFlags shadow;
  SliceFlags slices;
  MeshFlags mesh;
  TractFlags tracts;
  LookFlags look;

  // The field's selection, the slice planes and the meshes are loaded and
  // uploaded; the rest, the field's sizing included, are frame parameters.
  void addSceneFlags(OptionTable& ap) {
    const bool reloads = ap.reloadsDefault();
    ap.setReloadsDefault(true);
    field.addTo(ap, true);
    slices.addTo(ap);
    mesh.addTo(ap);
    tracts.addTo(ap);
    ap.setReloadsDefault(reloads);
    legend.addTo(ap);
    effects.addTo(ap);
    shadow.addTo(ap);
    look.addTo(ap);
  }
  // UsageError for the first group whose flags do not fit; `input` is the
  // command's INPUT (--mesh-from-input needs one).
  void validateSceneFlags(const std::string& input) const {
    field.validate();
    legend.validate();
    effects.validate();
    shadow.validate();
    slices.validate();
    mesh.validate(input);
    tracts.validate();
    look.validate(shadow.params.enabled, effects.ao.enabled, effects.outline.enabled, legend.params.enabled);
  }
};

}  // namespace tg::app
