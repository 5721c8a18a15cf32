#pragma once
// The numbers of text meshes (.obj, ASCII .ply and .stl), read strictly
// before VTK reads them. VTK 9.1's readers take a word's longest numeric
// prefix or stop without a word: its OBJ reader (a stream into floats) read
// "v 0 2 nan" as (0, 2, 0) and "v 1,5 2 3" as (1, 0, 0), "inf" and "0x10" as
// 0, and face indices by sscanf ("3x" as 3); its PLY reader (atof, atoi)
// read "0,5" as 0; its STL reader (sscanf) reads "1.5abc" as 1.5.
#include <cstdint>
#include <string>
#include <vector>

namespace tg::io {

// An OBJ file's "v", "vt", "vn", "f", "l" and "p" lines: every number whole
// (util/strict_number.h) and every index an integer. Returns the (0-based)
// vertices with a NaN/Inf coordinate or one beyond single precision, which
// VTK cannot read: the caller marks them, so that their cells are skipped
// and counted as for the other formats. `vertices` gets the number of "v"
// lines. InputError("readMesh: path: line N: ...").
std::vector<std::uint64_t> checkObjText(const std::string& path, std::uint64_t& vertices);

// An ASCII PLY file's element data against its header: each element's line
// holds exactly the values its properties take, integers where the type is
// one. Binary PLY is left alone (its header counts are checked elsewhere).
void checkPlyText(const std::string& path);

// An ASCII STL file's "facet normal" and "vertex" lines hold three whole numbers.
void checkStlText(const std::string& path);

}  // namespace tg::io
