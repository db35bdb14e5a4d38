#include "normal_votes.h"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <memory>

#include "ball_flood.h"
#include "tuning.h"

namespace nvv {
namespace {

// The vote of one triangle (Eq. 6) with its weight (Eq. 8) added to V and to the oriented mean m;
// `distance(f, N, |c - v|)` is g_i, given the triangle's corners, normal and centroid distance.
template <class Distance>
void AddTriangleVote(const SurfaceGraph& g, int v, int fi, const Pass1Settings& s, Distance distance,
                     Eigen::Matrix3d& V, Eigen::Vector3d& m) {
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
  const double gi = distance(f, N, len);
  const double w = (area / g.maxArea) * VoteWeight(gi, s.sigma);
  V.noalias() += w * Ni * Ni.transpose();
  m += w * Ni;
}

// The votes of v's neighbourhood (Eq. 7): every triangle whose three vertices the neighbourhood
// holds, counted once (from its lowest-numbered vertex), and v's one-ring always (its far
// vertices may lie beyond a small g_m).
template <class Ball, class Distance>
void TallyVotes(const SurfaceGraph& g, const Ball& ball, int v, const Pass1Settings& s, Distance distance,
                Eigen::Matrix3d& V, Eigen::Vector3d& m) {
  V.setZero();
  m.setZero();
  for (int x : ball.Reached()) {
    for (int i = g.FaceBegin(x); i < g.FaceEnd(x); ++i) {
      const int fi = g.vfList[i];
      const auto& f = g.face[fi];
      // The index test first: it needs no scratch load and rejects two of every three visits.
      if (x != std::min(f[0], std::min(f[1], f[2]))) continue;
      if (!ball.IsReached(f[0]) || !ball.IsReached(f[1]) || !ball.IsReached(f[2])) continue;
      AddTriangleVote(g, v, fi, s, distance, V, m);
    }
  }
  for (int i = g.FaceBegin(v); i < g.FaceEnd(v); ++i) {
    const int fi = g.vfList[i];
    const auto& f = g.face[fi];
    if (ball.IsReached(f[0]) && ball.IsReached(f[1]) && ball.IsReached(f[2])) continue;
    AddTriangleVote(g, v, fi, s, distance, V, m);
  }
}

// The votes' eigen-analysis: eigenvalues over their trace and eigenvectors, in the sign-aware
// order (ALGORITHM.md): of the two largest, the one along the oriented mean vote comes first, so
// at a crease beyond 90 deg the bisector is first and S_s < 0. False where no triangle voted.
struct VoteTensor {
  double l[3];
  Eigen::Vector3d E[3];
  Eigen::Vector3d m;
  double Ss() const { return l[0] - l[1]; }
  double Sc() const { return l[1] - l[2]; }
  double Sn() const { return std::max(0.0, l[2]); }
};
bool Analyse(Eigen::Matrix3d V, Eigen::Vector3d m, const Pass1Settings& s, VoteTensor& t) {
  const double trace = V.trace();
  if (!(trace > 0) || !std::isfinite(trace)) return false;
  V /= trace;  // eigenvalues then sum to 1; classification only uses their ratios
  t.m = m / trace;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(V);
  for (int j = 0; j < 3; ++j) {
    t.l[j] = es.eigenvalues()(2 - j);
    t.E[j] = es.eigenvectors().col(2 - j);
  }
  if (s.signAware && std::abs(t.E[1].dot(t.m)) > std::abs(t.E[0].dot(t.m))) {
    std::swap(t.l[0], t.l[1]);
    std::swap(t.E[0], t.E[1]);
  }
  return true;
}

// Eq. 10's class, the normal oriented by the one-ring (ringNormal: SurfaceGraph::RingNormalSum),
// and the crease's tangent and cusp.
void Classify(const Eigen::Vector3d& ringNormal, const Pass1Settings& s, const VoteTensor& t, VertexResult& r) {
  for (int j = 0; j < 3; ++j) r.lambda[j] = float(std::max(0.0, t.l[j]));
  const double Ss = t.Ss(), Sc = t.Sc(), Sn = t.Sn();
  if (SurfaceByEq10(Ss, Sc, Sn, s.epsilon, s.eta)) r.cls = VertexClass::Surface;
  else if (s.epsilon * Sc >= s.epsilon * s.eta * Sn) r.cls = VertexClass::Crease;
  else r.cls = VertexClass::Corner;

  // Orient E1 with the area-weighted one-ring normal (falls back to the mean vote).
  Eigen::Vector3d n = t.E[0];
  const Eigen::Vector3d ref = ringNormal.squaredNorm() > 0 ? ringNormal : t.m;
  if (n.dot(ref) < 0) n = -n;
  for (int j = 0; j < 3; ++j) r.normal[j] = float(n[j]);
  if (r.cls != VertexClass::Corner) r.flags |= kNormalValid;
  if (r.cls == VertexClass::Crease) {
    for (int j = 0; j < 3; ++j) r.creaseTangent[j] = float(t.E[2][j]);
    // Two sheets of equal weight: l2 / l1 = tan^2(alpha / 2) (par. 6.5).
    const double l0 = std::max(t.l[0], 1e-300), l1 = std::max(0.0, t.l[1]);
    r.cuspAngle = float(2.0 * std::atan(std::sqrt(l1 / l0)));
    r.flags |= kCreaseValid;
  }
}

// A thread's scratch: the flood of the Euclidean ball, and the march where the flood's votes do
// not settle the class.
struct Pass1Scratch {
  explicit Pass1Scratch(const SurfaceGraph& graph) : g(graph), flood(graph) {}
  GeodesicMarch& March() {
    if (!march) march.reset(new GeodesicMarch(g));
    return *march;
  }
  const SurfaceGraph& g;
  BallFlood flood;
  std::unique_ptr<GeodesicMarch> march;
};

// Pass 1 for v. First over the Euclidean ball (the flood), with Euclidean distances to the
// triangles' centroids in Eq. 8: on a smooth sheet the two balls differ by g^3 / (24 R^2). Where
// those votes say surface with tuning::kFloodSurfaceMargin to spare and no face of the ball turns
// far from v's one-ring normal (tuning::kFloodTurnOfCreaseAngle), that is v's result. Beside a
// crease the other sheet lies nearer in space than along the surface, so the Euclidean votes make
// v look more like a crease and tilt its normal: every vertex they do not settle (a crease, a
// corner, a surface vertex without the margin or near another sheet, a ball that hit the cap) is
// voted again over the geodesic neighbourhood of par. 6.1, the paper's form.
void VoteNormal(const SurfaceGraph& g, Pass1Scratch& sc, int v, const Pass1Settings& s, VertexResult& r) {
  r = VertexResult();
  if (!g.usable[v] || !g.Referenced(v)) return;
  Eigen::Matrix3d V;
  Eigen::Vector3d m;
  VoteTensor t;
  const Eigen::Vector3d ringSum = g.RingNormalSum(v);
  if (s.floodFirst && ringSum.squaredNorm() > 0 && sc.flood.Run(v, s.radius, s.maxNeighbourhood)) {
    // The most a voting triangle's normal turns from v's one-ring normal: a ball that reaches
    // another sheet (or bends as much) is left to the march.
    const Eigen::Vector3d ring = ringSum.normalized();
    double leastCos = 1;
    TallyVotes(g, sc.flood, v, s, [&](const std::array<int, 3>&, const Eigen::Vector3d& N, double centroidDistance) {
      leastCos = std::min(leastCos, N.dot(ring));
      return centroidDistance;
    }, V, m);
    if (!Analyse(V, m, s, t)) return;  // no usable triangle: stays Invalid (the march sees no more)
    const double margin = tuning::kFloodSurfaceMargin;
    if (leastCos >= s.cosFloodTurn && SurfaceByEq10(t.Ss(), t.Sc(), t.Sn(), margin * s.epsilon, margin * s.eta)) {
      Classify(ringSum, s, t, r);
      return;
    }
  }
  GeodesicMarch& march = sc.March();
  if (!march.Run(v, s.radius, s.maxNeighbourhood)) r.flags |= kNeighbourhoodCapped;
  TallyVotes(g, march, v, s, [&march](const std::array<int, 3>& f, const Eigen::Vector3d&, double) {
    return (march.Distance(f[0]) + march.Distance(f[1]) + march.Distance(f[2])) / 3.0;
  }, V, m);
  if (!Analyse(V, m, s, t)) return;  // no usable triangle: stays Invalid
  Classify(ringSum, s, t, r);
}

}  // namespace

PassEnd VoteNormals(const SurfaceGraph& g, const Pass1Settings& s, int threads, PassProgress& progress,
                    std::vector<VertexResult>& out) {
  return ParallelOverVertices<Pass1Scratch>(g, threads, progress, [&](int v, Pass1Scratch& sc) {
    VoteNormal(g, sc, v, s, out[v]);
  });
}

}  // namespace nvv
