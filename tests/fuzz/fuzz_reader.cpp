// libFuzzer target for one reader's header path: built four times with
// TG_FUZZ_FORMAT = 0 (NRRD: header and streamed data), 1 (NIfTI: header and
// data, and the data-file list outputs are checked against), 2 (legacy VTK:
// our count checks and VTK's header read), 3 (MRtrix .mif: header and data,
// as a tensor image and as a mask), 4 (XML .vtu: VTK's parse of the
// structure and our checks of it: extents, piece counts, inline lengths),
// 5 (MRtrix .tck) and 6 (TrackVis .trk): the tract readers, header and data.
// Any input must end in a result or an InputError: never a crash, a hang,
// a sanitizer report or an allocation sized by an unchecked header.
//   build-fuzz/fuzz_nrrd CORPUS_COPY tests/fuzz/corpus/nrrd -max_total_time=30
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "io/core/input_files.h"
#include "io/core/readers.h"
#include "io/core/tract_reader.h"

namespace {

std::string scratchPath(const std::uint8_t* data, std::size_t size) {
  const bool gz = size >= 2 && data[0] == 0x1f && data[1] == 0x8b;
  const char* ext = TG_FUZZ_FORMAT == 0   ? ".nrrd"
                    : TG_FUZZ_FORMAT == 1 ? (gz ? ".nii.gz" : ".nii")
                    : TG_FUZZ_FORMAT == 2 ? ".vtk"
                    : TG_FUZZ_FORMAT == 3 ? ".mif"
                    : TG_FUZZ_FORMAT == 4 ? ".vtu"
                    : TG_FUZZ_FORMAT == 5 ? ".tck"
                                          : ".trk";
  return "/tmp/tg_fuzz_" + std::to_string(::getpid()) + ext;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = scratchPath(data, size);
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data, 1, size, f);
    std::fclose(f);
  } else {
    return 0;
  }
  try {
    if (TG_FUZZ_FORMAT == 0) tg::io::nrrdDataFiles(path);
  } catch (const tg::io::InputError&) {
  }
  try {
    if (TG_FUZZ_FORMAT == 0) tg::io::readNrrd(path, {});
    else if (TG_FUZZ_FORMAT == 1) tg::io::readNifti(path, {});
    else if (TG_FUZZ_FORMAT == 2) tg::io::checkVtkLegacyHeader(path);  // VTK's body parser is not ours; see README
    else if (TG_FUZZ_FORMAT == 3) tg::io::readMif(path, {});
    else if (TG_FUZZ_FORMAT == 4) tg::io::checkVtkXmlHeader(path);  // VTK's data decoders run only in the guarded child
    else tg::io::readTractsInProcess(path, std::uint64_t(256) << 20);
  } catch (const tg::io::InputError&) {
  }
  if (TG_FUZZ_FORMAT == 3) {
    try {
      const int dims[3] = {2, 2, 2};  // the corpus's masks
      tg::io::readMifScalar(path, dims);
    } catch (const tg::io::InputError&) {
    }
  }
  std::remove(path.c_str());
  return 0;
}
