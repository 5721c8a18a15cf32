#include <teem/biff.h>
#include <teem/nrrd.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

#include "data-synthetic/generators.h"
#include "data-synthetic/random_tensors.h"
#include "io/atomic_file.h"

namespace tg::synth {

void writeRandomNrrdStreaming(const std::string& nhdrPath, std::size_t n, std::uint64_t seed) {
  const std::filesystem::path hp(nhdrPath);
  if (hp.extension() != ".nhdr") throw std::runtime_error("writeRandomNrrdStreaming: " + nhdrPath + ": needs .nhdr");
  if (n == 0) throw std::runtime_error("writeRandomNrrdStreaming: " + nhdrPath + ": N must be positive");
  const GridDims dims = gridDims(n);
  const std::string rawName = hp.stem().string() + ".raw";
  const std::string rawPath = (hp.parent_path() / rawName).string();

  // Data first, in 1M-tensor chunks, to a temporary file.
  io::AtomicOutput raw(rawPath);
  {
    std::unique_ptr<FILE, int (*)(FILE*)> out(std::fopen(raw.tempPath().c_str(), "wb"), &std::fclose);
    if (!out) throw std::runtime_error("writeRandomNrrdStreaming: " + rawPath + ": cannot create");
    RandomTensorStream rs(seed);
    constexpr std::size_t kChunk = 1 << 20;
    std::vector<float> buf(6 * kChunk);
    for (std::size_t done = 0; done < n;) {
      const std::size_t m = std::min(kChunk, n - done);
      for (std::size_t i = 0; i < m; ++i) rs.next(&buf[6 * i]);
      if (std::fwrite(buf.data(), sizeof(float), 6 * m, out.get()) != 6 * m)
        throw std::runtime_error("writeRandomNrrdStreaming: " + rawPath + ": write failed (disk full?)");
      done += m;
    }
    if (std::fflush(out.get()) != 0) throw std::runtime_error("writeRandomNrrdStreaming: " + rawPath + ": write failed");
  }

  // The header, by Teem, without data: it points at the final data file name.
  Nrrd* nrrd = nrrdNew();
  float placeholder = 0;  // never read: skipData
  const std::size_t sizes[4] = {6, dims.x, dims.y, dims.z};
  const int kinds[4] = {nrrdKind3DSymMatrix, nrrdKindSpace, nrrdKindSpace, nrrdKindSpace};
  const double spacings[4] = {AIR_NAN, 1.0, 1.0, 1.0};
  NrrdIoState* nio = nrrdIoStateNew();
  nio->detachedHeader = AIR_TRUE;
  nio->skipData = AIR_TRUE;
  nio->encoding = nrrdEncodingRaw;
  const unsigned idx = airArrayLenIncr(nio->dataFNArr, 1);
  nio->dataFN[idx] = airStrdup(rawName.c_str());
  io::AtomicOutput header(nhdrPath);
  int err = nrrdWrap_nva(nrrd, &placeholder, nrrdTypeFloat, 4, sizes);
  if (!err) {
    nrrdAxisInfoSet_nva(nrrd, nrrdAxisInfoKind, kinds);
    nrrdAxisInfoSet_nva(nrrd, nrrdAxisInfoSpacing, spacings);
    err = nrrdSave(header.tempPath().c_str(), nrrd, nio);
  }
  nrrdIoStateNix(nio);
  nrrdNix(nrrd);
  if (err) {
    char* e = biffGetDone(NRRD);
    const std::string msg = e ? e : "Teem error";
    std::free(e);
    throw std::runtime_error("writeRandomNrrdStreaming: " + nhdrPath + ": " + msg);
  }
  raw.commit();
  header.commit();
}

}  // namespace tg::synth
