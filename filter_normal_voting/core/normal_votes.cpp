#include "normal_votes.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace nvv {
namespace {

// The vote of one triangle (Eq. 6) with its weight (Eq. 8) added to V and to the oriented mean m.
void AddTriangleVote(const SurfaceGraph& g, const GeodesicMarch& march, int v, int fi,
                            const Pass1Settings& s, Eigen::Matrix3d& V, Eigen::Vector3d& m) {
  const double area = g.faceArea[fi];
  if (!(area > 0)) return;
  const auto& f = g.face[fi];
  const Eigen::Vector3d& N = g.faceNormal[fi];
  const Eigen::Vector3d c = (g.pos[f[0]] + g.pos[f[1]] + g.pos[f[2]]) / 3.0;
  const Eigen::Vector3d d = c - g.pos[v];
  const double len = d.norm();
  Eigen::Vector3d Ni = N;
  if (len > 0) {
    const Eigen::Vector3d u = d / len;
    Ni = N + 2.0 * (-N.dot(u)) * u;
  }
  const double gi = (march.Distance(f[0]) + march.Distance(f[1]) + march.Distance(f[2])) / 3.0;
  const double w = (area / g.maxArea) * VoteWeight(gi, s.sigma);
  V.noalias() += w * Ni * Ni.transpose();
  m += w * Ni;
}

}  // namespace

void VoteNormal(const SurfaceGraph& g, GeodesicMarch& march, int v, const Pass1Settings& s,
                       VertexResult& r) {
  r = VertexResult();
  if (!g.usable[v] || !g.Referenced(v)) return;
  if (!march.Run(v, s.radius, s.maxNeighbourhood)) r.flags |= kNeighbourhoodCapped;

  Eigen::Matrix3d V = Eigen::Matrix3d::Zero();
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  // Every triangle with three reached vertices, counted once: from its lowest-numbered vertex.
  for (int x : march.Reached()) {
    for (int i = g.FaceBegin(x); i < g.FaceEnd(x); ++i) {
      const int fi = g.vfList[i];
      const auto& f = g.face[fi];
      // The index test first: it needs no scratch load and rejects two of every three visits.
      if (x != std::min(f[0], std::min(f[1], f[2]))) continue;
      if (!march.IsReached(f[0]) || !march.IsReached(f[1]) || !march.IsReached(f[2])) continue;
      AddTriangleVote(g, march, v, fi, s, V, m);
    }
  }
  // The one-ring always votes (its far vertices may lie beyond a small g_m).
  for (int i = g.FaceBegin(v); i < g.FaceEnd(v); ++i) {
    const int fi = g.vfList[i];
    const auto& f = g.face[fi];
    if (march.IsReached(f[0]) && march.IsReached(f[1]) && march.IsReached(f[2])) continue;
    AddTriangleVote(g, march, v, fi, s, V, m);
  }
  const double trace = V.trace();
  if (!(trace > 0) || !std::isfinite(trace)) return;  // no usable triangle: stays Invalid
  V /= trace;  // eigenvalues then sum to 1; classification only uses their ratios
  m /= trace;

  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(V);
  double l[3] = {es.eigenvalues()(2), es.eigenvalues()(1), es.eigenvalues()(0)};
  Eigen::Vector3d E[3] = {es.eigenvectors().col(2), es.eigenvectors().col(1), es.eigenvectors().col(0)};
  // Sign-aware order (ALGORITHM.md): of the two largest, the one along the oriented mean vote
  // comes first. At a crease beyond 90 deg this puts the bisector first, so S_s < 0.
  if (s.signAware && std::abs(E[1].dot(m)) > std::abs(E[0].dot(m))) {
    std::swap(l[0], l[1]);
    std::swap(E[0], E[1]);
  }
  for (int j = 0; j < 3; ++j) r.lambda[j] = float(std::max(0.0, l[j]));

  const double Ss = l[0] - l[1], Sc = l[1] - l[2], Sn = std::max(0.0, l[2]);
  if (SurfaceByEq10(Ss, Sc, Sn, s.epsilon, s.eta)) r.cls = VertexClass::Surface;
  else if (s.epsilon * Sc >= s.epsilon * s.eta * Sn) r.cls = VertexClass::Crease;
  else r.cls = VertexClass::Corner;

  // Orient E1 with the area-weighted one-ring normal (falls back to the mean vote).
  Eigen::Vector3d n = E[0];
  const Eigen::Vector3d ringNormal = g.RingNormalSum(v);
  const Eigen::Vector3d ref = ringNormal.squaredNorm() > 0 ? ringNormal : m;
  if (n.dot(ref) < 0) n = -n;
  for (int j = 0; j < 3; ++j) r.normal[j] = float(n[j]);
  if (r.cls != VertexClass::Corner) r.flags |= kNormalValid;
  if (r.cls == VertexClass::Crease) {
    for (int j = 0; j < 3; ++j) r.creaseTangent[j] = float(E[2][j]);
    // Two sheets of equal weight: l2 / l1 = tan^2(alpha / 2) (par. 6.5).
    const double l0 = std::max(l[0], 1e-300), l1 = std::max(0.0, l[1]);
    r.cuspAngle = float(2.0 * std::atan(std::sqrt(l1 / l0)));
    r.flags |= kCreaseValid;
  }
}

PassEnd VoteNormals(const SurfaceGraph& g, const Pass1Settings& s, int threads, PassProgress& progress,
                    std::vector<VertexResult>& out) {
  return ParallelOverVertices<GeodesicMarch>(g, threads, progress, [&](int v, GeodesicMarch& march) {
    VoteNormal(g, march, v, s, out[v]);
  });
}

}  // namespace nvv
