#include <teem/biff.h>
#include <teem/nrrd.h>

#include <memory>
#include <stdexcept>

#include "io/modules/teem/nrrd_save.h"
#include "io/modules/teem/teem_util.h"
#include "io/core/format_impl.h"

namespace tg::io {

std::int64_t impl::writeNrrd(const TensorField& f, const std::string& path, int fd, const double m[9]) {
  if (!f.grid) throw std::runtime_error("writeNrrd: " + path + ": field has no grid");
  const GridInfo& g = *f.grid;
  const std::size_t n = std::size_t(g.dims[0]) * g.dims[1] * g.dims[2];
  if (n != f.size()) throw std::runtime_error("writeNrrd: " + path + ": grid is incomplete");
  // Into the measurement frame: D_stored = Mᵀ D_world M.
  const double mt[9] = {m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]};
  std::vector<float> data(6 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const double d[6] = {f.tensors[6 * i], f.tensors[6 * i + 1], f.tensors[6 * i + 2],
                         f.tensors[6 * i + 3], f.tensors[6 * i + 4], f.tensors[6 * i + 5]};
    double out[6];
    congruence(mt, d, out);
    for (int k = 0; k < 6; ++k) data[6 * i + k] = float(out[k]);
  }
  Nrrd* nrrd = nrrdNew();
  auto done = [&] { nrrdNix(nrrd); };
  const std::size_t sizes[4] = {6, std::size_t(g.dims[0]), std::size_t(g.dims[1]), std::size_t(g.dims[2])};
  if (nrrdWrap_nva(nrrd, data.data(), nrrdTypeFloat, 4, sizes) || nrrdSpaceSet(nrrd, nrrdSpaceRightAnteriorSuperior) ||
      nrrdSpaceOriginSet(nrrd, g.origin)) {
    done();
    throw std::runtime_error("writeNrrd: " + path + ": " + teemNrrdError());
  }
  const int kinds[4] = {nrrdKind3DSymMatrix, nrrdKindSpace, nrrdKindSpace, nrrdKindSpace};
  nrrdAxisInfoSet_nva(nrrd, nrrdAxisInfoKind, kinds);
  double dirs[NRRD_DIM_MAX][NRRD_SPACE_DIM_MAX];
  for (int k = 0; k < 3; ++k) dirs[0][k] = AIR_NAN;
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < 3; ++k) dirs[a + 1][k] = g.directions[k * 3 + a] * g.spacing[a];
  nrrdAxisInfoSet_nva(nrrd, nrrdAxisInfoSpaceDirection, dirs);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) nrrd->measurementFrame[c][r] = m[r * 3 + c];  // Teem: [column][row]
  NrrdIoState* nio = nrrdIoStateNew();
  nio->encoding = nrrdEncodingGzip;
  std::int64_t size = 0;
  try {
    size = writeNrrdTo(fd, path, nrrd, nio, "writeNrrd");
  } catch (...) {
    nrrdIoStateNix(nio);
    done();
    throw;
  }
  nrrdIoStateNix(nio);
  done();
  return size;
}

std::int64_t impl::writeRawTensorHeader(const std::string& path, int fd, const std::size_t dims[3],
                                        const std::string& dataFile, const std::string& caller) {
  std::unique_ptr<Nrrd, Nrrd* (*)(Nrrd*)> nrrd(nrrdNew(), nrrdNix);
  std::unique_ptr<NrrdIoState, NrrdIoState* (*)(NrrdIoState*)> nio(nrrdIoStateNew(), nrrdIoStateNix);
  // nrrdWrap needs a data pointer to describe the grid; with skipData Teem
  // writes the header alone and never reads it.
  float unreadValue = 0;
  const std::size_t sizes[4] = {6, dims[0], dims[1], dims[2]};
  const int kinds[4] = {nrrdKind3DSymMatrix, nrrdKindSpace, nrrdKindSpace, nrrdKindSpace};
  const double spacings[4] = {AIR_NAN, 1.0, 1.0, 1.0};
  nio->detachedHeader = AIR_TRUE;
  nio->skipData = AIR_TRUE;
  nio->encoding = nrrdEncodingRaw;
  const unsigned idx = airArrayLenIncr(nio->dataFNArr, 1);
  nio->dataFN[idx] = airStrdup(dataFile.c_str());
  if (nrrdWrap_nva(nrrd.get(), &unreadValue, nrrdTypeFloat, 4, sizes))
    throw std::runtime_error(caller + ": " + path + ": Teem cannot describe the grid");
  nrrdAxisInfoSet_nva(nrrd.get(), nrrdAxisInfoKind, kinds);
  nrrdAxisInfoSet_nva(nrrd.get(), nrrdAxisInfoSpacing, spacings);
  return writeNrrdTo(fd, path, nrrd.get(), nio.get(), caller);
}

}  // namespace tg::io
