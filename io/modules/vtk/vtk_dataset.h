#pragma once
// A VTK file as VTK's readers give it, after readVtk's checks: the legacy
// counts against the file size, the XML structure, the memory promise, and
// VTK's own errors. Shared by the tensor reader and the mesh reader
// (io/core/mesh_reader.h); run it in the guarded child (io/core/read_guard.h).
#include <string>
#include <vector>

#include <vtkDataSet.h>
#include <vtkSmartPointer.h>

#include "io/core/readers.h"
#include "io/modules/vtk/vtk_nonfinite.h"
#include "io/modules/vtk/vtk_xml_pieces.h"

namespace tg::io {

struct ReadResult {
  vtkSmartPointer<vtkDataSet> data;
  std::string vtkSaid;      // VTK's first warning; empty: VTK said nothing
  NonFiniteText nonFinite;  // legacy ASCII read through sentinels: restore each value
  std::vector<PieceGap> pieceGaps;  // XML point arrays some piece lacks, left unread (io/modules/vtk/vtk_xml_pieces.h)
};

// .vtk (legacy), .vti, .vtu, .vtp or .vts by extension. `dims`: the grid a
// mask must have (null: any). InputError "readVtk: path: problem".
ReadResult readDataSet(const std::string& path, const ReadOptions& opt, const int* dims = nullptr);

}  // namespace tg::io
