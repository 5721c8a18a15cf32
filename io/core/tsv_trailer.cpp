// 3D-TSV (Wang et al., github.com/Junpeng-Wang-TUM/3D-TSV) appends its FEM
// stresses to a legacy .vtk file after the standard sections, which VTK's
// reader stops before. No library reads this trailer, so it is parsed here:
// "Cartesian Stress: N" then N lines "Sxx Syy Szz Syz Szx Sxy".
#include <charconv>
#include <cstring>
#include <optional>
#include <string_view>
#include <fstream>
#include <string>

#include "io/core/tsv_trailer.h"
#include "util/strict_number.h"

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
    // Whole numbers (util/strict_number.h), six of them: a seventh means
    // another layout than 3D-TSV's, not one to read the first six of.
    double s[6];
    std::size_t count = 0;
    for (std::size_t k = 0; k < line.size();) {
      while (k < line.size() && (line[k] == ' ' || line[k] == '\t' || line[k] == '\r')) ++k;
      const std::size_t from = k;
      while (k < line.size() && !(line[k] == ' ' || line[k] == '\t' || line[k] == '\r')) ++k;
      if (k == from) break;
      const std::string_view word = std::string_view(line).substr(from, k - from);
      const std::optional<double> v = util::parseNumber(word);
      if (!v)
        throw InputError("readVtk: " + path + ": \"Cartesian Stress\" row " + std::to_string(i) + ": \"" +
                         std::string(word) + "\" is not a number");
      if (count == 6)
        throw InputError("readVtk: " + path + ": \"Cartesian Stress\" row " + std::to_string(i) +
                         " holds more than six numbers (Sxx Syy Szz Syz Szx Sxy)");
      s[count++] = *v;
    }
    if (count < 6)
      throw InputError("readVtk: " + path + ": \"Cartesian Stress\" row " + std::to_string(i) +
                       " does not hold six numbers");
    // Sxx Syy Szz Syz Szx Sxy -> row-major 3x3.
    const double m[9] = {s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2]};
    std::copy(m, m + 9, &full9[9 * i]);
  }
  return true;
}

}  // namespace tg::io
