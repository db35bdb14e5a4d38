// Normal Vector Voting (Page, Sun, Koschan, Paik, Abidi: "Normal Vector Voting: Crease
// Detection and Curvature Estimation on Large, Noisy Meshes", Graphical Models 64, 2002).
//
// Entry point, in the manner of vcglib's tri::UpdateCurvature:
//
//   std::vector<nvv::VertexResult> res;
//   nvv::Summary sum;
//   nvv::Status st = vcg::tri::NormalVectorVoting<MyMesh>::Compute(m, params, res, sum, cb);
//
// Inputs:  m       any vcglib triangle mesh (read only: the mesh is never modified)
//          params  see params.h (k in mean edge lengths, crease / corner angles, fit, ...)
//          cb      progress, called from the calling thread only; returning false cancels
// Outputs: res     one VertexResult per slot of m.vert (deleted slots are Invalid)
//          sum     counts per class, ranges, radius, timings, warnings about the input
// On refusal or cancellation res is empty and the Status says why.
//
// Pass 1 (normal_votes.h) classifies every vertex and gives its normal, and crease bands are
// thinned to their ridge (crease_thinning.h, by default with the ridge fit of ridge_fit.h);
// pass 2 gives the curvature of SURFACE vertices (sheet_fit.h, fitted Params::fitRounds times;
// or the paper's votes, curvature_votes.h) and of CREASE lines (crease_curvature.h). Each pass is
// parallel over vertices (OpenMP); every vertex's result depends only on pass-1 results and its
// own march, so any thread count gives the same bits.
#ifndef NVV_CORE_NORMAL_VECTOR_VOTING_H
#define NVV_CORE_NORMAL_VECTOR_VOTING_H

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ball_flood.h"
#include "crease_curvature.h"
#include "crease_thinning.h"
#include "curvature_votes.h"
#include "geodesic_march.h"
#include "huge_pages.h"
#include "normal_votes.h"
#include "params.h"
#include "ridge_fit.h"
#include "sheet_fit.h"
#include "surface_graph.h"
#include "threads.h"
#include "vertex_result.h"

namespace nvv {

// Progress in percent with a short text; return false to cancel. A vcg::CallBackPos*
// converts to it.
typedef std::function<bool(int, const char*)> Progress;

struct Status {
  bool ok = false;
  bool cancelled = false;
  std::string message;  // why it was refused, empty when ok
};

namespace detail {

// Shared progress / cancellation state of one parallel pass. Only thread 0 (the caller's
// thread) calls the user's callback: GUIs pump their event loop inside it.
class PassProgress {
 public:
  PassProgress(const Progress& cb, int n, int percentFrom, int percentTo, const char* text)
      : cb_(cb), n_(n), from_(percentFrom), to_(percentTo), text_(text) {}
  bool Cancelled() const { return cancelled_.load(std::memory_order_relaxed); }
  void Cancel() { cancelled_.store(true); }
  // Called by each thread after every few vertices (`count` of them since its last call).
  void Tick(bool mainThread, int count) {
    const int done = done_.fetch_add(count, std::memory_order_relaxed) + count;
    if (!mainThread || !cb_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    const int percent = from_ + int((to_ - from_) * double(done) / std::max(1, n_));
    if (!cb_(percent, text_)) Cancel();
  }

 private:
  const Progress& cb_;
  const int n_, from_, to_;
  const char* text_;
  std::atomic<int> done_{0};
  std::atomic<bool> cancelled_{false};
  std::chrono::steady_clock::time_point last_{};
};

inline double Seconds(std::chrono::steady_clock::time_point a) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

enum class PassEnd { Done, Cancelled, OutOfMemory };

// Runs body(v, scratch) for every vertex in parallel, one Scratch(g) per thread, in index
// order: consecutive vertices of scanned and generated meshes are near each other, so
// consecutive marches reuse what the last one brought into cache (a breadth-first order was
// measured too: 6 % faster on one thread on the twice-subdivided blade, 8-33 % slower on every
// other run).
template <class Scratch, class Body>
PassEnd ParallelOverVertices(const SurfaceGraph& g, int threads, PassProgress& progress, Body body) {
  const int n = g.VertexCount();
  std::atomic<bool> failed{false};
#pragma omp parallel num_threads(threads)
  {
    try {
      Scratch scratch(g);
      const bool mainThread = ThreadId() == 0;
      // Progress is counted in batches of kTickBatch vertices: one shared atomic add per vertex
      // made the two threads fight over its cache line (and over the cancel flag's beside it)
      // in passes where most vertices have nothing to do, such as the crease pass.
      constexpr int kTickBatch = 16;
      int pending = 0;
#pragma omp for schedule(dynamic, 64)
      for (int v = 0; v < n; ++v) {
        if (progress.Cancelled() || failed.load(std::memory_order_relaxed)) continue;
        body(v, scratch);
        if (++pending == kTickBatch) {
          progress.Tick(mainThread, pending);
          pending = 0;
        }
      }
      if (pending > 0) progress.Tick(mainThread, pending);
    } catch (...) {  // bad_alloc: never let an exception cross the OpenMP region
      failed.store(true);
    }
  }
  if (failed.load()) return PassEnd::OutOfMemory;
  return progress.Cancelled() ? PassEnd::Cancelled : PassEnd::Done;
}

// The Status of a pass that did not finish.
inline Status Unfinished(PassEnd end) {
  Status st;
  st.cancelled = end == PassEnd::Cancelled;
  st.message = st.cancelled ? "Cancelled." : "Out of memory: the neighbourhoods did not fit. Try a smaller k.";
  return st;
}

// The flood (quadric fit) and the march (the paper's vote forms) each hold O(n) state per
// thread; a fit round allocates only the one its form uses (a march is 13 bytes per vertex and
// thread: 0.09 x the mesh on two threads, the torus of docs/performance.md).
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

struct RidgeScratch {
  explicit RidgeScratch(const SurfaceGraph& g) : flood(g) {}
  BallFlood flood;
  std::vector<Eigen::Vector3d> xyz;
};

// The kink's F statistic a ridge must reach (ridge_fit.h): 3 standard deviations of a kink
// that is only noise.
constexpr double kRidgeMinF = 9.0;

}  // namespace detail

// Both passes on a prepared graph. Results are indexed like the graph's vertices.
inline Status RunNormalVectorVoting(const SurfaceGraph& g, const Params& p, std::vector<VertexResult>& res,
                                    Summary& sum, const Progress& cb = Progress()) {
  using namespace detail;
  const auto t0 = std::chrono::steady_clock::now();
  Status st;
  res.clear();
  sum = Summary();
  sum.vertices = g.pos.size();
  sum.nonFiniteVertices = g.nonFinite;
  sum.unreferencedVertices = g.unreferenced;
  sum.degenerateFaces = g.degenerate;
  sum.droppedFaces = g.dropped;
  sum.consistentlyOriented = g.consistentlyOriented;
  sum.meanEdge = g.meanEdge;
  st.message = ValidateParams(p);
  if (!st.message.empty()) return st;
  if (g.VertexCount() == 0) { st.message = "The mesh is empty."; return st; }
  if (g.FaceCount() == 0) {
    st.message = "The mesh has no usable triangles (a point cloud, or every face is deleted, "
                 "repeats a vertex or has a non-finite coordinate): normal vector voting needs faces.";
    return st;
  }
  if (!(g.maxArea > 0) || !(g.meanEdge > 0) || !std::isfinite(g.meanEdge)) {
    st.message = "Every triangle of the mesh has zero area: there is no surface to vote on.";
    return st;
  }

  Pass1Settings s1;
  s1.radius = p.absoluteRadius > 0 ? p.absoluteRadius : p.k * g.meanEdge;
  s1.sigma = p.sigmaFraction * s1.radius;
  s1.epsilon = EpsilonFromAngle(p.creaseAngleDeg);
  s1.eta = EpsilonFromAngle(p.cornerAngleDeg);
  s1.signAware = p.classRule == ClassRule::SignAware && g.consistentlyOriented;
  s1.maxNeighbourhood = p.maxNeighbourhood > 0 ? p.maxNeighbourhood : AutoNeighbourhoodCap(s1.radius / g.meanEdge);
  if (!std::isfinite(s1.radius) || !(s1.radius > 0)) {
    st.message = "The neighbourhood radius is not a positive finite number for this mesh.";
    return st;
  }
  sum.radius = s1.radius;
  sum.epsilon = s1.epsilon;
  sum.eta = s1.eta;
  sum.signAwareUsed = s1.signAware;
  if (p.classRule == ClassRule::SignAware && !g.consistentlyOriented)
    sum.warnings.push_back("The faces are not consistently oriented: the paper's classification rule "
                           "was used instead of the sign-aware one (creases above 120 degrees may be missed).");

  const int threads = ThreadCount(p.threads);
  std::vector<VertexResult> out;
  AssignOnHugePages(out, g.VertexCount());

  // Progress: pass 1 and each fit round of pass 2 get an equal share.
  const int rounds = p.fit == CurvatureFit::SheetQuadric ? p.fitRounds : 1;
  const int share = 100 / (1 + rounds);

  // Pass 1: classes and normals.
  {
    PassProgress prog(cb, g.VertexCount(), 0, share, "Normal vector voting: normals and classes");
    const PassEnd end = ParallelOverVertices<GeodesicMarch>(g, threads, prog, [&](int v, GeodesicMarch& march) {
      VoteNormal(g, march, v, s1, out[v]);
    });
    if (end != PassEnd::Done) return Unfinished(end);
  }
  if (p.thinCreases && p.ridgeFit) {
    std::vector<RidgeScore> ridge;
    AssignOnHugePages(ridge, g.VertexCount());
    const double floorRss = 1e-12 * g.meanEdge * g.meanEdge;
    const double phi = DegToRad(p.creaseAngleDeg);
    // Two to three edge lengths: a smaller ball holds too few heights for the fit's four
    // unknowns, and in a larger one a curved ridge (the capped cylinder's rims at k = 5) is no
    // longer a straight line.
    const double ridgeRadius = std::min(std::max(s1.radius, 2.0 * g.meanEdge), 3.0 * g.meanEdge);
    PassProgress prog(cb, g.VertexCount(), share, share, "Normal vector voting: crease ridges");
    const PassEnd end = ParallelOverVertices<RidgeScratch>(g, threads, prog, [&](int v, RidgeScratch& sc) {
      if (!IsFeature(out[v])) return;
      sc.flood.Run(v, ridgeRadius, s1.maxNeighbourhood);
      // Two frames are fitted and the stronger kink kept: pass 1's normal, and the ball's mean
      // normal (the bisector of a crease's two sheets; in the frame of one sheet's normal, which
      // pass 1's E1 often is, the other sheet of a 90 deg crease is vertical).
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (int x : sc.flood.Reached()) mean += g.RingNormalSum(x);
      RidgeFitResult fit;
      for (const Eigen::Vector3d& axis : {ToVec(out[v].normal), mean}) {
        if (!(axis.squaredNorm() > 0)) continue;
        const TangentFrame F(axis.normalized());
        sc.xyz.clear();
        for (int x : sc.flood.Reached()) {
          const Eigen::Vector3d d = g.pos[x] - g.pos[v];
          sc.xyz.emplace_back(F.e1.dot(d), F.e2.dot(d), F.n.dot(d));
        }
        const RidgeFitResult f = FitRidge(F, sc.xyz, floorRss * double(sc.xyz.size()));
        if (f.ok && (!fit.ok || f.F > fit.F)) fit = f;
      }
      if (!fit.ok || fit.alphaRad < phi || fit.F < kRidgeMinF) return;
      ridge[v].F = float(fit.F);
      ridge[v].alphaRad = float(fit.alphaRad);
      for (int j = 0; j < 3; ++j) ridge[v].tangent[j] = float(fit.tangent[j]);
    });
    if (end != PassEnd::Done) return Unfinished(end);
    sum.thinned = ThinCreaseBandByRidgeFit(g, out, ridge, threads, p.creaseAngleDeg);
  } else if (p.thinCreases) {
    sum.thinned = ThinCreaseBand(g, out, threads, p.creaseAngleDeg);
  }
  sum.secondsPass1 = Seconds(t0);
  const auto t1 = std::chrono::steady_clock::now();

  // Pass 2: curvature of surface vertices, curvature along creases. With fitRounds > 1 the
  // quadric fit runs again: round r reads the normals round r - 1 fitted (slopeNormal) and
  // writes its own (fittedNormal); only the last round's curvature is kept. Every round reads
  // only the previous round's values, so any thread count still gives the same bits.
  // The last round writes no normals, so two rounds need one array (12 bytes per vertex).
  std::vector<std::array<float, 3>> slopeNormal, fittedNormal;
  const double cosPhi = std::cos(DegToRad(p.creaseAngleDeg));
  const double slopeWeight = 2.0 * g.meanEdge;
  auto notSurface = [&](int x) { return out[x].cls != VertexClass::Surface; };
  // Vertices on the mesh's border (an edge of one face). A fit with the border within half its
  // radius has one-sided samples, as beside a crease, and gets no cubic either: fitted there,
  // the cubic's extrapolation to v tilts the normal, and the next rounds carry that inwards
  // (docs/accuracy.md, "Borders": clean 32 x 32 sphere at k = 5, curvature p90 0.036 -> 0.019 %;
  // cylinder at 1 % noise, k = 5, curvature p90 0.72 -> 0.56 %). Where the border is only
  // reached at the rim of the ball, the cubic stays: no cubic wherever the ball reaches the
  // border also took it from fits that needed it (irregular sphere at 20 % noise, k = 8,
  // curvature median 1.11 -> 1.47 %; at three quarters of the radius 1.29 %).
  std::vector<std::uint8_t> onBorder;
  const double nearBorder2 = 0.25 * s1.radius * s1.radius;  // (g_m / 2)^2
  if (p.fit == CurvatureFit::SheetQuadric && p.cubicFit) {
    AssignOnHugePages(onBorder, g.VertexCount(), std::uint8_t(0));
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
    for (int v = 0; v < g.VertexCount(); ++v) onBorder[v] = g.OnBorder(v);
  }
  for (int round = 0; round < rounds; ++round) {
    const bool last = round == rounds - 1;
    if (!last) AssignOnHugePages(fittedNormal, g.VertexCount());
    const std::string text = rounds == 1 ? std::string("Normal vector voting: curvature")
        : "Normal vector voting: curvature, fit " + std::to_string(round + 1) + " of " + std::to_string(rounds);
    PassProgress prog(cb, g.VertexCount(), share * (1 + round), last ? 100 : share * (2 + round), text.c_str());
    // The normal the fit of this round uses for vertex x: pass 1's, then the previous round's.
    auto normalOf = [&](int x) {
      return round == 0 ? ToVec(out[x].normal) : ToVec(slopeNormal[x].data());
    };
    const PassEnd end = ParallelOverVertices<Pass2Scratch>(g, threads, prog,
        [&](int v, Pass2Scratch& sc) {
      VertexResult& r = out[v];
      if (r.cls != VertexClass::Surface) return;
      const Eigen::Vector3d Nv = normalOf(v).normalized();
      const TangentFrame F(Nv);
      PrincipalCurvatures pc;
      if (p.fit == CurvatureFit::SheetQuadric) {
        // The fit needs M_v but no distances: the ball flood finds it (ball_flood.h).
        BallFlood& flood = sc.Flood();
        const bool complete = p.stopAtCreases ? flood.Run(v, s1.radius, s1.maxNeighbourhood, notSurface)
                                              : flood.Run(v, s1.radius, s1.maxNeighbourhood);
        if (!complete) r.flags |= kNeighbourhoodCapped;
        sc.samples.clear();
        bool oneSided = false;  // the neighbourhood reaches a crease, or the border is near
        for (int x : flood.Reached()) {
          if (out[x].cls != VertexClass::Surface) { oneSided = true; continue; }
          if (!onBorder.empty() && onBorder[x] && (g.pos[x] - g.pos[v]).squaredNorm() < nearBorder2) oneSided = true;
          sc.samples.push_back({g.pos[x] - g.pos[v], normalOf(x)});
        }
        pc = SheetQuadricFit(F, sc.samples, s1.radius, slopeWeight, cosPhi, p.cubicFit && !oneSided, !last);
        if (!last) {  // hand the fitted normal (or, if the fit failed, this round's) to the next round
          const Eigen::Vector3d n = pc.ok ? pc.normal : Nv;
          for (int j = 0; j < 3; ++j) fittedNormal[v][j] = float(n[j]);
          return;
        }
      } else {
        GeodesicMarch& march = sc.March();
        const bool complete = p.stopAtCreases ? march.Run(v, s1.radius, s1.maxNeighbourhood, notSurface)
                                              : march.Run(v, s1.radius, s1.maxNeighbourhood);
        if (!complete) r.flags |= kNeighbourhoodCapped;
        sc.votes.clear();
        for (int x : march.Reached()) {
          if (x == v || out[x].cls != VertexClass::Surface) continue;
          const double gi = march.Distance(x);
          CurvatureVote vote;
          if (CurvatureVoteOf(F, g.pos[x] - g.pos[v], ToVec(out[x].normal), gi, std::exp(-gi / s1.sigma), vote))
            sc.votes.push_back(vote);
        }
        pc = p.fit == CurvatureFit::PaperTaubin ? TaubinFromVotes(F, sc.votes) : EulerFromVotes(F, sc.votes);
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
    if (end != PassEnd::Done) return Unfinished(end);
    if (!last) slopeNormal.swap(fittedNormal);
  }
  // Curvature along creases (par. 6.5) needs distances, so a march; in a pass of its own, so a
  // thread never holds the march and the fits' flood at once. It reads pass-1 fields only.
  if (std::any_of(out.begin(), out.end(), [](const VertexResult& r) { return r.cls == VertexClass::Crease; })) {
    PassProgress prog(cb, g.VertexCount(), 100, 100, "Normal vector voting: curvature along creases");
    const PassEnd end = ParallelOverVertices<GeodesicMarch>(g, threads, prog, [&](int v, GeodesicMarch& march) {
      VertexResult& r = out[v];
      if (r.cls != VertexClass::Crease) return;
      if (!march.Run(v, s1.radius, s1.maxNeighbourhood)) r.flags |= kNeighbourhoodCapped;
      r.creaseCurvature = float(CreaseCurvature(march, out, v, s1.sigma));
    });
    if (end != PassEnd::Done) return Unfinished(end);
  }
  sum.secondsPass2 = Seconds(t1);
  // Fitted normals are written after the pass, so every fit saw only the previous round's normals.
  // (SheetQuadricFit's refined normal is recomputed here cheaply from t1 x t2.)
  bool first = true;
  for (auto& r : out) {
    ++sum.perClass[int(r.cls)];
    if (r.Has(kNeighbourhoodCapped)) ++sum.capped;
    if (!r.Has(kCurvatureValid)) continue;
    if (p.fit == CurvatureFit::SheetQuadric) {
      const Eigen::Vector3d n = ToVec(r.t1).cross(ToVec(r.t2)).normalized();
      for (int j = 0; j < 3; ++j) r.normal[j] = float(n[j]);
    }
    if (first) { sum.k1Min = sum.k1Max = r.k1; sum.k2Min = sum.k2Max = r.k2; first = false; }
    sum.k1Min = std::min<double>(sum.k1Min, r.k1);
    sum.k1Max = std::max<double>(sum.k1Max, r.k1);
    sum.k2Min = std::min<double>(sum.k2Min, r.k2);
    sum.k2Max = std::max<double>(sum.k2Max, r.k2);
  }
  if (sum.capped > 0)
    sum.warnings.push_back(std::to_string(sum.capped) + " vertices reached the neighbourhood cap of " +
                           std::to_string(s1.maxNeighbourhood) + " vertices; their neighbourhood was truncated.");
  if (g.nonFinite > 0)
    sum.warnings.push_back(std::to_string(g.nonFinite) + " vertices have non-finite coordinates and were left out.");
  if (g.unreferenced > 0)
    sum.warnings.push_back(std::to_string(g.unreferenced) + " vertices belong to no face and were left unclassified.");
  if (g.degenerate > 0)
    sum.warnings.push_back(std::to_string(g.degenerate) + " faces have zero area and cast no vote.");
  if (g.dropped > 0)
    sum.warnings.push_back(std::to_string(g.dropped) + " faces repeat a vertex or touch a non-finite one and were ignored.");
  res.swap(out);
  sum.secondsTotal = Seconds(t0);
  st.ok = true;
  return st;
}

}  // namespace nvv

namespace vcg {
namespace tri {

template <class MeshType>
class NormalVectorVoting {
 public:
  static nvv::Status Compute(const MeshType& m, const nvv::Params& p, std::vector<nvv::VertexResult>& res,
                             nvv::Summary& sum, const nvv::Progress& cb = nvv::Progress()) {
    // An absurd thread count is refused by the run below; until then the graph must not try it.
    const int graphThreads = nvv::ValidateParams(p).empty() ? p.threads : 1;
    nvv::SurfaceGraph g;
    nvv::BuildSurfaceGraph(m, g, graphThreads);
    return nvv::RunNormalVectorVoting(g, p, res, sum, cb);
  }
};

}  // namespace tri
}  // namespace vcg

#endif
