#include "io/modules/vtk/mesh_text_checks.h"

#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <string_view>

#include "io/field/tensor_field.h"
#include "util/strict_number.h"

namespace tg::io {
namespace {

[[noreturn]] void failAt(const std::string& path, std::uint64_t line, const std::string& what) {
  throw InputError("readMesh: " + path + ": line " + std::to_string(line) + ": " + what);
}

std::string quoted(std::string_view s) {
  std::string q(1, '"');
  return q.append(s).append(1, '"');
}

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> w;
  for (std::size_t k = 0; k < line.size();) {
    while (k < line.size() && std::isspace(static_cast<unsigned char>(line[k]))) ++k;
    const std::size_t s = k;
    while (k < line.size() && !std::isspace(static_cast<unsigned char>(line[k]))) ++k;
    if (k > s) w.push_back(line.substr(s, k - s));
  }
  return w;
}

// Lines of a text file, numbered from 1, to `each(lineNo, words)`; false stops.
template <class Each>
void eachLine(const std::string& path, Each&& each) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (std::uint64_t n = 1; std::getline(in, line); ++n)
    if (!each(n, words(line))) return;
}

double numberAt(const std::string& path, std::uint64_t line, std::string_view w) {
  const std::optional<double> v = util::parseNumber(w);
  if (!v) failAt(path, line, quoted(w) + " is not a number");
  return *v;
}

}  // namespace

std::vector<std::uint64_t> checkObjText(const std::string& path, std::uint64_t& vertices) {
  std::vector<std::uint64_t> bad;
  vertices = 0;
  bool continued = false;  // a "\" ended the last index line
  eachLine(path, [&](std::uint64_t n, const std::vector<std::string_view>& w) {
    if (w.empty()) return true;
    const bool indexLine = continued || w[0] == "f" || w[0] == "l" || w[0] == "p";
    const std::size_t from = continued ? 0 : 1;
    continued = false;
    if (!indexLine && (w[0] == "v" || w[0] == "vt" || w[0] == "vn")) {
      const std::size_t need = w[0] == "vt" ? 1 : 3;  // vt u [v [w]]
      if (w.size() - 1 < need)
        failAt(path, n, std::string(w[0]) + " needs " + std::to_string(need) + " numbers, the line has " +
                            std::to_string(w.size() - 1));
      bool finite = true;
      for (std::size_t k = 1; k < w.size(); ++k) {
        const double v = numberAt(path, n, w[k]);
        finite &= k > 3 || std::abs(v) <= double(FLT_MAX);  // false for NaN
      }
      if (w[0] == "v" && !finite) bad.push_back(vertices);
      vertices += w[0] == "v";
    } else if (indexLine) {
      for (std::size_t k = from; k < w.size(); ++k) {
        if (w[k] == "\\" && k + 1 == w.size()) {
          continued = true;
          break;
        }
        // v, v/vt, v//vn or v/vt/vn: the vertex's index given, the others integers or empty.
        std::string_view rest = w[k];
        for (int part = 0; part < 3 && (part == 0 || !rest.empty()); ++part) {
          const std::size_t slash = rest.find('/');
          const std::string_view index = rest.substr(0, slash);
          if ((part == 0 || !index.empty()) && !util::parseInteger(index))
            failAt(path, n, quoted(w[k]) + " is not a vertex index (v, v/vt, v//vn or v/vt/vn)");
          rest = slash == std::string_view::npos ? std::string_view() : rest.substr(slash + 1);
          if (slash != std::string_view::npos && part == 2)
            failAt(path, n, quoted(w[k]) + " is not a vertex index (v, v/vt, v//vn or v/vt/vn)");
        }
      }
    }
    return true;
  });
  return bad;
}

void checkPlyText(const std::string& path) {
  struct Property {
    bool list = false, integral = false, countIntegral = true;
  };
  struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> props;
  };
  auto integralType = [](std::string_view t) {
    return !(t == "float" || t == "double" || t == "float32" || t == "float64");
  };
  std::vector<Element> elements;
  bool ascii = false, header = true;
  std::size_t element = 0;
  std::uint64_t instance = 0;
  eachLine(path, [&](std::uint64_t n, const std::vector<std::string_view>& w) {
    if (header) {
      if (w.empty()) return true;
      if (w[0] == "format") ascii = w.size() > 1 && w[1] == "ascii";
      if (w[0] == "element") {
        const std::optional<long long> count = w.size() == 3 ? util::parseInteger(w[2]) : std::nullopt;
        if (!count || *count < 0) failAt(path, n, "\"element\" needs a name and a count of 0 or more");
        elements.push_back({std::string(w[1]), std::uint64_t(*count), {}});
      } else if (w[0] == "property" && !elements.empty()) {
        Property p;
        p.list = w.size() > 1 && w[1] == "list";
        p.countIntegral = !p.list || (w.size() > 2 && integralType(w[2]));
        p.integral = w.size() > (p.list ? 3u : 1u) && integralType(w[p.list ? 3 : 1]);
        elements.back().props.push_back(p);
      } else if (w[0] == "end_header") {
        header = false;
        if (!ascii) return false;
      }
      return true;
    }
    while (element < elements.size() && instance == elements[element].count) ++element, instance = 0;
    if (element == elements.size()) return false;  // after the data: VTK reads no further
    const Element& e = elements[element];
    std::size_t k = 0;
    auto value = [&](bool integral) {
      if (k == w.size())
        failAt(path, n, "element " + e.name + " " + std::to_string(instance) + " has too few values for its properties");
      const std::string_view t = w[k++];
      if (integral ? !util::parseInteger(t) : !util::parseNumber(t))
        failAt(path, n, quoted(t) + (integral ? " is not an integer" : " is not a number"));
      return t;
    };
    for (const Property& p : e.props) {
      if (!p.list) {
        value(p.integral);
        continue;
      }
      const long long items = *util::parseInteger(value(true));
      if (items < 0 || std::uint64_t(items) > w.size()) failAt(path, n, "a list of " + std::to_string(items) + " items");
      for (long long i = 0; i < items; ++i) value(p.integral);
    }
    if (k != w.size())
      failAt(path, n, "element " + e.name + " " + std::to_string(instance) + " has " + std::to_string(w.size()) +
                          " values, its properties take " + std::to_string(k));
    ++instance;
    return true;
  });
}

void checkStlText(const std::string& path) {
  {
    // Text, as VTK tells an ASCII STL: a binary one may begin with "solid" too.
    std::ifstream in(path, std::ios::binary);
    char head[512] = {};
    in.read(head, sizeof head);
    const std::size_t got = std::size_t(in.gcount());
    if (got < 5 || std::memcmp(head, "solid", 5) != 0) return;
    for (std::size_t k = 0; k < got; ++k)
      if (static_cast<unsigned char>(head[k]) > 0x7e || (head[k] < 0x20 && !std::isspace(static_cast<unsigned char>(head[k]))))
        return;
  }
  eachLine(path, [&](std::uint64_t n, const std::vector<std::string_view>& w) {
    std::size_t from = 0;
    if (!w.empty() && w[0] == "vertex") from = 1;
    else if (w.size() > 1 && w[0] == "facet" && w[1] == "normal") from = 2;
    else return true;
    if (w.size() != from + 3)
      failAt(path, n, quoted(w[0]) + " needs three numbers, the line has " + std::to_string(w.size() - from));
    for (std::size_t k = from; k < w.size(); ++k) numberAt(path, n, w[k]);
    return true;
  });
}

}  // namespace tg::io
