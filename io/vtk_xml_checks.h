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

// Every inline binary (base64) DataArray holds at least the bytes its own
// size prefix declares. VTK decodes a short one past its end into the
// following markup and reports nothing. Compressed inline arrays are left to
// VTK's decompressor, which does report short blocks.
void checkInlineBinary(vtkAlgorithm* reader, const std::string& path);

}  // namespace tg::io
