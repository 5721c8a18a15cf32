#pragma once
// Checks of an XML VTK file's structure, made on the element tree VTK's
// parser builds in UpdateInformation, before or after VTK decodes the data:
// what VTK itself leaves unchecked and then fills with garbage or allocates
// from.
#include <cstdint>
#include <string>

class vtkAlgorithm;

namespace tg::io {

// Points the header promises: the whole extent of a structured file, else
// the sum of its pieces' NumberOfPoints (VTK's unstructured readers count
// them only once the data is read). Extents are taken in 64 bits: one past
// INT_MAX made VTK report a -1 x -1 grid. InputError("readVtk: path: ...")
// for an empty or overlong extent or a negative count.
std::uint64_t xmlPoints(vtkAlgorithm* reader, const std::string& path);

// Whether the file names a compressor.
bool xmlCompressed(vtkAlgorithm* reader);

// What VTK leaves unchecked in an XML file's structure and then fills with
// zeros, uninitialised memory or defaults: every inline or appended binary
// array holds the bytes its size prefix (or block table) promises, within the
// file; appended offsets are not negative; Origin, Spacing and Direction are
// finite numbers; each piece lies inside the whole extent. Compressed inline
// arrays are left to VTK's decompressor, which reports short blocks.
void checkXmlStructure(vtkAlgorithm* reader, const std::string& path);

}  // namespace tg::io
