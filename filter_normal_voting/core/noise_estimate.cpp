#include "noise_estimate.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "sharp_edges.h"
#include "small_ldlt.h"
#include "tangent_frame.h"
#include "threads.h"
#include "tuning.h"

namespace nvv {
namespace {

// The residual standard deviation of a quadratic height field over v's two-ring, or -1 where the
// two-ring is too small or degenerate to fit.
double TwoRingResidual(const SurfaceGraph& g, int v, std::vector<int>& ring) {
  ring.clear();
  for (int i = g.FaceBegin(v); i < g.FaceEnd(v); ++i)
    for (int x : g.face[g.vfList[i]]) ring.push_back(x);
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  const std::size_t oneRing = ring.size();
  for (std::size_t j = 0; j < oneRing; ++j)
    for (int i = g.FaceBegin(ring[j]); i < g.FaceEnd(ring[j]); ++i)
      for (int x : g.face[g.vfList[i]]) ring.push_back(x);
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  const int n = int(ring.size());
  if (n < tuning::kNoiseMinSamples) return -1;
  const Eigen::Vector3d normal = g.RingNormalSum(v);
  if (!(normal.squaredNorm() > 0)) return -1;
  const TangentFrame frame(normal.normalized());
  const Eigen::Vector3d& o = g.pos[v];
  // Normal equations in units of l_ave (conditioning), heights too.
  const double s = 1.0 / g.meanEdge;
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
  for (int x : ring) {
    const Eigen::Vector3d d = (g.pos[x] - o) * s;
    const double u = frame.e1.dot(d), w = frame.e2.dot(d), z = frame.n.dot(d);
    Eigen::Matrix<double, 6, 1> r;
    r << u * u, u * w, w * w, u, w, 1.0;
    A.selfadjointView<Eigen::Lower>().rankUpdate(r);
    b += z * r;
  }
  A = A.selfadjointView<Eigen::Lower>();
  const SmallLdlt<6> ldlt(A);
  if (!ldlt.PivotsWithin(tuning::kNoiseFitPivotRatio)) return -1;
  const Eigen::Matrix<double, 6, 1> c = ldlt.Solve(b);
  double rss = 0;  // summed directly: z'z - c'b cancels on clean meshes
  for (int x : ring) {
    const Eigen::Vector3d d = (g.pos[x] - o) * s;
    const double u = frame.e1.dot(d), w = frame.e2.dot(d), z = frame.n.dot(d);
    const double e = z - (c[0] * u * u + c[1] * u * w + c[2] * w * w + c[3] * u + c[4] * w + c[5]);
    rss += e * e;
  }
  return std::sqrt(rss / double(n - 6));
}

}  // namespace

NoiseEstimate EstimateNoise(const SurfaceGraph& g, int threads) {
  NoiseEstimate est;
  const int nv = g.VertexCount();
  if (nv == 0 || !(g.meanEdge > 0)) return est;
  const int stride = std::max(1, nv / tuning::kNoiseSamples);
  const int count = (nv + stride - 1) / stride;
  std::vector<double> sigma(std::size_t(count), -1.0);
#pragma omp parallel num_threads(ThreadCount(threads))
  {
    std::vector<int> ring;
#pragma omp for schedule(dynamic, 256)
    for (int i = 0; i < count; ++i) {
      const int v = i * stride;
      if (g.Referenced(v) && !g.OnBorder(v)) sigma[std::size_t(i)] = TwoRingResidual(g, v, ring);
    }
  }
  sigma.erase(std::remove_if(sigma.begin(), sigma.end(), [](double x) { return !(x >= 0); }), sigma.end());
  est.samples = int(sigma.size());
  const MeshNoiseAngles angles = MeasureNoiseAngles(g);
  est.noiseAngle = angles.scaled;
  est.fromDihedrals = angles.unscaled / tuning::kNoiseAnglePerSigma;
  if (sigma.empty()) {
    est.sigmaOverEdge = est.fromDihedrals;
    return est;
  }
  const std::size_t q = std::size_t(tuning::kNoiseQuantile * double(sigma.size() - 1));
  std::nth_element(sigma.begin(), sigma.begin() + std::ptrdiff_t(q), sigma.end());
  est.fromTwoRings = tuning::kNoiseQuantileScale * sigma[q];
  est.sigmaOverEdge = std::min(est.fromTwoRings, est.fromDihedrals);
  return est;
}

double AutoK(double sigmaOverEdge) {
  const double t = (sigmaOverEdge - tuning::kAutoKLowNoise) / (tuning::kAutoKHighNoise - tuning::kAutoKLowNoise);
  return tuning::kAutoKMin + (tuning::kAutoKMax - tuning::kAutoKMin) * std::min(1.0, std::max(0.0, t));
}

}  // namespace nvv
