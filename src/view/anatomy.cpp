#include "view/anatomy.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

namespace tg::render {

std::optional<ViewAxes> namedView(std::string_view name, bool radiological) {
  const glm::dvec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  if (name == "axial") name = radiological ? "inferior" : "superior";
  if (name == "coronal") name = radiological ? "anterior" : "posterior";
  if (name == "sagittal") name = "left";
  if (name == "superior") return ViewAxes{z, y};
  if (name == "inferior") return ViewAxes{-z, y};
  if (name == "anterior") return ViewAxes{y, z};
  if (name == "posterior") return ViewAxes{-y, z};
  if (name == "left") return ViewAxes{-x, z};
  if (name == "right") return ViewAxes{x, z};
  return std::nullopt;
}

ViewAxes faceOnView(const glm::dvec3& normalWC, bool radiological) {
  const glm::dvec3 n = glm::normalize(normalWC);
  ViewAxes best = *namedView("axial", radiological);
  double bestDot = -1;
  for (const char* plane : {"axial", "coronal", "sagittal"}) {
    const ViewAxes v = *namedView(plane, radiological);
    const double d = std::abs(glm::dot(v.towardEyeWC, n));
    if (d > bestDot) bestDot = d, best = v;
  }
  // The side the plane's view looks from; its up, less what lies along n.
  const glm::dvec3 toward = glm::dot(best.towardEyeWC, n) >= 0 ? n : -n;
  return {toward, glm::normalize(best.upWC - glm::dot(best.upWC, toward) * toward)};
}

CameraDesc turnedTo(const CameraDesc& d, const ViewAxes& axes) {
  CameraDesc out = d;
  out.eyeWC = d.lookAtWC + glm::length(d.eyeWC - d.lookAtWC) * glm::normalize(axes.towardEyeWC);
  out.upWC = axes.upWC;
  return out;
}

std::string orientationLetters(const glm::dvec3& dirWC) {
  constexpr char kPositive[] = "RAS", kNegative[] = "LPI";
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return std::abs(dirWC[a]) > std::abs(dirWC[b]); });
  const double largest = std::abs(dirWC[order[0]]);
  std::string out;
  if (!(largest > 0)) return out;
  for (int a : order)
    if (std::abs(dirWC[a]) >= 0.5 * largest) out += dirWC[a] > 0 ? kPositive[a] : kNegative[a];
  return out;
}

bool isAnatomicalSpace(std::string_view space) { return space.substr(0, 3) == "RAS"; }

}  // namespace tg::render
