// Writes Normal Vector Voting results onto a vcglib mesh: normals, quality, colour, selection,
// curvature directions (PD1/PD2, K1/K2) and named per-vertex attributes, and from the crease
// network the faces' edge selection, patch attribute and patch colours. Shared by both MeshLab
// plugin APIs and the command-line tool, so each output means the same everywhere.
//
// Conventions (documented in README.md):
//  - K1 >= K2 always, PD1 is the direction of K1 (maximum curvature), PD2 of K2; a sphere
//    of radius R with outward normals has K1 = K2 = +1/R. (MeshLab's own "Compute curvature
//    principal directions" does not keep this order for every method.)
//  - Quality modes: mean H = (k1+k2)/2, Gaussian K = k1 k2, shape index
//    SI = (2/pi) atan((k1+k2)/(k1-k2)) (+1 cap, 0 saddle, -1 cup), curvedness
//    C = sqrt((k1^2+k2^2)/2). Vertices without a curvature get 0 and are left out of the ramp.
#ifndef NVV_APPLY_APPLY_RESULTS_H
#define NVV_APPLY_APPLY_RESULTS_H

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>

#include "filter/crease_outputs.h"
#include "filter/filter_options.h"
#include "core/vertex_result.h"

namespace nvv {

// Names of the attributes the filter adds (per vertex unless said; the mesh's scalar, or its Point3).
struct AttributeNames {
  static const char* Class() { return "nvv_class"; }
  static const char* SurfaceSaliency() { return "nvv_surface_saliency"; }
  static const char* CreaseSaliency() { return "nvv_crease_saliency"; }
  static const char* CornerSaliency() { return "nvv_corner_saliency"; }
  static const char* CuspAngle() { return "nvv_cusp_angle"; }            // degrees
  static const char* CreaseCurvature() { return "nvv_crease_curvature"; }
  static const char* CreaseTangent() { return "nvv_crease_tangent"; }    // Point3
  static const char* Patch() { return "nvv_patch"; }                     // per face; -1: no patch
  static const char* Line() { return "nvv_line"; }                       // per edge of the lines layer
};

// The quality value of one vertex; `valid` false when it has none for this mode.
inline double QualityValue(const VertexResult& r, QualityMode mode, bool& valid) {
  const bool curv = r.Has(kCurvatureValid);
  valid = true;
  const double k1 = r.k1, k2 = r.k2;
  switch (mode) {
    case QualityMode::MeanCurvature: valid = curv; return curv ? 0.5 * (k1 + k2) : 0;
    case QualityMode::GaussianCurvature: valid = curv; return curv ? k1 * k2 : 0;
    case QualityMode::MaxCurvature: valid = curv; return curv ? k1 : 0;
    case QualityMode::MinCurvature: valid = curv; return curv ? k2 : 0;
    case QualityMode::ShapeIndex:
      valid = curv;
      if (!curv || (k1 == 0 && k2 == 0)) return 0;
      return (2.0 / 3.14159265358979323846) * std::atan2(k1 + k2, k1 - k2);
    case QualityMode::Curvedness: valid = curv; return curv ? std::sqrt(0.5 * (k1 * k1 + k2 * k2)) : 0;
    case QualityMode::Class: return double(int(r.cls));
    case QualityMode::CuspAngle:
      valid = r.Has(kCreaseValid);
      return valid ? RadToDeg(r.cuspAngle) : 0;
    case QualityMode::SurfaceSaliency: valid = r.cls != VertexClass::Invalid; return r.SurfaceSaliency();
    default: valid = false; return 0;
  }
}

inline vcg::Color4b ClassColor(VertexClass c) {
  switch (c) {
    case VertexClass::Surface: return vcg::Color4b(190, 190, 190, 255);
    case VertexClass::Crease: return vcg::Color4b(220, 30, 30, 255);
    case VertexClass::Corner: return vcg::Color4b(30, 80, 235, 255);
    default: return vcg::Color4b(255, 0, 255, 255);
  }
}

// The p-th and (100-p)-th percentiles of the valid quality values.
inline bool PercentileRange(std::vector<double> values, double p, double& lo, double& hi) {
  if (values.empty()) return false;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  const std::size_t a = std::min(n - 1, std::size_t(std::floor(p / 100.0 * (n - 1))));
  const std::size_t b = std::min(n - 1, std::size_t(std::ceil((100.0 - p) / 100.0 * (n - 1))));
  lo = values[a];
  hi = values[b];
  return true;
}

template <class MeshType>
class ApplyResults {
 public:
  typedef typename MeshType::ScalarType ScalarType;
  typedef typename MeshType::CoordType CoordType;

  // What the mesh must offer for the chosen options; the adapter enables it (MeshLab:
  // updateDataMask) before calling Apply.
  struct Needs {
    bool quality = false, color = false, curvatureDir = false, faceColor = false;
  };
  static Needs NeedsFor(const FilterOptions& o) {
    Needs n;
    n.quality = o.quality != QualityMode::Keep || o.color == ColorMode::QualityRamp;
    n.color = o.color != ColorMode::Keep && o.color != ColorMode::Patches;
    n.curvatureDir = true;
    n.faceColor = o.color == ColorMode::Patches;
    return n;
  }

  // Writes everything the options ask for. The mesh's optional components must exist. crease:
  // the run's crease network, when WantsCreaseNetwork(o); without it nothing per face is written
  // and patch colours are left out.
  static void Apply(MeshType& m, const std::vector<VertexResult>& res, const FilterOptions& o,
                    const CreaseOutputs* crease = nullptr) {
    if (o.updateNormals && vcg::tri::HasPerVertexNormal(m)) Normals(m, res);
    const QualityMode qmode = o.quality == QualityMode::Keep && o.color == ColorMode::QualityRamp
                                  ? QualityMode::MeanCurvature : o.quality;
    if (qmode != QualityMode::Keep && vcg::tri::HasPerVertexQuality(m)) Quality(m, res, qmode);
    if (o.color == ColorMode::Classes && vcg::tri::HasPerVertexColor(m)) ClassColors(m, res);
    if (o.color == ColorMode::QualityRamp && vcg::tri::HasPerVertexColor(m)) Ramp(m, res, qmode, o.clampPercentile);
    if (o.selection != SelectionMode::None && o.selection != SelectionMode::CreaseLines) Selection(m, res, o.selection);
    if (vcg::tri::HasPerVertexCurvatureDir(m)) CurvatureDir(m, res);
    Attributes(m, res);
    if (!crease) return;
    if (o.creaseEdges && vcg::tri::HasPerFaceFlags(m)) CreaseEdgeSelection(m, *crease);
    if (o.selection == SelectionMode::CreaseLines) LineVertexSelection(m, *crease);
    PatchAttribute(m, *crease);
    if (o.color == ColorMode::Patches) PatchColors(m, res, *crease);
  }

  // Estimated normals where there is one; elsewhere (corners, unclassified) the mesh's own normal
  // keeps its direction but is made unit length (MeshLab leaves loaded normals unnormalised).
  static void Normals(MeshType& m, const std::vector<VertexResult>& res) {
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      auto& v = m.vert[i];
      if (v.IsD()) continue;
      if (res[i].Has(kNormalValid)) v.N() = ToCoord(res[i].normal);
      else if (v.N().Norm() > 0 && std::isfinite(v.N().Norm())) v.N().Normalize();
      else v.N() = CoordType(0, 0, 0);  // no direction to keep: never a non-finite normal
    }
  }
  static void Quality(MeshType& m, const std::vector<VertexResult>& res, QualityMode mode) {
    bool valid;
    for (std::size_t i = 0; i < m.vert.size(); ++i)
      if (!m.vert[i].IsD()) m.vert[i].Q() = ScalarType(QualityValue(res[i], mode, valid));
  }
  static void ClassColors(MeshType& m, const std::vector<VertexResult>& res) {
    for (std::size_t i = 0; i < m.vert.size(); ++i)
      if (!m.vert[i].IsD()) m.vert[i].C() = ClassColor(res[i].cls);
  }
  // MeshLab's red (low) -> blue (high) ramp over the clamped percentile range; vertices without
  // a value are grey.
  static void Ramp(MeshType& m, const std::vector<VertexResult>& res, QualityMode mode, double percentile) {
    std::vector<double> values;
    bool valid;
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      if (m.vert[i].IsD()) continue;
      const double q = QualityValue(res[i], mode, valid);
      if (valid) values.push_back(q);
    }
    double lo = 0, hi = 0;
    PercentileRange(values, percentile, lo, hi);
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      if (m.vert[i].IsD()) continue;
      const double q = QualityValue(res[i], mode, valid);
      m.vert[i].C() = valid ? vcg::Color4b::ColorRamp(float(lo), float(hi), float(q)) : vcg::Color4b(128, 128, 128, 255);
    }
  }
  static bool Selected(const VertexResult& r, SelectionMode mode) {
    switch (mode) {
      case SelectionMode::CreasesAndCorners: return r.cls == VertexClass::Crease || r.cls == VertexClass::Corner;
      case SelectionMode::CornersOnly: return r.cls == VertexClass::Corner;
      case SelectionMode::SurfaceOnly: return r.cls == VertexClass::Surface;
      default: return false;
    }
  }
  static void Selection(MeshType& m, const std::vector<VertexResult>& res, SelectionMode mode) {
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      if (m.vert[i].IsD()) continue;
      if (Selected(res[i], mode)) m.vert[i].SetS();
      else m.vert[i].ClearS();
    }
  }
  // The vertices at the ends of the crease edges, and only them.
  static void LineVertexSelection(MeshType& m, const CreaseOutputs& c) {
    for (auto& v : m.vert)
      if (!v.IsD()) v.ClearS();
    for (const auto& e : c.net.edges)
      for (int v : e) m.vert[v].SetS();
  }
  static void CurvatureDir(MeshType& m, const std::vector<VertexResult>& res) {
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      auto& v = m.vert[i];
      if (v.IsD()) continue;
      const bool ok = res[i].Has(kCurvatureValid);
      v.PD1() = ok ? ToCoord(res[i].t1) : CoordType(0, 0, 0);
      v.PD2() = ok ? ToCoord(res[i].t2) : CoordType(0, 0, 0);
      v.K1() = ok ? ScalarType(res[i].k1) : ScalarType(0);
      v.K2() = ok ? ScalarType(res[i].k2) : ScalarType(0);
    }
  }
  static void Attributes(MeshType& m, const std::vector<VertexResult>& res) {
    typedef vcg::tri::Allocator<MeshType> Alloc;
    auto cls = Alloc::template GetPerVertexAttribute<ScalarType>(m, AttributeNames::Class());
    auto ss = Alloc::template GetPerVertexAttribute<ScalarType>(m, AttributeNames::SurfaceSaliency());
    auto cs = Alloc::template GetPerVertexAttribute<ScalarType>(m, AttributeNames::CreaseSaliency());
    auto ns = Alloc::template GetPerVertexAttribute<ScalarType>(m, AttributeNames::CornerSaliency());
    auto cusp = Alloc::template GetPerVertexAttribute<ScalarType>(m, AttributeNames::CuspAngle());
    auto ck = Alloc::template GetPerVertexAttribute<ScalarType>(m, AttributeNames::CreaseCurvature());
    auto tan = Alloc::template GetPerVertexAttribute<CoordType>(m, AttributeNames::CreaseTangent());
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      const VertexResult& r = res[i];
      cls[i] = ScalarType(int(r.cls));
      ss[i] = ScalarType(r.SurfaceSaliency());
      cs[i] = ScalarType(r.CreaseSaliency());
      ns[i] = ScalarType(r.CornerSaliency());
      cusp[i] = ScalarType(r.Has(kCreaseValid) ? RadToDeg(r.cuspAngle) : 0.0);
      ck[i] = ScalarType(r.Has(kCreaseValid) ? r.creaseCurvature : 0.0f);
      tan[i] = r.Has(kCreaseValid) ? ToCoord(r.creaseTangent) : CoordType(0, 0, 0);
    }
  }

  // The crease edges become the faces' edge selection (vcglib's FaceEdgeS, what MeshLab's
  // "Select Crease Edges" sets), replacing any earlier one; both faces of an edge carry it.
  static void CreaseEdgeSelection(MeshType& m, const CreaseOutputs& c) {
    const auto* base = m.vert.empty() ? nullptr : &m.vert[0];
    for (std::size_t s = 0; s < m.face.size(); ++s) {
      auto& f = m.face[s];
      if (f.IsD()) continue;
      for (int j = 0; j < 3; ++j) f.ClearFaceEdgeS(j);
      if (c.meshFacePatch[s] < 0) continue;  // not in the network's graph
      for (int j = 0; j < 3; ++j) {
        const int a = int(f.cV(j) - base), b = int(f.cV((j + 1) % 3) - base);
        if (c.EdgeIndex(a, b) >= 0) f.SetFaceEdgeS(j);
      }
    }
  }
  static void PatchAttribute(MeshType& m, const CreaseOutputs& c) {
    auto patch = vcg::tri::Allocator<MeshType>::template GetPerFaceAttribute<ScalarType>(m, AttributeNames::Patch());
    for (std::size_t s = 0; s < m.face.size(); ++s) patch[s] = ScalarType(c.meshFacePatch[s]);
  }
  // One colour per patch, on the faces where the mesh has face colours (MeshLab then shows them:
  // on a coarse CAD mesh nearly every vertex lies on a line, so only faces can show the patches)
  // and its vertex colours are left as they were. A mesh without face colours (the command-line
  // tool's) gets them on its vertices instead: a vertex takes its faces' patch colour when they
  // all lie in one patch, else (on a line) the crease or corner colour. Faces and vertices outside
  // every patch take the unclassified colour.
  static vcg::Color4b PatchColor(int patch, int count) {
    return patch < 0 ? ClassColor(VertexClass::Invalid) : vcg::Color4b::Scatter(count, patch, 0.55f, 0.95f);
  }
  static void PatchColors(MeshType& m, const std::vector<VertexResult>& res, const CreaseOutputs& c) {
    const int count = c.net.patchCount;
    if (vcg::tri::HasPerFaceColor(m)) {
      for (std::size_t s = 0; s < m.face.size(); ++s)
        if (!m.face[s].IsD()) m.face[s].C() = PatchColor(c.meshFacePatch[s], count);
      return;
    }
    if (!vcg::tri::HasPerVertexColor(m)) return;
    const auto* base = m.vert.empty() ? nullptr : &m.vert[0];
    const int kNone = -1, kSeveral = -2;
    std::vector<int> vertexPatch(m.vert.size(), kNone);
    for (std::size_t s = 0; s < m.face.size(); ++s) {
      const int p = c.meshFacePatch[s];
      if (m.face[s].IsD() || p < 0) continue;
      for (int j = 0; j < 3; ++j) {
        int& vp = vertexPatch[m.face[s].cV(j) - base];
        vp = vp == kNone || vp == p ? p : kSeveral;
      }
    }
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      if (m.vert[i].IsD()) continue;
      const int p = vertexPatch[i];
      m.vert[i].C() = p != kSeveral ? PatchColor(p, count)
                                    : ClassColor(res[i].cls == VertexClass::Corner ? VertexClass::Corner : VertexClass::Crease);
    }
  }

 private:
  static CoordType ToCoord(const float* p) { return CoordType(ScalarType(p[0]), ScalarType(p[1]), ScalarType(p[2])); }
};

// One log line with counts per class, curvature ranges, radius and time.
inline std::string SummaryLine(const Summary& s) {
  char sharp[128] = "";
  if (s.sharpEdges)
    std::snprintf(sharp, sizeof sharp, "; a clean mesh: classes from its sharp edges, %zu changed from the votes'",
                  s.sharpEdgeChanged);
  else if (s.sharpEdgesAdded)
    std::snprintf(sharp, sizeof sharp, "; noisy: %zu vertices on its sharp edges changed class",
                  s.sharpEdgeChanged);
  char buf[640];
  std::snprintf(buf, sizeof buf,
                "Normal vector voting: %zu surface, %zu crease, %zu corner, %zu unclassified vertices "
                "(%zu band vertices thinned off the ridges%s); "
                "k1 in [%.4g, %.4g], k2 in [%.4g, %.4g]; radius %.4g (mean edge %.4g), epsilon %.3g, eta %.3g; "
                "k = %.3g%s, noise along the normals %.2g %% of the mean edge; "
                "%.2f s (pass 1 %.2f s, pass 2 %.2f s)",
                s.perClass[0], s.perClass[1], s.perClass[2], s.perClass[3], s.thinned, sharp, s.k1Min, s.k1Max, s.k2Min,
                s.k2Max, s.radius, s.meanEdge, s.epsilon, s.eta, s.k, s.autoK ? " chosen from the noise" : "",
                100.0 * s.noiseOverEdge, s.secondsTotal, s.secondsPass1, s.secondsPass2);
  return buf;
}

}  // namespace nvv

#endif
