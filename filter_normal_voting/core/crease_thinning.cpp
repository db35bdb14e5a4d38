#include "crease_thinning.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "ball_flood.h"
#include "huge_pages.h"
#include "ridge_fit.h"
#include "tangent_frame.h"
#include "tuning.h"

namespace nvv {
namespace {

using tuning::kCosAcrossLine;
using tuning::kCosSameLine;

// True when a one-ring neighbour u of v with a score (score(u) > 0; ties go to the lower index,
// so two equal neighbours do not remove each other) at least v's lies across v's line T (the
// edge v->u at least 37 deg from T: |cos| < cosAcross). A neighbour whose own line (lineOf(u);
// zero when it has none) is more than 45 deg off T lies on another crease (two creases meeting
// at a corner) and is not compared. With T zero (a corner) every stronger neighbour counts: a
// corner must be the strongest feature of its one-ring.
template <class Score, class Line>
bool StrongerNeighbourAcross(const SurfaceGraph& g, int v, const Eigen::Vector3d& T, Score score, Line lineOf,
                             double cosAcross = kCosAcrossLine) {
  const float mine = score(v);
  for (int i = g.FaceBegin(v); i < g.FaceEnd(v); ++i)
    for (int u : g.face[g.vfList[i]]) {
      if (u == v) continue;
      const float theirs = score(u);
      if (!(theirs > 0) || theirs < mine || (theirs == mine && u > v)) continue;
      if (T.squaredNorm() == 0) return true;
      const Eigen::Vector3d Tu = lineOf(u);
      if (Tu.squaredNorm() > 0 && std::abs(Tu.dot(T)) < kCosSameLine) continue;
      if (std::abs((g.pos[u] - g.pos[v]).normalized().dot(T)) < cosAcross) return true;
    }
  return false;
}

// True when feature vertex v is not the ridge of its band, scored by FeatureStrength.
bool OffRidge(const SurfaceGraph& g, const std::vector<VertexResult>& res, int v) {
  const Eigen::Vector3d T = res[v].cls == VertexClass::Crease ? ToVec(res[v].creaseTangent) : Eigen::Vector3d::Zero();
  return StrongerNeighbourAcross(g, v, T,
      [&](int u) { return IsFeature(res[u]) ? std::max(FeatureStrength(res[u]), 1e-30f) : 0.0f; },
      [&](int u) { return res[u].cls == VertexClass::Crease ? ToVec(res[u].creaseTangent) : Eigen::Vector3d::Zero(); });
}

// True when CREASE vertex v lies on a crease of the mesh itself: at least two of its edges
// (v, x) run along v's crease tangent and have faces whose normals are more than the sharp angle
// apart (cosSharp). Two aligned edges are required so that a noisy flank's one odd edge does not
// veto its thinning. Corners are never vetoed.
bool OnSharpEdge(const SurfaceGraph& g, const std::vector<VertexResult>& res, int v, double cosSharp) {
  if (res[v].cls != VertexClass::Crease) return false;
  const Eigen::Vector3d T = ToVec(res[v].creaseTangent);
  int sharp = 0;
  for (int i = g.FaceBegin(v); i < g.FaceEnd(v); ++i) {
    const int f = g.vfList[i];
    if (!(g.faceArea[f] > 0)) continue;
    for (int x : g.face[f]) {
      if (x == v || !(std::abs((g.pos[x] - g.pos[v]).normalized().dot(T)) > kCosAcrossLine)) continue;
      const int third = g.face[f][0] + g.face[f][1] + g.face[f][2] - v - x;
      g.ForEachFaceAcross(f, v, x, [&](int o) {  // each face pair once, from its lower face
        const auto& t = g.face[o];
        const bool duplicate = t[0] == third || t[1] == third || t[2] == third;  // f again: no edge neighbour
        if (o > f && !duplicate && g.faceArea[o] > 0 && g.faceNormal[f].dot(g.faceNormal[o]) < cosSharp) ++sharp;
      });
      if (sharp >= 2) return true;
    }
  }
  return false;
}

// Median over the mesh's interior edges of the angle (radians) between the normals of the two
// faces sharing it: 0 on a clean CAD mesh, a few degrees on a noisy scan. Estimated from the
// edges of a bounded number of evenly spread faces.
double MedianEdgeAngle(const SurfaceGraph& g) {
  std::vector<float> angles;
  g.ForEachSampledEdgePair([&](int f, int o, int, int) {
    angles.push_back(float(std::acos(std::max(-1.0, std::min(1.0, g.faceNormal[f].dot(g.faceNormal[o]))))));
  });
  if (angles.empty()) return 0;
  std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
  return angles[angles.size() / 2];
}

// cos of the angle above which a mesh edge is sharp: the crease angle, or a multiple of the
// median edge angle on noisy meshes (tuning.h).
double CosSharpEdgeAngle(const SurfaceGraph& g, double creaseAngleDeg) {
  const double sharpAngle = std::max(DegToRad(creaseAngleDeg), tuning::kSharpOverMedianEdgeAngle * MedianEdgeAngle(g));
  return std::cos(std::min(sharpAngle, DegToRad(tuning::kSharpAngleMaxDeg)));
}

// True when ridge candidate v is not the ridge of its band: a one-ring candidate across v's
// fitted line whose own line is within 45 deg of v's has a larger F.
bool OffFittedRidge(const SurfaceGraph& g, const std::vector<RidgeScore>& ridge, int v) {
  auto line = [&](int u) { return ToVec(ridge[u].tangent.data()); };
  return StrongerNeighbourAcross(g, v, line(v), [&](int u) { return ridge[u].F; }, line);
}

// What the ridge-fit form does with a feature vertex.
enum RidgeAction : std::uint8_t { kKeep = 0, kDemote = 1, kCornerToCrease = 2 };

// Keep a feature vertex where it is on a sharp mesh edge, or where its ridge fit found a kink,
// no candidate across its line has a larger F, and no sharp-edge crease lies across it within
// 45 deg of its line (it is that crease's flank). A kept corner that is not the strongest
// feature of its one-ring becomes a crease along its fitted line.
std::vector<std::uint8_t> RidgeActions(const SurfaceGraph& g, const std::vector<VertexResult>& res,
                                       const std::vector<RidgeScore>& ridge, int threads, double cosSharp) {
  const int n = g.VertexCount();
  std::vector<std::uint8_t> sharp(n, 0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int v = 0; v < n; ++v)
    if (IsFeature(res[v])) sharp[v] = OnSharpEdge(g, res, v, cosSharp);
  auto lineOf = [&](int u) { return ridge[u].F > 0 ? ToVec(ridge[u].tangent.data()) : ToVec(res[u].creaseTangent); };
  auto sharpScore = [&](int u) { return sharp[u] ? 1.0f : 0.0f; };
  std::vector<std::uint8_t> action(n, kKeep);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int v = 0; v < n; ++v) {
    if (!IsFeature(res[v])) continue;
    const bool ridgeHere = ridge[v].F > 0;
    const bool keep = sharp[v] || (ridgeHere && !ridge[v].rounded && !ridge[v].chamferMiddle &&
                                   !OffFittedRidge(g, ridge, v) &&
                                   !StrongerNeighbourAcross(g, v, lineOf(v), sharpScore, lineOf, kCosSameLine));
    if (!keep) action[v] = kDemote;
    else if (res[v].cls == VertexClass::Corner && OffRidge(g, res, v)) action[v] = kCornerToCrease;
  }
  return action;
}

// Where two fitted ridges meet (a cube's corner) the fit of the meeting vertex sees three sheets
// and loses to its neighbours: a vertex to demote that lies on the lines of two kept crease
// neighbours more than 45 deg apart is kept as a corner.
std::vector<std::uint8_t> CornersWhereRidgesMeet(const SurfaceGraph& g, const std::vector<VertexResult>& res,
                                                 const std::vector<RidgeScore>& ridge,
                                                 const std::vector<std::uint8_t>& action, int threads) {
  const int n = g.VertexCount();
  std::vector<std::uint8_t> corner(n, 0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int v = 0; v < n; ++v) {
    if (action[v] != kDemote) continue;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    for (int i = g.FaceBegin(v); i < g.FaceEnd(v) && !corner[v]; ++i)
      for (int u : g.face[g.vfList[i]]) {
        if (u == v || action[u] == kDemote || res[u].cls != VertexClass::Crease || !(ridge[u].F > 0)) continue;
        const Eigen::Vector3d T = ToVec(ridge[u].tangent.data());
        if (std::abs((g.pos[v] - g.pos[u]).normalized().dot(T)) < kCosAcrossLine) continue;  // v is not on u's line
        if (first.squaredNorm() == 0) first = T;
        else if (std::abs(first.dot(T)) < kCosSameLine) { corner[v] = 1; break; }
      }
  }
  return corner;
}

// The scratch of one thread of ScoreRidges.
struct RidgeScratch {
  explicit RidgeScratch(const SurfaceGraph& g) : flood(g) {}
  BallFlood flood;
  std::vector<Eigen::Vector3d> xyz, bestXyz;  // the ball in a frame; in the stronger fit's
  Eigen::Vector3d bestAxis = Eigen::Vector3d::UnitZ();  // the stronger fit's frame normal
};

// True when Eq. 10 with epsilon = eta = `epsilon` calls r a feature (pass 1's eigenvalues, in
// their sign-aware order): would the votes make v a crease or corner at that angle.
bool VotesFeatureAt(const VertexResult& r, double epsilon) {
  return !SurfaceByEq10(r.lambda[0] - r.lambda[1], r.lambda[1] - r.lambda[2], r.lambda[2], epsilon, epsilon);
}

// True when the mesh is cut much finer at v than on average: a mesher refined the surface there to
// follow a curved profile (a fillet narrower than the neighbourhood, a hole's wall), which a crease
// between two planes does not need.
bool MeshRefinedAt(const SurfaceGraph& g, int v) {
  return g.MeanRingEdge(v) < g.meanEdge / tuning::kRefinedEdgeRatio;
}

// The better of two ridge fits at v: in the frame of pass 1's normal, and of the ball's mean
// normal (the bisector of a crease's two sheets; in the frame of one sheet's normal, which pass
// 1's E1 often is, the other sheet of a 90 deg crease is vertical).
RidgeFitResult StrongerRidgeFit(const SurfaceGraph& g, const VertexResult& r, int v, double floorRss, RidgeScratch& sc) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int x : sc.flood.Reached()) mean += g.RingNormalSum(x);
  RidgeFitResult fit;
  for (const Eigen::Vector3d& axis : {ToVec(r.normal), mean}) {
    if (!(axis.squaredNorm() > 0)) continue;
    const TangentFrame F(axis.normalized());
    sc.xyz.clear();
    for (int x : sc.flood.Reached()) {
      const Eigen::Vector3d d = g.pos[x] - g.pos[v];
      sc.xyz.emplace_back(F.e1.dot(d), F.e2.dot(d), F.n.dot(d));
    }
    const RidgeFitResult f = FitRidge(F, sc.xyz, floorRss * double(sc.xyz.size()));
    if (f.ok && (!fit.ok || f.F > fit.F)) fit = f, sc.bestXyz.swap(sc.xyz), sc.bestAxis = F.n;
  }
  return fit;
}

// The mean dihedral angle (radians) of the mesh edges along `tangent` between two vertices of `line`, and
// their mean length; count: how many.
struct LineEdges {
  double turn = 0, length = 0;
  int count = 0;
};
LineEdges EdgesAlong(const SurfaceGraph& g, const std::vector<int>& line, const Eigen::Vector3d& tangent) {
  LineEdges out;
  for (int a : line)
    for (int i = g.FaceBegin(a); i < g.FaceEnd(a); ++i) {
      const int f = g.vfList[i];
      for (int b : g.face[f]) {
        if (b <= a || std::find(line.begin(), line.end(), b) == line.end()) continue;
        const Eigen::Vector3d d = g.pos[b] - g.pos[a];
        if (std::abs(d.normalized().dot(tangent)) < kCosAcrossLine) continue;
        g.ForEachFaceAcross(f, a, b, [&](int o) {  // each face pair once, from its lower face
          if (o <= f) return;
          // Unsigned: a mesh whose orientation flips there still turns by the smaller angle.
          out.turn += std::acos(std::max(-1.0, std::min(1.0, std::abs(g.faceNormal[f].dot(g.faceNormal[o])))));
          out.length += d.norm();
          ++out.count;
        });
      }
    }
  if (out.count > 0) out.turn /= out.count, out.length /= out.count;
  return out;
}

// A chamfer across v's band (FitChamfer): two kinks at least kChamferMinWidth l_ave apart, each turning
// between kChamferMinTurnDeg and kChamferMaxTurnDeg, which fit the heights within the noise and better
// than any single kink or fillet (SmoothProfileResidual) by kChamferGain times the noise's variance; and
// along each line the mesh itself must turn (its edges there, beyond what noise turns an edge, by
// kChamferEdgeTurn of the fitted angle) on edges of at least kChamferMinEdge l_ave: a CAD mesher puts a
// chamfer's lines on mesh edges and does not refine a flat strip, while a fillet's rows each turn a
// fraction of it and are refined. The ball's vertices within kChamferOnLine l_ave of a line claim a crease
// there (ApplyChamferClaims); v itself, on neither line, is the strip's middle, which thinning removes.
void ChamferLines(const SurfaceGraph& g, int v, const RidgeFitResult& fit, const RidgeScratch& sc, double sigma2,
                  double noiseTurn, std::vector<ChamferClaim>& claims, RidgeScore& score) {
  const ChamferFitResult c = FitChamfer(sc.bestXyz, fit.lineInFrame, g.meanEdge);
  if (!c.ok || c.w2 - c.w1 < tuning::kChamferMinWidth * g.meanEdge) return;
  const double minTurn = DegToRad(tuning::kChamferMinTurnDeg), maxTurn = DegToRad(tuning::kChamferMaxTurnDeg);
  if (std::min(c.alpha1, c.alpha2) < minTurn || std::max(c.alpha1, c.alpha2) > maxTurn) return;
  const int n = int(sc.bestXyz.size());
  if (c.rssTwo > (n - 5) * tuning::kRidgeConfirmNoise * tuning::kRidgeConfirmNoise * sigma2) return;
  // The ball's vertices on each line.
  const double tol = tuning::kChamferOnLine * g.meanEdge;
  const std::vector<int>& reached = sc.flood.Reached();
  std::vector<int> onLine[2];
  for (std::size_t i = 0; i < reached.size(); ++i) {
    const Eigen::Vector3d& q = sc.bestXyz[i];
    const double w = AcrossLine(q, fit.lineInFrame);
    if (std::abs(w - c.w1) < tol) onLine[0].push_back(reached[i]);
    else if (std::abs(w - c.w2) < tol) onLine[1].push_back(reached[i]);
  }
  const double alpha[2] = {c.alpha1, c.alpha2};
  for (int k = 0; k < 2; ++k) {
    const LineEdges e = EdgesAlong(g, onLine[k], fit.tangent);
    if (e.count < 2 || e.turn - noiseTurn < tuning::kChamferEdgeTurn * alpha[k] ||
        e.length < tuning::kChamferMinEdge * g.meanEdge)
      return;
  }
  if (SmoothProfileResidual(sc.bestXyz, fit.lineInFrame, g.meanEdge) - c.rssTwo < tuning::kChamferGain * sigma2) return;
  const TangentFrame F(sc.bestAxis);
  std::vector<ChamferClaim> mine;
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d s = c.sheetNormal[k] + c.sheetNormal[k + 1];
    const Eigen::Vector3d bisector = (s.x() * F.e1 + s.y() * F.e2 + s.z() * F.n).normalized();
    for (int q : onLine[k]) {
      ChamferClaim cl{q, v, {}, {}, float(alpha[k])};
      for (int j = 0; j < 3; ++j) cl.tangent[j] = float(fit.tangent[j]), cl.normal[j] = float(bisector[j]);
      mine.push_back(cl);
    }
  }
  if (std::find(onLine[0].begin(), onLine[0].end(), v) == onLine[0].end() &&
      std::find(onLine[1].begin(), onLine[1].end(), v) == onLine[1].end())
    score.chamferMiddle = true;
#pragma omp critical(nvv_chamfer_claims)
  claims.insert(claims.end(), mine.begin(), mine.end());
}

}  // namespace

int DemoteToSurface(const SurfaceGraph& g, VertexResult& r, int v) {
  Eigen::Vector3d ring = g.RingNormalSum(v);
  if (!(ring.squaredNorm() > 0)) return 0;
  ring.normalize();
  for (int j = 0; j < 3; ++j) r.normal[j] = float(ring[j]);
  r.cls = VertexClass::Surface;
  r.flags = std::uint8_t((r.flags & ~kCreaseValid) | kNormalValid);
  for (int j = 0; j < 3; ++j) r.creaseTangent[j] = 0;
  r.cuspAngle = 0;
  return 1;
}

PassEnd ScoreRidges(const SurfaceGraph& g, const std::vector<VertexResult>& res, const Pass1Settings& s,
                    double creaseAngleDeg, int threads, PassProgress& progress, std::vector<RidgeScore>& ridge,
                    std::vector<ChamferClaim>* claims) {
  AssignOnHugePages(ridge, g.VertexCount());
  const double floorRss = tuning::kRidgeResidualFloor * g.meanEdge * g.meanEdge;
  const double phi = DegToRad(creaseAngleDeg);
  const double confirmEpsilon = EpsilonFromAngle(tuning::kRidgeConfirmAngleDeg);
  const double confirmSigma = std::max(s.noiseSigma, tuning::kRidgeConfirmFloorEdges * g.meanEdge);
  const double confirmMeanSquare = tuning::kRidgeConfirmNoise * tuning::kRidgeConfirmNoise * confirmSigma * confirmSigma;
  const double roundedGain = tuning::kRoundedRidgeGain * confirmSigma * confirmSigma;
  const double chamferSigma2 = confirmSigma * confirmSigma;
  const double noiseTurn = claims ? MedianEdgeAngle(g) : 0;
  const double ridgeRadius =
      std::min(std::max(s.radius, tuning::kRidgeRadiusMin * g.meanEdge), tuning::kRidgeRadiusMax * g.meanEdge);
  return ParallelOverVertices<RidgeScratch>(g, threads, progress, [&](int v, RidgeScratch& sc) {
    if (!IsFeature(res[v])) return;
    sc.flood.Run(v, ridgeRadius, s.maxNeighbourhood);
    const RidgeFitResult fit = StrongerRidgeFit(g, res[v], v, floorRss, sc);
    if (!fit.ok || fit.alphaRad < phi || fit.F < tuning::kRidgeMinF) return;
    // A crease the votes find only below the confirmation angle, or where the mesh is refined, must
    // also be a kink of two planes within the noise.
    if (fit.meanSquareAcross > confirmMeanSquare && (!VotesFeatureAt(res[v], confirmEpsilon) || MeshRefinedAt(g, v)))
      return;
    ridge[v].F = float(fit.F);
    ridge[v].alphaRad = float(fit.alphaRad);
    for (int j = 0; j < 3; ++j) ridge[v].tangent[j] = float(fit.tangent[j]);
    // A fillet narrower than the ball votes like a crease; its heights fit a round profile by many
    // times the noise's variance better. It still suppresses its band's weaker rows (RidgeActions),
    // and is demoted itself.
    ridge[v].rounded = RoundedRidgeGain(sc.bestXyz, fit.lineInFrame, g.meanEdge) > roundedGain;
    if (claims) ChamferLines(g, v, fit, sc, chamferSigma2, noiseTurn, *claims, ridge[v]);
  });
}

namespace {

// Surface vertices claimed by at least kChamferClaims chamfer fits become creases along the first
// claimer's line (claims sorted by vertex, then claimer: the same on any thread count).
std::size_t ApplyChamferClaims(const SurfaceGraph& g, std::vector<VertexResult>& res,
                               std::vector<ChamferClaim>& claims) {
  std::sort(claims.begin(), claims.end(), [](const ChamferClaim& a, const ChamferClaim& b) {
    return a.vertex < b.vertex || (a.vertex == b.vertex && a.by < b.by);
  });
  std::size_t promoted = 0;
  for (std::size_t i = 0; i < claims.size();) {
    std::size_t j = i;
    while (j < claims.size() && claims[j].vertex == claims[i].vertex) ++j;
    VertexResult& r = res[claims[i].vertex];
    if (int(j - i) >= tuning::kChamferClaims && r.cls == VertexClass::Surface && g.usable[claims[i].vertex]) {
      r.cls = VertexClass::Crease;
      r.flags |= kCreaseValid | kNormalValid;
      for (int k = 0; k < 3; ++k) r.creaseTangent[k] = claims[i].tangent[k], r.normal[k] = claims[i].normal[k];
      r.cuspAngle = claims[i].alpha;
      ++promoted;
    }
    i = j;
  }
  return promoted;
}

}  // namespace

PassEnd ThinCreases(const SurfaceGraph& g, const Params& p, const Pass1Settings& s, int threads,
                    PassProgress& progress, std::vector<VertexResult>& res, std::size_t& thinned) {
  thinned = 0;
  if (!p.thinCreases) return PassEnd::Done;
  if (!p.ridgeFit) {
    thinned = ThinCreaseBand(g, res, threads, p.creaseAngleDeg);
    return PassEnd::Done;
  }
  std::vector<RidgeScore> ridge;
  std::vector<ChamferClaim> claims;
  const PassEnd end = ScoreRidges(g, res, s, p.creaseAngleDeg, threads, progress, ridge, &claims);
  if (end != PassEnd::Done) return end;
  thinned = ThinCreaseBandByRidgeFit(g, res, ridge, threads, p.creaseAngleDeg);
  const std::size_t promoted = ApplyChamferClaims(g, res, claims);
  thinned = thinned > promoted ? thinned - promoted : 0;
  return PassEnd::Done;
}

std::size_t ThinCreaseBand(const SurfaceGraph& g, std::vector<VertexResult>& res, int threads, double creaseAngleDeg) {
  const int n = g.VertexCount();
  const double cosSharp = CosSharpEdgeAngle(g, creaseAngleDeg);
  std::vector<std::uint8_t> demote(n, 0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int v = 0; v < n; ++v)
    if (IsFeature(res[v])) demote[v] = OffRidge(g, res, v) && !OnSharpEdge(g, res, v, cosSharp);
  std::size_t count = 0;
  for (int v = 0; v < n; ++v) {
    if (demote[v]) count += DemoteToSurface(g, res[v], v);
  }
  return count;
}

std::size_t CloseCreaseGaps(const SurfaceGraph& g, std::vector<VertexResult>& res, const std::vector<RidgeScore>& ridge,
                            int threads) {
  const int n = g.VertexCount();
  // True when u is a kept ridge crease and v lies on its line; d: the unit edge v -> u.
  auto onLineOf = [&](int v, int u, Eigen::Vector3d& d) {
    if (u == v || res[u].cls != VertexClass::Crease || !(ridge[u].F > 0)) return false;
    d = (g.pos[u] - g.pos[v]).normalized();
    return std::abs(d.dot(ToVec(ridge[u].tangent.data()))) > kCosAcrossLine;
  };
  // The gap's two ends, or -1.
  std::vector<std::array<int, 2>> ends(n, std::array<int, 2>{{-1, -1}});
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int v = 0; v < n; ++v) {
    if (res[v].cls != VertexClass::Surface || !g.usable[v]) continue;
    for (int i = g.FaceBegin(v); i < g.FaceEnd(v) && ends[v][0] < 0; ++i)
      for (int a : g.face[g.vfList[i]]) {
        Eigen::Vector3d da, db;
        if (!onLineOf(v, a, da)) continue;
        const Eigen::Vector3d Ta = ToVec(ridge[a].tangent.data());
        for (int j = g.FaceBegin(v); j < g.FaceEnd(v) && ends[v][0] < 0; ++j)
          for (int b : g.face[g.vfList[j]])
            if (b != a && onLineOf(v, b, db) && da.dot(db) < -kCosAcrossLine &&
                std::abs(Ta.dot(ToVec(ridge[b].tangent.data()))) > kCosSameLine) {
              ends[v] = {{a, b}};
              break;
            }
        if (ends[v][0] >= 0) break;
      }
  }
  std::size_t closed = 0;
  for (int v = 0; v < n; ++v) {
    const int a = ends[v][0], b = ends[v][1];
    if (a < 0) continue;
    VertexResult& r = res[v];
    r.cls = VertexClass::Crease;
    r.flags |= kCreaseValid | kNormalValid;
    const Eigen::Vector3d t = (g.pos[b] - g.pos[a]).normalized();
    for (int j = 0; j < 3; ++j) r.creaseTangent[j] = float(t[j]);
    r.cuspAngle = 0.5f * (ridge[a].alphaRad + ridge[b].alphaRad);
    ++closed;
  }
  return closed;
}

std::size_t ThinCreaseBandByRidgeFit(const SurfaceGraph& g, std::vector<VertexResult>& res,
                                     const std::vector<RidgeScore>& ridge, int threads, double creaseAngleDeg) {
  const int n = g.VertexCount();
  const std::vector<std::uint8_t> action = RidgeActions(g, res, ridge, threads, CosSharpEdgeAngle(g, creaseAngleDeg));
  const std::vector<std::uint8_t> corner = CornersWhereRidgesMeet(g, res, ridge, action, threads);
  std::size_t count = 0;
  for (int v = 0; v < n; ++v) {
    VertexResult& r = res[v];
    if (action[v] == kKeep && r.cls == VertexClass::Crease && ridge[v].F > 0) {
      for (int j = 0; j < 3; ++j) r.creaseTangent[j] = ridge[v].tangent[j];
      continue;
    }
    if (action[v] == kCornerToCrease) {
      r.cls = VertexClass::Crease;
      r.flags |= kCreaseValid | kNormalValid;
      for (int j = 0; j < 3; ++j) r.creaseTangent[j] = ridge[v].tangent[j];
      r.cuspAngle = ridge[v].alphaRad;
      continue;
    }
    if (action[v] != kDemote) continue;
    if (corner[v]) {
      r.cls = VertexClass::Corner;
      r.flags = std::uint8_t(r.flags & ~(kCreaseValid | kNormalValid));
      continue;
    }
    count += DemoteToSurface(g, r, v);
  }
  // Net: what thinning took from pass 1's features, so features with and without it differ by it.
  const std::size_t closed = CloseCreaseGaps(g, res, ridge, threads);
  return count > closed ? count - closed : 0;
}

}  // namespace nvv
