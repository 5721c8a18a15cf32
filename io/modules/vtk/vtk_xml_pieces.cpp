#include "io/modules/vtk/vtk_xml_pieces.h"

#include <algorithm>
#include <cstring>
#include <set>

#include <vtkAlgorithm.h>
#include <vtkDataArraySelection.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLReader.h>

#include "io/field/tensor_field.h"

namespace tg::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("readVtk: " + path + ": " + what);
}

std::string quoted(const std::string& s) {
  std::string q(1, '"');
  return q.append(s).append(1, '"');
}

std::string attr(vtkXMLDataElement* e, const char* name) {
  const char* v = e ? e->GetAttribute(name) : nullptr;
  return v ? v : "";
}

// The Piece elements of the dataset element, and each one's group (PointData
// or CellData), null where a piece has none.
struct Pieces {
  std::vector<vtkXMLDataElement*> point, cell;
};

Pieces piecesOf(vtkAlgorithm* reader) {
  Pieces out;
  auto* xr = vtkXMLReader::SafeDownCast(reader);
  vtkXMLDataElement* root = xr && xr->GetXMLParser() ? xr->GetXMLParser()->GetRootElement() : nullptr;
  const char* type = root ? root->GetAttribute("type") : nullptr;
  vtkXMLDataElement* data = type ? root->FindNestedElementWithName(type) : nullptr;
  for (int p = 0; data && p < data->GetNumberOfNestedElements(); ++p) {
    vtkXMLDataElement* piece = data->GetNestedElement(p);
    if (std::strcmp(piece->GetName(), "Piece") != 0) continue;
    out.point.push_back(piece->FindNestedElementWithName("PointData"));
    out.cell.push_back(piece->FindNestedElementWithName("CellData"));
  }
  return out;
}

std::vector<vtkXMLDataElement*> arraysOf(vtkXMLDataElement* group) {
  std::vector<vtkXMLDataElement*> a;
  for (int k = 0; group && k < group->GetNumberOfNestedElements(); ++k) a.push_back(group->GetNestedElement(k));
  return a;
}

vtkXMLDataElement* named(const std::vector<vtkXMLDataElement*>& arrays, const std::string& name) {
  for (vtkXMLDataElement* e : arrays)
    if (attr(e, "Name") == name) return e;
  return nullptr;
}

// One group kind (point or cell) across the pieces: refusals, the names to
// disable, and for points the gaps.
void compare(const std::vector<vtkXMLDataElement*>& groups, const char* kind, const std::string& path,
             std::set<std::string>& disable, std::vector<PieceGap>* gaps) {
  if (groups.empty()) return;
  const std::string of = std::string(" ") + kind + " array ";
  const std::vector<vtkXMLDataElement*> first = arraysOf(groups[0]);
  const std::string pieces = std::to_string(groups.size());
  for (std::size_t p = 0; p < groups.size(); ++p) {
    const std::vector<vtkXMLDataElement*> arrays = arraysOf(groups[p]);
    const std::string piece = "piece " + std::to_string(p + 1);
    std::set<std::string> seen;
    for (vtkXMLDataElement* e : arrays) {
      const std::string name = attr(e, "Name");
      if (!seen.insert(name).second) fail(path, piece + " has two" + of.substr(0, of.size() - 1) + "s named " + quoted(name));
      vtkXMLDataElement* ref = named(first, name);
      if (!ref) {
        // VTK made no array for it; left enabled, it would be read into another.
        if (disable.insert(name).second && gaps) {
          PieceGap g;
          g.name = name;
          e->GetScalarAttribute("NumberOfComponents", g.components);
          g.activeTensors = name == attr(groups[p], "Tensors");
          g.problem = "piece 1 of " + pieces + " has no" + of + quoted(name) + " (" + piece + " has it)";
          gaps->push_back(g);
        }
        continue;
      }
      const std::string c = attr(e, "NumberOfComponents"), rc = attr(ref, "NumberOfComponents");
      if ((c.empty() ? "1" : c) != (rc.empty() ? "1" : rc) || attr(e, "type") != attr(ref, "type"))
        fail(path, piece + "'s" + of + quoted(name) + " has " + (c.empty() ? "1" : c) + " components of type " +
                       attr(e, "type") + ", piece 1's has " + (rc.empty() ? "1" : rc) + " of type " + attr(ref, "type"));
    }
    if (p == 0) continue;
    const std::string tensors = attr(groups[p], "Tensors"), firstTensors = attr(groups[0], "Tensors");
    if (gaps && !tensors.empty() && !firstTensors.empty() && tensors != firstTensors)
      fail(path, "pieces 1 and " + std::to_string(p + 1) + " name different point tensors (" + quoted(firstTensors) +
                     " and " + quoted(tensors) + ")");
    for (vtkXMLDataElement* ref : first) {
      const std::string name = attr(ref, "Name");
      if (named(arrays, name) || !disable.insert(name).second || !gaps) continue;
      PieceGap g;
      g.name = name;
      ref->GetScalarAttribute("NumberOfComponents", g.components);
      g.activeTensors = name == firstTensors;
      g.problem = piece + " of " + pieces + " has no" + of + quoted(name) + " (piece 1 has it): VTK would leave " +
                  "its points' values unset";
      gaps->push_back(g);
    }
  }
}

// The group's arrays in the first piece's order, then any others.
void reorder(vtkXMLDataElement* group, const std::vector<vtkXMLDataElement*>& first) {
  if (!group) return;
  std::vector<vtkSmartPointer<vtkXMLDataElement>> now;
  for (vtkXMLDataElement* e : arraysOf(group)) now.emplace_back(e);
  std::vector<vtkSmartPointer<vtkXMLDataElement>> order;
  for (vtkXMLDataElement* ref : first)
    for (auto& e : now)
      if (e && attr(e, "Name") == attr(ref, "Name")) {
        order.push_back(e);
        e = nullptr;
        break;
      }
  for (auto& e : now)
    if (e) order.push_back(e);
  group->RemoveAllNestedElements();
  for (auto& e : order) group->AddNestedElement(e);
}

}  // namespace

std::vector<PieceGap> matchPieceArrays(vtkAlgorithm* reader, const std::string& path) {
  auto* xr = vtkXMLReader::SafeDownCast(reader);
  if (!xr) return {};
  Pieces pieces = piecesOf(reader);
  std::set<std::string> disablePoints, disableCells;
  std::vector<PieceGap> gaps;
  compare(pieces.point, "point", path, disablePoints, &gaps);
  compare(pieces.cell, "cell", path, disableCells, nullptr);
  if (pieces.point.size() < 2) return gaps;
  if (!disablePoints.empty() || !disableCells.empty()) {
    for (const std::string& n : disablePoints) xr->GetPointDataArraySelection()->DisableArray(n.c_str());
    for (const std::string& n : disableCells) xr->GetCellDataArraySelection()->DisableArray(n.c_str());
    // The selection's change makes VTK parse the file again, into a new tree.
    xr->UpdateInformation();
    pieces = piecesOf(reader);
  }
  for (auto* groups : {&pieces.point, &pieces.cell}) {
    if (groups->empty()) continue;
    const std::vector<vtkXMLDataElement*> first = arraysOf((*groups)[0]);
    for (std::size_t p = 1; p < groups->size(); ++p) reorder((*groups)[p], first);
  }
  return gaps;
}

}  // namespace tg::io
