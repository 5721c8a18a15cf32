#pragma once
// The numbers of a NRRD header, read strictly before Teem reads them. Teem's
// field parsers take each word's longest numeric prefix (airSingleSscanf,
// sscanf underneath), so "spacings: NaN 1,5 1 1" gave a spacing of 1 and
// "space origin: (1.5x,0,0)" an origin of 1.5, without a word.
#include <cstdio>
#include <string>

namespace tg::io {

// Every number of the header's numeric fields (dimension, sizes, spacings,
// thicknesses, axis mins and maxs, min, max, old min and max, line and byte
// skip, space dimension, space origin, space directions, measurement frame)
// must be whole (util/strict_number.h); "nan" is allowed where NRRD uses it
// for an unknown value, "none" for a space direction. InputError("who: path:
// header line N (field): ...") otherwise. `in` is left at its start.
void checkNrrdHeaderNumbers(const char* who, const std::string& path, FILE* in);

}  // namespace tg::io
