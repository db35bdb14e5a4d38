#include "sharp_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "tuning.h"

namespace nvv {
namespace {

// Angle (radians) between the normals of two faces with an area.
double FaceAngle(const SurfaceGraph& g, int f, int o) {
  return std::acos(std::max(-1.0, std::min(1.0, g.faceNormal[f].dot(g.faceNormal[o]))));
}

double MedianOf(std::vector<double>& a) {
  if (a.empty()) return 0;
  std::nth_element(a.begin(), a.begin() + a.size() / 2, a.end());
  return a[a.size() / 2];
}
double LowerQuartileOf(std::vector<double>& a) {
  if (a.empty()) return 0;
  std::nth_element(a.begin(), a.begin() + a.size() / 4, a.end());
  return a[a.size() / 4];
}

// nu(v): the median dihedral angle over the edges of v's faces (spokes twice, rim edges once).
double RingNoise(const SurfaceGraph& g, int v, std::vector<double>& scratch) {
  scratch.clear();
  for (int i = g.FaceBegin(v); i < g.FaceEnd(v); ++i) {
    const int f = g.vfList[i];
    if (!(g.faceArea[f] > 0)) continue;
    for (int j = 0; j < 3; ++j)
      g.ForEachFaceAcross(f, g.face[f][j], g.face[f][(j + 1) % 3], [&](int o) {
        if (g.faceArea[o] > 0) scratch.push_back(FaceAngle(g, f, o));
      });
  }
  return LowerQuartileOf(scratch);
}

// How face f turns away from its neighbours around its vertex c: the median angle between f and
// c's other faces (0 where c's fan is one plane; a strip's angle on a tessellated cylinder).
double TurnAround(const SurfaceGraph& g, int f, int c, std::vector<double>& scratch) {
  scratch.clear();
  for (int i = g.FaceBegin(c); i < g.FaceEnd(c); ++i) {
    const int h = g.vfList[i];
    if (h != f && g.faceArea[h] > 0) scratch.push_back(FaceAngle(g, f, h));
  }
  return MedianOf(scratch);
}

// The lower quartile of the dihedral angles over the edges of at most kMedianEdgeAngleFaces evenly
// spread faces: 0 on a CAD part, the noise's typical angle on a scan.
double MeshNoiseAngle(const SurfaceGraph& g) {
  std::vector<double> angles;
  const int stride = std::max(1, g.FaceCount() / tuning::kMedianEdgeAngleFaces);
  for (int f = 0; f < g.FaceCount(); f += stride) {
    if (!(g.faceArea[f] > 0)) continue;
    for (int j = 0; j < 3; ++j)
      g.ForEachFaceAcross(f, g.face[f][j], g.face[f][(j + 1) % 3], [&](int o) {
        if (o > f && g.faceArea[o] > 0) angles.push_back(FaceAngle(g, f, o));
      });
  }
  if (angles.empty()) return 0;
  std::nth_element(angles.begin(), angles.begin() + angles.size() / 10, angles.end());
  return angles[angles.size() / 10];
}

// Distance of c from the line through a and b.
double HeightOver(const SurfaceGraph& g, int a, int b, int c) {
  const Eigen::Vector3d e = g.pos[b] - g.pos[a];
  const double len = e.norm();
  return len > 0 ? e.cross(g.pos[c] - g.pos[a]).norm() / len : 0;
}

int ThirdVertex(const std::array<int, 3>& t, int a, int b) { return t[0] + t[1] + t[2] - a - b; }

// What the sharp edges of one clean vertex say.
struct SharpVerdict {
  std::uint8_t clean = 0;
  std::uint8_t cls = std::uint8_t(VertexClass::Surface);
  float tangent[3] = {0, 0, 0};
  float normal[3] = {0, 0, 0};
  float cusp = 0;
};

// sigma: the positions' noise the mesh's noise angle implies (a face of height h tilts by sigma / h).
SharpVerdict JudgeVertex(const SurfaceGraph& g, int v, double sharp, double sigma, std::vector<double>& scratch) {
  SharpVerdict out;
  if (!(tuning::kCleanOverNoise * RingNoise(g, v, scratch) < sharp)) return out;
  out.clean = 1;
  Eigen::Vector3d firstDir = Eigen::Vector3d::Zero(), tangent = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double cusp = 0;
  int count = 0;
  bool corner = false;
  for (int i = g.FaceBegin(v); i < g.FaceEnd(v); ++i) {
    const int f = g.vfList[i];
    if (!(g.faceArea[f] > 0)) continue;
    for (int x : g.face[f]) {
      if (x == v) continue;
      const int c = ThirdVertex(g.face[f], v, x);
      g.ForEachFaceAcross(f, v, x, [&](int o) {  // each face pair once, from its lower face
        if (o < f || !(g.faceArea[o] > 0)) return;
        const int d = ThirdVertex(g.face[o], v, x);
        if (d == c) return;  // f repeated with the other orientation
        const double theta = FaceAngle(g, f, o);
        if (theta < sharp) return;
        // Noise tilts a face of height h over the edge by about sigma / h: slivers by much more.
        const double hc = HeightOver(g, v, x, c), hd = HeightOver(g, v, x, d);
        if (!(hc > 0 && hd > 0) || theta < tuning::kCleanOverNoise * sigma * (1 / hc + 1 / hd)) return;
        if (theta < tuning::kSharpEdgeAlways * sharp) {
          const double turn = std::max(TurnAround(g, f, c, scratch), TurnAround(g, o, d, scratch));
          if (theta < tuning::kSharpEdgeIsolation * turn) return;
        }
        Eigen::Vector3d dir = (g.pos[x] - g.pos[v]).normalized();
        if (count == 0) firstDir = dir;
        else if (std::abs(dir.dot(firstDir)) < tuning::kCosSameLine) corner = true;
        if (dir.dot(firstDir) < 0) dir = -dir;
        tangent += dir;
        normal += g.faceNormal[f] + g.faceNormal[o];
        cusp += theta;
        ++count;
      });
    }
  }
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

}  // namespace

std::size_t ClassifyCleanVerticesBySharpEdges(const SurfaceGraph& g, const Params& p, int threads,
                                              std::vector<VertexResult>& res) {
  if (!(p.sharpEdgeAngleDeg > 0)) return 0;
  const int n = g.VertexCount();
  const double sharp = DegToRad(std::min(p.sharpEdgeAngleDeg, p.creaseAngleDeg));
  const double noise = MeshNoiseAngle(g);
  if (!(tuning::kCleanMeshOverNoise * noise < sharp)) return 0;  // a noisy mesh: the votes decide everywhere
  // Two equilateral faces of edge l_ave tilt apart by about sigma (2 / 0.87 l_ave) under noise sigma.
  const double sigma = noise * 0.87 * g.meanEdge / 2;
  std::vector<SharpVerdict> verdict(n);
#pragma omp parallel num_threads(threads)
  {
    std::vector<double> scratch;
#pragma omp for schedule(dynamic, 1024)
    for (int v = 0; v < n; ++v)
      if (res[v].cls != VertexClass::Invalid && g.Referenced(v)) verdict[v] = JudgeVertex(g, v, sharp, sigma, scratch);
  }
  std::size_t changed = 0;
  for (int v = 0; v < n; ++v) {
    const SharpVerdict& s = verdict[v];
    VertexResult& r = res[v];
    if (!s.clean) continue;
    const VertexClass want = VertexClass(s.cls);
    if (want == VertexClass::Surface) {
      if (IsFeature(r)) {
        Eigen::Vector3d ring = g.RingNormalSum(v);
        if (!(ring.squaredNorm() > 0)) continue;
        ring.normalize();
        for (int j = 0; j < 3; ++j) r.normal[j] = float(ring[j]), r.creaseTangent[j] = 0;
        r.cls = VertexClass::Surface;
        r.flags = std::uint8_t((r.flags & ~kCreaseValid) | kNormalValid);
        r.cuspAngle = 0;
        ++changed;
      }
      continue;
    }
    if (r.cls == want && want == VertexClass::Corner) continue;
    if (r.cls != want) ++changed;
    r.cls = want;
    if (want == VertexClass::Corner) {
      r.flags = std::uint8_t(r.flags & ~kCreaseValid);
      continue;
    }
    for (int j = 0; j < 3; ++j) r.creaseTangent[j] = s.tangent[j], r.normal[j] = s.normal[j];
    r.cuspAngle = s.cusp;
    r.flags = std::uint8_t(r.flags | kCreaseValid | kNormalValid);
  }
  return changed;
}

}  // namespace nvv
