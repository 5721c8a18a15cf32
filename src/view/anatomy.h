#pragma once
// Anatomical views and orientation letters in world terms, GL-free. Every
// reader puts positions in RAS+ (x right, y anterior, z superior: NIfTI's
// and MRtrix's scanner space; NRRD's LPS and LAS are converted, io/), so one
// table serves them all; a field without an anatomical space (FEM, a bare
// grid) reads the same names as its +x, +y, +z.
#include <optional>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>

#include "view/camera.h"

namespace tg::render {

// Where the eye sits, from the look-at point, and which way is up.
struct ViewAxes {
  glm::dvec3 towardEyeWC{0, 0, 1};
  glm::dvec3 upWC{0, 1, 0};
};

// The view names --view takes, for messages and --help.
inline constexpr const char* kViewNames =
    "axial, coronal, sagittal, superior, inferior, anterior, posterior, left or right";

// Seen from a side: superior (from above, anterior up), inferior (from
// below), anterior (from the front, superior up), posterior (from behind),
// left and right (from that side, superior up). The planes by convention:
// axial is inferior when radiological (the patient's right on the image's
// left, as seen from the feet), superior when neurological; coronal is
// anterior (facing the patient) or posterior; sagittal is left in both (the
// nose on the image's left, as ITK-SNAP and DICOM show it). Nothing for
// another name.
std::optional<ViewAxes> namedView(std::string_view name, bool radiological);

// The named view (or the one whose eye direction is nearest `normalWC`,
// among axial, coronal and sagittal) turned to look straight along
// `normalWC`: a slice seen face-on, its up the view's, made orthogonal.
ViewAxes faceOnView(const glm::dvec3& normalWC, bool radiological);

// `d` turned to `axes`, its look-at point and distance kept.
CameraDesc turnedTo(const CameraDesc& d, const ViewAxes& axes);

// The letters of a world direction: R/L, A/P, S/I of each component at least
// half the largest, largest first ("R", "RA" for a direction 30 degrees off
// right towards anterior); "" for a zero vector.
std::string orientationLetters(const glm::dvec3& dirWC);

// Whether a field's space (io::TensorField::space) is anatomical: RAS after
// the readers' conversions. FEM meshes, bare grids and unknown spaces are not.
bool isAnatomicalSpace(std::string_view space);

}  // namespace tg::render
