#pragma once
// A pick as one line of JSON (JSON Lines: one object per pick, in the order
// asked), for `render --pick` and the viewer script's `pick`.
#include <string>

#include "app/pick.h"

namespace tg::app {

// Keys (docs/guide.md, "Picking"): "pixel" [I, J]; "hit" "glyph", "context" or
// "background"; "id" (the id channel, absent for background); for a glyph
// "index" (the input index: on a grid i + X (j + Y k), i fastest), "voxel"
// ([i, j, k], gridded inputs only), "position" (WC), "tensor" (3x3 rows, WC), "eigenvalues"
// (descending), "eigenvectors" (rows, unit, ↔ eigenvalues), "fa", "md",
// "cl", "cp", "sign", "glyph_group"; for context "label" and "value"
// (null when the item has none); and for both "surface" (WC) and "depth"
// (view depth from the eye).
std::string pickJson(const Pick& p);

}  // namespace tg::app
