#pragma once
// Arrays matched by name across the pieces of an XML VTK file. VTK's XML
// readers make their output arrays from the first piece's list and fill
// each later piece's by position (vtkXMLDataReader::ReadPieceData): with
// piece 1 listing "t, s" and piece 2 "s, t", piece 2's s was drawn as the
// tensors t, and an array piece 2 lacked kept, for its points, memory VTK
// never filled.
#include <string>
#include <vector>

class vtkAlgorithm;

namespace tg::io {

// A point array some piece lacks; VTK is told not to read it at all.
struct PieceGap {
  std::string name;
  int components = 1;
  bool activeTensors = false;  // the first piece names it Tensors="..."
  std::string problem;         // "piece 2 of 3 has no point array "t" (piece 1 has it)..."
};

// Between a reader's UpdateInformation and its Update: every piece's point
// and cell arrays are put in the first piece's order, so that VTK's
// positional fill takes each by its name; arrays missing from a piece, or
// found only in later pieces, are disabled (and the header read again).
// Refused (InputError "readVtk: path: ..."): two arrays of one name in a
// piece, an array whose components or type differ between pieces, and
// pieces naming different active tensors. Returns the point arrays that
// were disabled because a piece lacks them.
std::vector<PieceGap> matchPieceArrays(vtkAlgorithm* reader, const std::string& path);

}  // namespace tg::io
