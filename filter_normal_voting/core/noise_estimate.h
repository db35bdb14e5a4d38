// How noisy a mesh is along its normals, and the neighbourhood size that noise asks for.
//
// Noise: at a sample of vertices (every vertex up to kNoiseSamples, evenly strided beyond), a
// quadratic height field z = a x^2 + b xy + c y^2 + d x + e y + f is fitted by least squares to
// the vertex's two-ring in the frame of its one-ring normal; the fit absorbs the surface's
// curvature, so what is left over, sqrt(RSS / (N - 6)), is the noise of those heights. Creases and
// corners leave far larger residuals, so the estimate is a low quantile of the samples
// (kNoiseQuantile, a quarter: robust to half the samples lying near features), scaled to the
// standard deviation by the quantile's calibration on noisy planes (kNoiseQuantileScale), and
// given in units of the mean edge length l_ave, as the benchmarks' noise is. On a coarse CAD
// tessellation every two-ring spans a crease or a curved face cut into strips and this reads far
// too high; there the lowest tenth of the dihedral angles (sharp_edges.h's unscaled noise angle,
// exactly 0 on a CAD export) over its value per unit noise on noisy planes is the lower, and the
// estimate is the lower of the two (each reads high where it fails, neither low). The noise angle
// scaled by the faces' heights, which the sharp edges read, comes nearer the noise on export meshes
// but read 14-18 % high on the CAD parts' Delaunay meshes at 5 % and 25 % low on the ribs at 20 %
// (recalibrated on the regular plane): not used here.
//
// Automatic k (Params::autoK): k = 3 up to kAutoKLowNoise, rising linearly to kAutoKMax at
// kAutoKHighNoise and staying there (docs/accuracy.md, "Which k", measures it against k = 3).
#ifndef NVV_CORE_NOISE_ESTIMATE_H
#define NVV_CORE_NOISE_ESTIMATE_H

#include "surface_graph.h"

namespace nvv {

struct NoiseEstimate {
  double sigmaOverEdge = 0;  // standard deviation of the noise along the normals / l_ave: the lower of
  double fromTwoRings = 0;   // the two-rings' residuals (curvature absorbed; too high where features fill every two-ring)
  double fromDihedrals = 0;  // and the mesh's unscaled noise angle (sharp_edges.h; too high on curved meshes, 0 on CAD exports)
  double noiseAngle = 0;     // the noise angle scaled by the faces' heights (radians), which the sharp edges read
  int samples = 0;           // vertices whose two-ring was fitted
};

// Deterministic for any thread count (the samples are fixed, each written to its own slot).
NoiseEstimate EstimateNoise(const SurfaceGraph& g, int threads);

// The k that automatic k chooses for noise sigma / l_ave.
double AutoK(double sigmaOverEdge);

}  // namespace nvv

#endif
