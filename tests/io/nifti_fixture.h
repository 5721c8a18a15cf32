#pragma once
// Tensor NIfTI files as the tools write them, through libnifti2: any affine,
// six values per voxel in any order, 4-D (FSL, MRtrix, DIPY's scripts) or
// 5-D with the SYMMATRIX intent (DIPY's workflow), and a `descrip`.
#include <gtest/gtest.h>
#include <nifti2_io.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace tg::test {

struct NiftiTensors {
  int dims[3] = {1, 1, 1};
  double affine[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  bool symmatrix = false;  // 5-D (x y z 1 6) with the SYMMATRIX intent, else 4-D (x y z 6)
  std::string descrip;
  std::vector<std::array<float, 6>> voxels;  // six values per voxel, in stored order, i fastest
};

inline void writeNifti(const std::filesystem::path& path, const NiftiTensors& fx) {
  const int64_t dims[8] = {fx.symmatrix ? 5 : 4, fx.dims[0], fx.dims[1], fx.dims[2],
                           fx.symmatrix ? 1 : 6, fx.symmatrix ? 6 : 1, 1, 1};
  nifti_image* nim = nifti_make_new_nim(dims, NIFTI_TYPE_FLOAT32, 1);
  ASSERT_TRUE(nim);
  const std::size_t n = std::size_t(fx.dims[0]) * std::size_t(fx.dims[1]) * std::size_t(fx.dims[2]);
  ASSERT_EQ(fx.voxels.size(), n);
  auto* data = static_cast<float*>(nim->data);
  for (std::size_t v = 0; v < n; ++v)
    for (std::size_t c = 0; c < 6; ++c) data[c * n + v] = fx.voxels[v][c];
  nim->sform_code = NIFTI_XFORM_SCANNER_ANAT;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) nim->sto_xyz.m[r][c] = r < 3 ? fx.affine[r][c] : (c == 3 ? 1 : 0);
  if (fx.symmatrix) nim->intent_code = NIFTI_INTENT_SYMMATRIX;
  std::strncpy(nim->descrip, fx.descrip.c_str(), sizeof nim->descrip - 1);
  const std::string prefix = path.string();
  ASSERT_EQ(nifti_set_filenames(nim, prefix.c_str(), 0, 1), 0);
  nifti_image_write(nim);
  nifti_image_free(nim);
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
}

}  // namespace tg::test
