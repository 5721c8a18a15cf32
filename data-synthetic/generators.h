#pragma once
// Synthetic tensor fields with known structure, for tests, demos and benchmarks.
#include <cstdint>
#include <string>

#include "io/field/tensor_field.h"
#include "util/progress.h"

namespace tg::synth {

// A tube of linear tensors along a two-turn helix in an isotropic background,
// on a grid whose axes are rotated (non-identity space directions). Tensors
// are in WC; `measurementFrame` (row-major) is the frame writeNrrd stores them in.
struct Helix {
  io::TensorField field;
  double measurementFrame[9];
};
Helix helixPhantom(int nx, int ny, int nz);

// Boussinesq's point load P on an elastic half-space (Timoshenko & Goodier,
// "Theory of Elasticity", 3rd ed., §138): stress at depth z > 0 below the
// surface, tension positive. Indefinite tensors; P = 1, Poisson ratio nu.
io::TensorField boussinesq(int n, double nu);
// The same stress at one point (x, y, z), z > 0; row-major 3x3.
void boussinesqStress(double x, double y, double z, double nu, double out[9]);

// Kirsch's plate with a circular hole of radius a = 1 under uniaxial tension
// S = 100 along x (plane stress; Timoshenko & Goodier, §35), on an n x n
// grid over [-4, 4]^2 in the plane z = 0: zero tensors inside the hole. The
// hoop stress reaches 3S = 300 at (0, ±1) and -S at (±1, 0).
io::TensorField kirschPlate(int n);
// The same stress at one point (x, y) with r >= a; xx xy xz yy yz zz.
void kirschStress(double x, double y, double out6[6]);

// A row per family: needles, disks, spheres, eigenvalue ratios 1e1..1e6, zero,
// negative and all-negative eigenvalues, in several orientations. Eigenvalues
// are multiplied by eigenScale and positions by positionScale.
io::TensorField extremesGallery(double eigenScale, double positionScale);

// N random positive-definite tensors on a cubic grid (uniform random
// orientation, eigenvalues in [0.1, 1]); reproducible from `seed`.
io::TensorField randomField(std::size_t n, std::uint64_t seed);

// The same field written straight to NRRD (detached .nhdr + .raw) in chunks,
// never holding more than one chunk: for N up to 1e8 and beyond. `progress`
// hears ("writing", done, N, "tensors") once per chunk.
void writeRandomNrrdStreaming(const std::string& nhdrPath, std::size_t n, std::uint64_t seed,
                              const util::ProgressSink& progress = {});

}  // namespace tg::synth
