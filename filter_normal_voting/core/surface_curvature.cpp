#include "surface_curvature.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>

#include "ball_flood.h"
#include "curvature_votes.h"
#include "geodesic_march.h"
#include "huge_pages.h"
#include "sheet_fit.h"
#include "tangent_frame.h"
#include "tuning.h"

namespace nvv {
namespace {

// A thread's scratch. The flood (quadric fit) and the march (the paper's vote forms) each hold
// O(n) state; a pass allocates only the one its form uses.
struct Pass2Scratch {
  explicit Pass2Scratch(const SurfaceGraph& graph) : g(graph) {}
  BallFlood& Flood() {
    if (!flood) flood.reset(new BallFlood(g));
    return *flood;
  }
  GeodesicMarch& March() {
    if (!march) march.reset(new GeodesicMarch(g));
    return *march;
  }
  const SurfaceGraph& g;
  std::unique_ptr<BallFlood> flood;
  std::unique_ptr<GeodesicMarch> march;
  std::vector<CurvatureVote> votes;
  std::vector<SheetSample> samples;
};

typedef std::vector<std::array<float, 3>> NormalArray;

// What one pass of pass 2 reads. The neighbours' classes and normals are read from compact
// arrays (1 and 12 bytes per vertex) rather than from the 80-byte results: a ball's samples lie
// scattered in memory, and each such read is a cache miss on a large mesh.
struct CurvatureRound {
  const SurfaceGraph& g;
  const Params& p;
  const Pass1Settings& s;
  std::vector<VertexResult>& out;  // pass-1 classes; each vertex writes only its own
  const std::vector<std::uint8_t>& surface;   // 1 where pass 1 (and thinning) left a surface vertex
  const NormalArray& normals;      // pass 1's normals in the first round, then the previous round's
  const std::vector<std::uint8_t>& onBorder;  // empty where no fit may take the cubic
  double cosPhi, slopeWeight, nearBorder2;
  bool last;

  // The normal this round's fit uses for vertex x.
  Eigen::Vector3d NormalOf(int x) const { return ToVec(normals[x].data()); }
  bool NotSurface(int x) const { return !surface[x]; }
};

// Whether v's same-sheet samples can support the fitted curvatures. No circle through v and a
// sample at distance d is tighter than radius d / 2, so a principal curvature above
// kMaxCurvatureOverNearest / d_near (d_near: the nearest sample) came from the fit's freedom, not
// from the samples; and samples along one line (the tangent spread's smaller axis below
// kFitMinSpread of the larger) leave the curvature across that line free. Both happen on a
// surface vertex shut in between close creases or beside a micro-step (fandisk: one vertex whose
// four samples lie on a line fitted k1 = 1084, 45 / l_ave): such a vertex gets no curvature.
bool SupportedByNeighbourhood(const TangentFrame& F, const std::vector<SheetSample>& samples,
                              const PrincipalCurvatures& pc) {
  double nearest2 = std::numeric_limits<double>::infinity();
  double suu = 0, suv = 0, svv = 0;
  for (const auto& s : samples) {
    const double d2 = s.d.squaredNorm();
    if (!(d2 > 0)) continue;  // v itself
    nearest2 = std::min(nearest2, d2);
    const double u = F.e1.dot(s.d), w = F.e2.dot(s.d);
    suu += u * u;
    suv += u * w;
    svv += w * w;
  }
  if (!std::isfinite(nearest2)) return false;
  // Eigenvalues of [[suu, suv], [suv, svv]]: the spread of the samples over the tangent plane.
  const double mean = 0.5 * (suu + svv), dev = std::sqrt(0.25 * (suu - svv) * (suu - svv) + suv * suv);
  if (!(mean - dev >= tuning::kFitMinSpread * (mean + dev))) return false;
  const double bound = tuning::kMaxCurvatureOverNearest / std::sqrt(nearest2);
  return std::abs(pc.k1) <= bound && std::abs(pc.k2) <= bound;
}

// The quadric fit of v over its same-sheet ball. The fit needs the ball but no distances, so the
// flood finds it (ball_flood.h). A fit whose ball reaches a crease, or whose border is within
// tuning::kBorderCubicFraction of g_m, is one-sided and gets no cubic.
PrincipalCurvatures FitByQuadric(const CurvatureRound& R, int v, const TangentFrame& F, Pass2Scratch& sc,
                                 bool& capped) {
  const SurfaceGraph& g = R.g;
  BallFlood& flood = sc.Flood();
  capped = !(R.p.stopAtCreases ? flood.Run(v, R.s.radius, R.s.maxNeighbourhood, [&](int x) { return R.NotSurface(x); })
                               : flood.Run(v, R.s.radius, R.s.maxNeighbourhood));
  sc.samples.clear();
  bool oneSided = false;
  for (int x : flood.Reached()) {
    if (R.NotSurface(x)) { oneSided = true; continue; }
    if (!R.onBorder.empty() && R.onBorder[x] && (g.pos[x] - g.pos[v]).squaredNorm() < R.nearBorder2) oneSided = true;
    // Written in place: a sample built on the stack and copied in was read back across its two
    // halves' stores, a store-forwarding stall that was a sixth of the fit rounds' own time.
    sc.samples.emplace_back();
    SheetSample& sample = sc.samples.back();
    sample.d = g.pos[x] - g.pos[v];
    const std::array<float, 3>& n = R.normals[x];
    sample.n.x() = n[0];
    sample.n.y() = n[1];
    sample.n.z() = n[2];
  }
  PrincipalCurvatures pc = SheetQuadricFit(F, sc.samples, R.s.radius, R.slopeWeight, R.cosPhi,
                                           R.p.cubicFit && !oneSided, !R.last, R.p.levers);
  if (pc.ok && !SupportedByNeighbourhood(F, sc.samples, pc)) pc.ok = false;
  return pc;
}

// The paper's curvature votes (Eq. 13-17) of v's geodesic neighbourhood, as Taubin's matrix or
// Euler's least squares.
PrincipalCurvatures FitByVotes(const CurvatureRound& R, int v, const TangentFrame& F, Pass2Scratch& sc, bool& capped) {
  const SurfaceGraph& g = R.g;
  GeodesicMarch& march = sc.March();
  capped = !(R.p.stopAtCreases ? march.Run(v, R.s.radius, R.s.maxNeighbourhood, [&](int x) { return R.NotSurface(x); })
                               : march.Run(v, R.s.radius, R.s.maxNeighbourhood));
  sc.votes.clear();
  for (int x : march.Reached()) {
    if (x == v || R.NotSurface(x)) continue;
    const double gi = march.Distance(x);
    CurvatureVote vote;
    if (CurvatureVoteOf(F, g.pos[x] - g.pos[v], R.NormalOf(x), gi, VoteWeight(gi, R.s.sigma), vote))
      sc.votes.push_back(vote);
  }
  return R.p.fit == CurvatureFit::PaperTaubin ? TaubinFromVotes(F, sc.votes) : EulerFromVotes(F, sc.votes);
}

// Vertices on the mesh's border (an edge of one face), where the cubic may be taken; empty
// where it never is.
std::vector<std::uint8_t> BorderVertices(const SurfaceGraph& g, const Params& p, int threads) {
  std::vector<std::uint8_t> onBorder;
  if (p.fit == CurvatureFit::SheetQuadric && p.cubicFit) {
    AssignOnHugePages(onBorder, g.VertexCount(), std::uint8_t(0));
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
    for (int v = 0; v < g.VertexCount(); ++v) onBorder[v] = g.OnBorder(v);
  }
  return onBorder;
}

// One pass over the surface vertices: a fit round of the quadric fit (writing the fitted normal
// to `fitted` in rounds before the last) or the paper's votes.
PassEnd CurvaturePass(const CurvatureRound& R, int threads, PassProgress& progress, NormalArray* fitted) {
  return ParallelOverVertices<Pass2Scratch>(R.g, threads, progress, [&](int v, Pass2Scratch& sc) {
    if (R.NotSurface(v)) return;
    VertexResult& r = R.out[v];
    const Eigen::Vector3d Nv = R.NormalOf(v).normalized();
    const TangentFrame F(Nv);
    bool capped = false;
    const bool quadric = R.p.fit == CurvatureFit::SheetQuadric;
    const PrincipalCurvatures pc = quadric ? FitByQuadric(R, v, F, sc, capped) : FitByVotes(R, v, F, sc, capped);
    if (capped) r.flags |= kNeighbourhoodCapped;
    if (quadric && !R.last) {  // hand the fitted normal (or, if the fit failed, this round's) to the next round
      const Eigen::Vector3d n = pc.ok ? pc.normal : Nv;
      for (int j = 0; j < 3; ++j) (*fitted)[v][j] = float(n[j]);
      return;
    }
    if (!pc.ok) return;
    r.k1 = float(pc.k1);
    r.k2 = float(pc.k2);
    for (int j = 0; j < 3; ++j) {
      r.t1[j] = float(pc.t1[j]);
      r.t2[j] = float(pc.t2[j]);
    }
    r.flags |= kCurvatureValid;
  });
}

// The quadric fit's refined normal, t1 x t2, written once every round is done.
void WriteFittedNormals(std::vector<VertexResult>& out) {
  for (auto& r : out) {
    if (!r.Has(kCurvatureValid)) continue;
    const Eigen::Vector3d n = ToVec(r.t1).cross(ToVec(r.t2)).normalized();
    for (int j = 0; j < 3; ++j) r.normal[j] = float(n[j]);
  }
}

}  // namespace

int CurvatureRounds(const Params& p) { return p.fit == CurvatureFit::SheetQuadric ? p.fitRounds : 1; }

PassEnd FitSurfaceCurvature(const SurfaceGraph& g, const Params& p, const Pass1Settings& s, int threads,
                            const Progress& cb, int firstPercent, int perRound, std::vector<VertexResult>& out) {
  const int rounds = CurvatureRounds(p);
  const std::vector<std::uint8_t> onBorder = BorderVertices(g, p, threads);
  const double nearBorder = tuning::kBorderCubicFraction * s.radius;
  // The surface flags and pass 1's normals in compact arrays (CurvatureRound); the rounds then
  // need one more normal array (12 bytes per vertex): the last round writes no normals.
  std::vector<std::uint8_t> surface;
  NormalArray previous, fitted;
  AssignOnHugePages(surface, g.VertexCount(), std::uint8_t(0));
  AssignOnHugePages(previous, g.VertexCount());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int v = 0; v < g.VertexCount(); ++v) {
    surface[v] = out[v].cls == VertexClass::Surface;
    for (int j = 0; j < 3; ++j) previous[v][j] = out[v].normal[j];
  }
  const double cosSheet = std::cos(DegToRad(std::max(p.creaseAngleDeg, tuning::kFitSampleAngleFloorDeg)));
  for (int round = 0; round < rounds; ++round) {
    const bool last = round == rounds - 1;
    if (!last) AssignOnHugePages(fitted, g.VertexCount());
    const CurvatureRound R{g, p, s, out, surface, previous, onBorder, cosSheet, tuning::kSlopeWeightEdges * g.meanEdge,
                           nearBorder * nearBorder, last};
    const std::string text = rounds == 1 ? std::string("Normal vector voting: curvature")
        : "Normal vector voting: curvature, fit " + std::to_string(round + 1) + " of " + std::to_string(rounds);
    PassProgress progress(cb, g.VertexCount(), firstPercent + perRound * round,
                          last ? 100 : firstPercent + perRound * (round + 1), text.c_str());
    const PassEnd end = CurvaturePass(R, threads, progress, &fitted);
    if (end != PassEnd::Done) return end;
    if (!last) previous.swap(fitted);
  }
  if (p.fit == CurvatureFit::SheetQuadric) WriteFittedNormals(out);
  return PassEnd::Done;
}

}  // namespace nvv
