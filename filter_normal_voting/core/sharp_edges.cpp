#include "sharp_edges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "crease_thinning.h"  // DemoteToSurface
#include "tuning.h"

namespace nvv {
namespace {

// True when face t runs from a to b (a, b: two of its vertices).
bool RunsFromTo(const std::array<int, 3>& t, int a, int b) {
  return (t[0] == a && t[1] == b) || (t[1] == a && t[2] == b) || (t[2] == a && t[0] == b);
}

// Face o's normal as if o were oriented like f, its neighbour across the edge (a, b): flipped
// where the two faces run along the edge the same way (a mesh whose orientation is not
// consistent, as STL files often are, would otherwise show a 180 deg crease at every flipped face).
Eigen::Vector3d NormalOrientedLike(const SurfaceGraph& g, int f, int o, int a, int b) {
  return RunsFromTo(g.face[f], a, b) == RunsFromTo(g.face[o], a, b) ? Eigen::Vector3d(-g.faceNormal[o])
                                                                      : g.faceNormal[o];
}

// The dihedral angle (radians) between faces f and o across their edge (a, b).
double EdgeAngle(const SurfaceGraph& g, int f, int o, int a, int b) {
  return std::acos(std::max(-1.0, std::min(1.0, g.faceNormal[f].dot(NormalOrientedLike(g, f, o, a, b)))));
}

// Distance of c from the line through a and b.
double HeightOver(const SurfaceGraph& g, int a, int b, int c) {
  const Eigen::Vector3d e = g.pos[b] - g.pos[a];
  const double len = e.norm();
  return len > 0 ? e.cross(g.pos[c] - g.pos[a]).norm() / len : 0;
}

// The sharpest edge (c, y) parallel to the unit direction e: within kSharpEdgeParallelCos of it,
// its dihedral angle `turn` between faces h < o (turn 0 and h = -1 where no such edge turns).
struct ParallelLine {
  double turn = 0;
  int h = -1, o = -1, y = -1;
};
ParallelLine SharpestParallelLine(const SurfaceGraph& g, int c, const Eigen::Vector3d& e) {
  ParallelLine best;
  for (int i = g.FaceBegin(c); i < g.FaceEnd(c); ++i) {
    const int h = g.vfList[i];
    if (!(g.faceArea[h] > 0)) continue;
    for (int y : g.face[h]) {
      if (y == c || std::abs((g.pos[y] - g.pos[c]).normalized().dot(e)) < tuning::kSharpEdgeParallelCos) continue;
      g.ForEachFaceAcross(h, c, y, [&](int o) {  // each face pair once, from its lower face
        if (!(o > h && g.faceArea[o] > 0)) return;
        const double angle = EdgeAngle(g, h, o, c, y);
        if (angle > best.turn) best.turn = angle, best.h = h, best.o = o, best.y = y;
      });
    }
  }
  return best;
}

// How the surface turns at c along lines parallel to the unit direction e: the largest dihedral
// angle over c's edges within kSharpEdgeParallelCos of e. On a cylinder cut into strips, the next
// strip's line through c turns as much as the edge does; beside a crease between two sheets
// nothing does; a crease through c across e (a corner's other edge) is not parallel and not counted.
double ParallelTurn(const SurfaceGraph& g, int c, const Eigen::Vector3d& e) { return SharpestParallelLine(g, c, e).turn; }

// An equilateral face's height per unit edge (sqrt(3) / 2, rounded as the noise angle's calibration was):
// the faces of edge l_ave the noise angle and the sharp edges' noise test are scaled to.
constexpr double kEquilateralHeight = 0.87;

int ThirdVertex(const std::array<int, 3>& t, int a, int b) { return t[0] + t[1] + t[2] - a - b; }

// Calls visit(f, o, x, c, d) once for every pair of faces f = (v, x, c) < o = (x, v, d) of positive
// area across an edge (v, x) of v (f repeated with the other orientation, d == c, is no pair); stops
// at the first visit that returns true, and returns whether one did.
template <class Visit>
bool ForEachEdgeFacePair(const SurfaceGraph& g, int v, Visit visit) {
  bool stop = false;
  for (int i = g.FaceBegin(v); i < g.FaceEnd(v) && !stop; ++i) {
    const int f = g.vfList[i];
    if (!(g.faceArea[f] > 0)) continue;
    for (int x : g.face[f]) {
      if (x == v || stop) continue;
      const int c = ThirdVertex(g.face[f], v, x);
      g.ForEachFaceAcross(f, v, x, [&](int o) {  // each face pair once, from its lower face
        if (stop || o < f || !(g.faceArea[o] > 0)) return;
        const int d = ThirdVertex(g.face[o], v, x);
        if (d != c) stop = visit(f, o, x, c, d);
      });
    }
  }
  return stop;
}

// How much the surface turns at the other edges of face h = (a, b, c) (its edges through c), below
// `below` (an edge that sharp is a crease of its own, as a chamfer's other side). Beside a crease
// between two sheets the faces' other edges lie in their sheets; on a coarse, irregular
// tessellation of a curved face the edges turn in every direction, and there may be no edge
// parallel to (a, b) at c for ParallelTurn to compare with.
double OtherEdgesTurn(const SurfaceGraph& g, int h, int a, int b, int c, double below) {
  double turn = 0;
  for (int y : {a, b})
    g.ForEachFaceAcross(h, c, y, [&](int o) {
      if (o == h || !(g.faceArea[o] > 0)) return;
      const double angle = EdgeAngle(g, h, o, c, y);
      if (angle < below) turn = std::max(turn, angle);
    });
  return turn;
}

// What the sharp edges of one vertex say.
struct SharpVerdict {
  std::uint8_t cls = std::uint8_t(VertexClass::Surface);
  float tangent[3] = {0, 0, 0};
  float normal[3] = {0, 0, 0};
  float cusp = 0;
};

struct Thresholds {
  double sharp;   // the sharp-edge angle (rad)
  double always;  // sharp whatever the neighbours (rad)
  double farAboveNoise;  // the same where it turns kSharpEdgeAloneOverNoise times what the noise tilts its faces
  double sigma;   // the positions' noise the mesh's noise angle implies
  bool chamferChain;  // a chamfer's line must continue along another sharp edge (noisy meshes)
};

// True when the line parallel to e through c, the sharpest one there (at least `sharp`), has a
// flat sheet beyond it, seen from the edge (v, x): c's line and (v, x) are a chamfer's two lines.
// On a curved face cut into strips the next strip's line lies beyond, and the surface turns there.
bool FlatBeyondParallelLine(const SurfaceGraph& g, int v, int x, int c, const Eigen::Vector3d& e, double sharp,
                            double always) {
  const ParallelLine line = SharpestParallelLine(g, c, e);
  if (line.h < 0 || line.turn < sharp * (1 - 1e-9)) return false;
  // The far vertex of that line's faces: the one farther from (v, x).
  const int zh = ThirdVertex(g.face[line.h], c, line.y), zo = ThirdVertex(g.face[line.o], c, line.y);
  const bool farH = HeightOver(g, v, x, zh) >= HeightOver(g, v, x, zo);
  const int z = farH ? zh : zo;
  if (z == v || z == x) return false;
  return line.turn >= tuning::kSharpEdgeIsolation *
                          std::max(ParallelTurn(g, z, e), OtherEdgesTurn(g, farH ? line.h : line.o, c, line.y, z, always));
}

bool ContinuedBySharpEdge(const SurfaceGraph& g, int q, int p, const Eigen::Vector3d& e, const Thresholds& t);

// True when the edge (v, x) between faces f = (v, x, c) and o = (x, v, d) at dihedral angle theta
// is sharp (sharp_edges.h).
bool IsSharpEdge(const SurfaceGraph& g, int f, int o, int v, int x, int c, int d, double theta, const Thresholds& t) {
  if (theta < t.sharp * (1 - 1e-9)) return false;  // an edge of exactly the angle is sharp
  // Noise tilts a face of height h over the edge by about sigma / h: slivers by much more.
  const double hc = HeightOver(g, v, x, c), hd = HeightOver(g, v, x, d);
  if (!(hc > 0 && hd > 0)) return false;
  const double noiseTilt = t.sigma * (1 / hc + 1 / hd);
  if (theta < tuning::kSharpEdgeOverNoise * noiseTilt) return false;
  if (theta >= t.always || (theta >= t.farAboveNoise && theta >= tuning::kSharpEdgeAloneOverNoise * noiseTilt))
    return true;
  const Eigen::Vector3d e = (g.pos[x] - g.pos[v]).normalized();
  const double pc = ParallelTurn(g, c, e), pd = ParallelTurn(g, d, e);
  // Flat on a side: neither a parallel line nor the face's other edges turn 1 / kSharpEdgeIsolation as much.
  const bool flatC = theta >= tuning::kSharpEdgeIsolation * pc &&
                     theta >= tuning::kSharpEdgeIsolation * OtherEdgesTurn(g, f, v, x, c, t.always);
  const bool flatD = theta >= tuning::kSharpEdgeIsolation * pd &&
                     theta >= tuning::kSharpEdgeIsolation * OtherEdgesTurn(g, o, v, x, d, t.always);
  if (flatC && flatD) return true;
  if (flatC == flatD) return false;
  // The line beside must not stand alone either: a crease with a lesser edge beside it is one crease.
  if (theta * tuning::kSharpEdgeIsolation <= (flatD ? pc : pd)) return false;
  if (!(flatD ? FlatBeyondParallelLine(g, v, x, c, e, t.sharp, t.always)
              : FlatBeyondParallelLine(g, v, x, d, e, t.sharp, t.always)))
    return false;
  return !t.chamferChain || ContinuedBySharpEdge(g, v, x, e, t) || ContinuedBySharpEdge(g, x, v, -e, t);
}

// True when an edge of p running on along e (away from q) is sharp: a chamfer's line is a chain of
// edges, a noise edge beside a crease stands alone.
bool ContinuedBySharpEdge(const SurfaceGraph& g, int q, int p, const Eigen::Vector3d& e, const Thresholds& t) {
  Thresholds single = t;
  single.chamferChain = false;
  return ForEachEdgeFacePair(g, p, [&](int h, int o, int y, int c, int d) {
    if (y == q || (g.pos[y] - g.pos[p]).normalized().dot(e) < tuning::kCosSameLine) return false;
    return IsSharpEdge(g, h, o, p, y, c, d, EdgeAngle(g, h, o, p, y), single);
  });
}

SharpVerdict JudgeVertex(const SurfaceGraph& g, int v, const Thresholds& t) {
  SharpVerdict out;
  Eigen::Vector3d firstDir = Eigen::Vector3d::Zero(), tangent = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double cusp = 0;
  int count = 0;
  bool corner = false;
  ForEachEdgeFacePair(g, v, [&](int f, int o, int x, int c, int d) {
    const double theta = EdgeAngle(g, f, o, v, x);
    if (!IsSharpEdge(g, f, o, v, x, c, d, theta, t)) return false;
    Eigen::Vector3d dir = (g.pos[x] - g.pos[v]).normalized();
    if (count == 0) firstDir = dir;
    else if (std::abs(dir.dot(firstDir)) < tuning::kCosSameLine) corner = true;
    if (dir.dot(firstDir) < 0) dir = -dir;
    tangent += dir;
    normal += g.faceNormal[f] + NormalOrientedLike(g, f, o, v, x);
    cusp += theta;
    ++count;
    return false;
  });
  if (count == 0) return out;
  if (corner || count > 2) {
    out.cls = std::uint8_t(VertexClass::Corner);
    return out;
  }
  out.cls = std::uint8_t(VertexClass::Crease);
  tangent.normalize();
  if (normal.squaredNorm() > 0) normal.normalize();
  for (int j = 0; j < 3; ++j) {
    out.tangent[j] = float(tangent[j]);
    out.normal[j] = float(normal[j]);
  }
  out.cusp = float(cusp / count);
  return out;
}

// Writes a verdict onto v's result; true when v's class changed.
bool Apply(const SurfaceGraph& g, int v, const SharpVerdict& s, VertexResult& r) {
  const VertexClass want = VertexClass(s.cls);
  if (want == VertexClass::Surface) return IsFeature(r) && DemoteToSurface(g, r, v) == 1;
  const bool changed = r.cls != want;
  r.cls = want;
  if (want == VertexClass::Corner) {
    r.flags = std::uint8_t(r.flags & ~kCreaseValid);
    return changed;
  }
  for (int j = 0; j < 3; ++j) r.creaseTangent[j] = s.tangent[j], r.normal[j] = s.normal[j];
  r.cuspAngle = s.cusp;
  r.flags = std::uint8_t(r.flags | kCreaseValid | kNormalValid);
  return changed;
}

}  // namespace

SharpEdgeRole SharpEdgeRoleFor(const Params& p, double noise) {
  if (!(p.sharpEdgeAngleDeg > 0)) return SharpEdgeRole::None;
  if (noise < DegToRad(tuning::kCleanMeshNoiseDeg)) return SharpEdgeRole::DecideAll;
  return noise < DegToRad(tuning::kLightNoiseDeg) ? SharpEdgeRole::AddFeatures : SharpEdgeRole::AddIsolated;
}

void ClassifyBySharpEdges(const SurfaceGraph& g, const Params& p, SharpEdgeRole role, double noise, int threads,
                          std::vector<VertexResult>& res, std::size_t& changed) {
  changed = 0;
  if (role == SharpEdgeRole::None) return;
  Thresholds t;
  t.sharp = DegToRad(std::min(p.sharpEdgeAngleDeg, p.creaseAngleDeg));
  // Noisier: an edge is sharp by its angle alone only far above the noise (noise takes a coarse cylinder's
  // 36 deg strip lines over kSharpEdgeAlwaysDeg); below that only isolated edges and a chamfer's lines that run
  // on along other sharp edges count. The isolation tests still count every other edge's turn (`always`
  // infinite): leaving out those over kSharpEdgeAlwaysDeg there (measured with the rule at 40 times the noise)
  // took new noise draws of the CAD parts at 20 % from patches' ARI 0.353 to 0.327.
  const double always = DegToRad(std::max(tuning::kSharpEdgeAlwaysDeg, p.sharpEdgeAngleDeg));
  t.always = role == SharpEdgeRole::AddIsolated ? std::numeric_limits<double>::infinity() : always;
  t.farAboveNoise = role == SharpEdgeRole::AddIsolated ? always : std::numeric_limits<double>::infinity();
  // Two equilateral faces of edge l_ave tilt apart by about sigma 2 / (kEquilateralHeight l_ave) under noise sigma.
  t.sigma = noise * kEquilateralHeight * g.meanEdge / 2;
  t.chamferChain = role != SharpEdgeRole::DecideAll;
  const int n = g.VertexCount();
  std::vector<SharpVerdict> verdict(n);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int v = 0; v < n; ++v)
    if (res[v].cls != VertexClass::Invalid && g.Referenced(v)) verdict[v] = JudgeVertex(g, v, t);
  for (int v = 0; v < n; ++v) {
    if (res[v].cls == VertexClass::Invalid || !g.Referenced(v)) continue;
    // Noisy: a vertex without sharp edges keeps the votes' class.
    if (role != SharpEdgeRole::DecideAll && VertexClass(verdict[v].cls) == VertexClass::Surface) continue;
    changed += Apply(g, v, verdict[v], res[v]);
  }
}

MeshNoiseAngles MeasureNoiseAngles(const SurfaceGraph& g) {
  std::vector<double> scaled, unscaled;
  // Noise sigma tilts two faces of heights hc, hd over their edge apart by about sigma (1/hc + 1/hd):
  // scaled, each edge's angle is what it would be between equilateral faces of edge l_ave (heights
  // kEquilateralHeight l_ave), so that slivers, tilted most by the same noise, do not read as a noisier mesh.
  const double equilateral = 2 / (kEquilateralHeight * g.meanEdge);
  g.ForEachSampledEdgePair([&](int f, int o, int a, int b) {
    const double angle = EdgeAngle(g, f, o, a, b);
    unscaled.push_back(angle);
    const double hc = HeightOver(g, a, b, ThirdVertex(g.face[f], a, b));
    const double hd = HeightOver(g, a, b, ThirdVertex(g.face[o], a, b));
    if (hc > 0 && hd > 0) scaled.push_back(angle * equilateral / (1 / hc + 1 / hd));
  });
  auto lowestTenth = [](std::vector<double>& angles) {
    if (angles.empty()) return 0.0;
    std::nth_element(angles.begin(), angles.begin() + angles.size() / 10, angles.end());
    return angles[angles.size() / 10];
  };
  MeshNoiseAngles out;
  out.scaled = lowestTenth(scaled);
  out.unscaled = lowestTenth(unscaled);
  return out;
}

}  // namespace nvv
