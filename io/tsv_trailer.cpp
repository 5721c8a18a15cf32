// 3D-TSV (Wang et al., github.com/Junpeng-Wang-TUM/3D-TSV) appends its FEM
// stresses to a legacy .vtk file after the standard sections, which VTK's
// reader stops before. No library reads this trailer, so it is parsed here:
// "Cartesian Stress: N" then N lines "Sxx Syy Szz Syz Szx Sxy".
#include <charconv>
#include <cstring>
#include <fstream>
#include <string>

#include "io/tsv_trailer.h"

namespace tg::io {

bool readTsvStressTrailer(const std::string& path, std::uint64_t points, std::vector<double>& full9) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  static constexpr char kKey[] = "Cartesian Stress:";
  while (std::getline(in, line))
    if (line.rfind(kKey, 0) == 0) break;
  if (!in) return false;
  const char* first = line.data() + std::strlen(kKey);
  while (*first == ' ') ++first;
  std::uint64_t n = 0;
  const auto [end, ec] = std::from_chars(first, line.data() + line.size(), n);
  if (ec != std::errc()) throw InputError("readVtk: " + path + ": \"Cartesian Stress:\" has no count");
  if (n != points)
    throw InputError("readVtk: " + path + ": \"Cartesian Stress\" has " + std::to_string(n) + " rows for " +
                     std::to_string(points) + " points");
  full9.assign(9 * points, 0.0);
  for (std::uint64_t i = 0; i < n; ++i) {
    if (!std::getline(in, line))
      throw InputError("readVtk: " + path + ": \"Cartesian Stress\" ends after " + std::to_string(i) + " of " +
                       std::to_string(n) + " rows");
    double s[6];
    const char* p = line.data();
    const char* e = p + line.size();
    for (double& v : s) {
      while (p < e && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
      const auto r = std::from_chars(p, e, v);
      if (r.ec != std::errc())
        throw InputError("readVtk: " + path + ": \"Cartesian Stress\" row " + std::to_string(i) +
                         " does not hold six numbers");
      p = r.ptr;
    }
    // A seventh number means another layout than 3D-TSV's six, not one to
    // read the first six of.
    while (p < e && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
    if (p != e)
      throw InputError("readVtk: " + path + ": \"Cartesian Stress\" row " + std::to_string(i) +
                       " holds more than six numbers (Sxx Syy Szz Syz Szx Sxy)");
    // Sxx Syy Szz Syz Szx Sxy -> row-major 3x3.
    const double m[9] = {s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2]};
    std::copy(m, m + 9, &full9[9 * i]);
  }
  return true;
}

}  // namespace tg::io
