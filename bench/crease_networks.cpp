// "network": what users take from creases, measured against the truth: the crease edges (which
// mesh edges lie on a crease), the crease lines (those edges as polylines) and the smooth
// patches the lines bound (a label per face). Three ways to get them, on the same meshes:
//   this filter with the plugin's defaults: its crease network (filter/crease_outputs.h, the
//     same FindCreaseOutputs the plugin and the command-line tool call after the run);
//   MeshLab's "Select Crease Edges" (vcglib's FaceEdgeSelSignedCrease at +-angle), its edges
//     chained into lines between vertices where other than two selected edges meet, and faces
//     flood-filled across unselected edges into patches: what a user of MeshLab gets;
//   CGAL's sharp_edges_segmentation(angle): its sharp edges (chained likewise) and its patches.
// The peers run at 20 / 30 / 45 / 60 deg, and so does this filter (its crease angle phi, the
// rest at its defaults); the report shows the peers at 60 deg (the angle of this filter's
// defaults) and each method at its best angle per mesh and noise level (an oracle).
// Meshes: the synthetic crease shapes (crease_shapes.h: roofs of 20..175 deg, a cube, a capped
// cylinder), the CAD parts of bench/cad/make_cad_parts.py (their .truth files' sharp edges)
// and the ABC model with its .fea feature edges. Noise 0, 1, 5, 10, 20 % of l_ave along the
// normals, as in the "f1" and "cad" sections.
// Truth: the true feature edges are the mesh edges on a crease (sharp model curve); the true
// lines are those edges chained as the peers' are; the true patches are the faces flood-filled
// across non-feature edges, i.e. the model's faces joined across tangent (non-sharp) curves.
// Measures, every distance on the clean mesh's positions and in units of its l_ave:
//   edges    strict precision / recall / F1 over mesh edges, and +-1-edge: a found edge counts
//            as right when its midpoint is within 1 l_ave of a true edge, a true edge as found
//            when its midpoint is within 1 l_ave of a found edge;
//   lines    how many found against true; a found line lies on the truth when its directed
//            Hausdorff distance to the true lines is at most 1 l_ave; the mean of that distance
//            over the found lines; gaps: the share of the true lines' length farther than
//            1 l_ave from every found line; line F1: of the share of found lines on the truth
//            and the share of true length covered; true lines at least half covered;
//   patches  how many found against true; Rand index and adjusted Rand index of the faces'
//            labels (every face counts once). network_truth.csv also counts the true patches of
//            fewer faces than the filter's network keeps apart (tuning::kMinPatchFaces).
// Usage: nvv_bench_accuracy network OUTDIR PARTSDIR; writes OUTDIR/network.csv (one row per
// mesh, noise, method and angle) and OUTDIR/network_truth.csv, and prints the truth's table.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>
#include <numeric>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "crease_shapes.h"
#include "estimators.h"
#include "core/tuning.h"
#include "filter/crease_outputs.h"
#include "filter/filter_options.h"
#include "mesh_files.h"
#include "report.h"
#include "sections.h"

#ifndef NVV_SHARED_MESHES
#define NVV_SHARED_MESHES "../shared/meshes"
#endif

namespace nvv_bench {

namespace {

// The seed offset between two noise draws of one mesh (the held-out section's draws 1 and 2).
constexpr unsigned kHeldOutSeedStep = 1000003;

typedef std::array<int, 2> Edge;  // lower vertex index first

Edge EdgeOf(int a, int b) { return {{std::min(a, b), std::max(a, b)}}; }

void SortUnique(std::vector<Edge>& e) {
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
}

// A crease network as the measures see it, whoever made it.
struct Network {
  std::vector<Edge> edges;              // sorted
  std::vector<std::vector<int>> lines;  // vertex polylines; a closed one ends on its first vertex
  std::vector<int> facePatch;           // per face of the PlainMesh
  int patches = 0;
};

// Lines from bare edges, as a user of an edge selection gets them: edges chained between the
// vertices where other than two selected edges meet; what is left over are closed loops.
std::vector<std::vector<int>> ChainLines(const std::vector<Edge>& edges, std::size_t vertexCount) {
  std::vector<std::vector<int>> incident(vertexCount);  // edge indices at each vertex
  for (std::size_t i = 0; i < edges.size(); ++i) {
    incident[edges[i][0]].push_back(int(i));
    incident[edges[i][1]].push_back(int(i));
  }
  std::vector<char> used(edges.size(), 0);
  auto walk = [&](int start, int e) {
    std::vector<int> line{start};
    int v = start;
    for (;;) {
      used[e] = 1;
      const int w = edges[e][0] == v ? edges[e][1] : edges[e][0];
      line.push_back(w);
      if (w == start || incident[w].size() != 2) break;
      const int next = incident[w][0] == e ? incident[w][1] : incident[w][0];
      if (used[next]) break;
      v = w;
      e = next;
    }
    return line;
  };
  std::vector<std::vector<int>> lines;
  for (std::size_t v = 0; v < vertexCount; ++v)
    if (!incident[v].empty() && incident[v].size() != 2)
      for (int e : incident[v])
        if (!used[e]) lines.push_back(walk(int(v), e));
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (!used[e]) lines.push_back(walk(edges[e][0], int(e)));
  return lines;
}

int Find(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Patches from bare edges: faces joined across every mesh edge that is not a crease edge.
// Returns the number of patches.
int FloodPatches(const PlainMesh& m, const std::vector<Edge>& creaseEdges, std::vector<int>& facePatch) {
  std::vector<std::pair<Edge, int>> faceEdges;  // (edge, face), sorted by edge
  for (std::size_t f = 0; f < m.face.size(); ++f)
    for (int j = 0; j < 3; ++j) faceEdges.push_back({EdgeOf(m.face[f][j], m.face[f][(j + 1) % 3]), int(f)});
  std::sort(faceEdges.begin(), faceEdges.end());
  std::vector<int> parent(m.face.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < faceEdges.size();) {  // the faces of one mesh edge are adjacent
    const Edge e = faceEdges[i].first;
    const int first = faceEdges[i].second;
    const bool joins = !std::binary_search(creaseEdges.begin(), creaseEdges.end(), e);
    for (++i; i < faceEdges.size() && faceEdges[i].first == e; ++i)
      if (joins) parent[Find(parent, faceEdges[i].second)] = Find(parent, first);
  }
  std::vector<int> label(m.face.size(), -1);
  int count = 0;
  facePatch.assign(m.face.size(), -1);
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    const int r = Find(parent, int(f));
    if (label[r] < 0) label[r] = count++;
    facePatch[f] = label[r];
  }
  return count;
}

// Lines and patches of an edge selection, as the peers' users get them.
Network FromSelectedEdges(const PlainMesh& m, std::vector<Edge> edges) {
  Network n;
  SortUnique(edges);
  n.edges = edges;
  n.lines = ChainLines(n.edges, m.pos.size());
  n.patches = FloodPatches(m, n.edges, n.facePatch);
  return n;
}

// This filter with the plugin's defaults (crease angle phi: `creaseAngleDeg`, or the default's
// when 0): the run, then the crease network the plugin's run sequence (filter/run_filter.h)
// finds from it.
Network FilterNetwork(const TMesh& m, double creaseAngleDeg = 0) {
  nvv::FilterOptions options;
  if (creaseAngleDeg > 0) options.core.creaseAngleDeg = creaseAngleDeg;
  std::vector<nvv::VertexResult> res;
  nvv::Summary sum;
  nvv::SurfaceGraph g;
  Network n;
  if (!vcg::tri::NormalVectorVoting<TMesh>::Compute(m, options.core, res, sum, g).ok) return n;
  const nvv::CreaseOutputs c = nvv::FindCreaseOutputs(m, g, res, sum, options.core.creaseAngleDeg);
  n.edges = c.net.edges;
  for (const nvv::CreaseLine& l : c.net.lines) {
    n.lines.push_back(l.vertices);
    if (l.closed && !l.vertices.empty()) n.lines.back().push_back(l.vertices.front());
  }
  n.facePatch = c.meshFacePatch;  // the meshes here have no deleted faces: slots are faces
  n.patches = c.net.patchCount;
  return n;
}

// MeshLab's "Select Crease Edges" at +-angleDeg (peers_vcg.h), lower vertex first.
std::vector<Edge> DihedralCreaseEdgesSorted(const TMesh& m, double angleDeg) {
  std::vector<Edge> edges;
  for (const auto& e : DihedralCreaseEdges(m, angleDeg)) edges.push_back(EdgeOf(e[0], e[1]));
  return edges;
}

// Nearest distance from points to a set of segments: a uniform grid, searched in growing
// shells around the point; far from every segment, all of them.
class SegmentSet {
 public:
  SegmentSet(const std::vector<Eigen::Vector3d>& pos, const std::vector<Edge>& edges, double cell) : cell_(cell) {
    for (const Edge& e : edges) {
      const Eigen::Vector3d a = pos[e[0]], b = pos[e[1]];
      seg_.push_back({a, b});
      const Key lo = KeyOf(a.cwiseMin(b)), hi = KeyOf(a.cwiseMax(b));
      for (long x = lo[0]; x <= hi[0]; ++x)
        for (long y = lo[1]; y <= hi[1]; ++y)
          for (long z = lo[2]; z <= hi[2]; ++z) grid_[Hash({{x, y, z}})].push_back(int(seg_.size() - 1));
    }
  }
  bool Empty() const { return seg_.empty(); }
  double Distance(const Eigen::Vector3d& p) const {
    if (seg_.empty()) return INFINITY;
    const Key c = KeyOf(p);
    double best = INFINITY;
    const long kShells = 3;
    for (long r = 0; r <= kShells; ++r) {
      for (long x = c[0] - r; x <= c[0] + r; ++x)
        for (long y = c[1] - r; y <= c[1] + r; ++y)
          for (long z = c[2] - r; z <= c[2] + r; ++z) {
            if (std::max({std::labs(x - c[0]), std::labs(y - c[1]), std::labs(z - c[2])}) != r) continue;
            const auto it = grid_.find(Hash({{x, y, z}}));
            if (it == grid_.end()) continue;
            for (int s : it->second) best = std::min(best, ToSegment(p, s));
          }
      if (best <= r * cell_) return best;  // every segment not yet seen is farther than r cells
    }
    for (std::size_t s = 0; s < seg_.size(); ++s) best = std::min(best, ToSegment(p, int(s)));
    return best;
  }

 private:
  typedef std::array<long, 3> Key;
  Key KeyOf(const Eigen::Vector3d& p) const {
    return {{long(std::floor(p.x() / cell_)), long(std::floor(p.y() / cell_)), long(std::floor(p.z() / cell_))}};
  }
  static std::uint64_t Hash(const Key& k) {
    return (std::uint64_t(k[0] & 0x1fffff) << 42) | (std::uint64_t(k[1] & 0x1fffff) << 21) | std::uint64_t(k[2] & 0x1fffff);
  }
  double ToSegment(const Eigen::Vector3d& p, int s) const {
    const Eigen::Vector3d &a = seg_[s].first, &b = seg_[s].second, d = b - a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::max(0.0, std::min(1.0, (p - a).dot(d) / len2)) : 0.0;
    return (a + t * d - p).norm();
  }
  double cell_;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> seg_;
  std::unordered_map<std::uint64_t, std::vector<int>> grid_;
};

// Points along a polyline's edges, each with the length it stands for: the midpoints of four
// equal pieces of every edge.
std::vector<std::pair<Eigen::Vector3d, double>> Samples(const std::vector<Eigen::Vector3d>& pos, int a, int b) {
  std::vector<std::pair<Eigen::Vector3d, double>> s;
  const double len = (pos[b] - pos[a]).norm();
  for (int i = 0; i < 4; ++i) s.push_back({pos[a] + (i + 0.5) / 4 * (pos[b] - pos[a]), len / 4});
  return s;
}

struct Measures {
  double precision = 0, recall = 0, f1 = 0, nearPrecision = 0, nearRecall = 0, nearF1 = 0;
  int linesFound = 0, linesTrue = 0, linesOnTruth = 0, trueLinesCovered = 0;
  double hausdorffMean = NAN, hausdorffMax = NAN, hausdorffSym = NAN, gapPct = 100, lineF1 = 0;
  int patchesFound = 0, patchesTrue = 0;
  double rand = 0, adjustedRand = 0;
};

double HarmonicMean(double p, double r) { return p + r > 0 ? 2 * p * r / (p + r) : 0; }

// Rand index and adjusted Rand index of two labellings of the same faces.
std::pair<double, double> RandIndices(const std::vector<int>& a, const std::vector<int>& b) {
  std::unordered_map<std::uint64_t, double> nij;
  std::unordered_map<int, double> ai, bj;
  for (std::size_t f = 0; f < a.size(); ++f) {
    ++nij[(std::uint64_t(std::uint32_t(a[f])) << 32) | std::uint32_t(b[f])];
    ++ai[a[f]];
    ++bj[b[f]];
  }
  auto pairs = [](double n) { return n * (n - 1) / 2; };
  double sij = 0, sa = 0, sb = 0;
  for (const auto& kv : nij) sij += pairs(kv.second);
  for (const auto& kv : ai) sa += pairs(kv.second);
  for (const auto& kv : bj) sb += pairs(kv.second);
  const double all = pairs(double(a.size()));
  if (all <= 0) return {1, 1};
  const double rand = 1 + (2 * sij - sa - sb) / all;
  const double expected = sa * sb / all, top = (sa + sb) / 2;
  const double adjusted = top - expected != 0 ? (sij - expected) / (top - expected) : 1;
  return {rand, adjusted};
}

Measures Measure(const PlainMesh& clean, double lave, const Network& truth, const Network& found) {
  Measures r;
  const std::vector<Eigen::Vector3d>& pos = clean.pos;
  // edges, strict
  std::vector<Edge> common;
  std::set_intersection(found.edges.begin(), found.edges.end(), truth.edges.begin(), truth.edges.end(),
                        std::back_inserter(common));
  r.precision = found.edges.empty() ? 1 : double(common.size()) / found.edges.size();
  r.recall = truth.edges.empty() ? 1 : double(common.size()) / truth.edges.size();
  r.f1 = HarmonicMean(r.precision, r.recall);
  // edges, within 1 l_ave
  const SegmentSet trueSet(pos, truth.edges, 2 * lave), foundSet(pos, found.edges, 2 * lave);
  auto mid = [&](const Edge& e) { return Eigen::Vector3d(0.5 * (pos[e[0]] + pos[e[1]])); };
  double ok = 0, hit = 0;
  for (const Edge& e : found.edges) ok += trueSet.Distance(mid(e)) <= lave;
  for (const Edge& e : truth.edges) hit += foundSet.Distance(mid(e)) <= lave;
  r.nearPrecision = found.edges.empty() ? 1 : ok / found.edges.size();
  r.nearRecall = truth.edges.empty() ? 1 : hit / truth.edges.size();
  r.nearF1 = HarmonicMean(r.nearPrecision, r.nearRecall);
  // lines found: how far each strays from the true lines
  r.linesFound = int(found.lines.size());
  r.linesTrue = int(truth.lines.size());
  double sum = 0, worst = 0;
  for (const auto& l : found.lines) {
    double h = 0;
    for (std::size_t i = 0; i + 1 < l.size(); ++i)
      for (const auto& s : Samples(pos, l[i], l[i + 1])) h = std::max(h, trueSet.Distance(s.first) / lave);
    for (int v : l) h = std::max(h, trueSet.Distance(pos[v]) / lave);
    r.linesOnTruth += h <= 1;
    sum += h;
    worst = std::max(worst, h);
  }
  if (!found.lines.empty()) {
    r.hausdorffMean = sum / found.lines.size();
    r.hausdorffMax = worst;
  }
  // true lines: how much of them no found line comes near
  double length = 0, uncovered = 0, farthest = 0;
  for (const auto& l : truth.lines) {
    double len = 0, missed = 0;
    for (std::size_t i = 0; i + 1 < l.size(); ++i)
      for (const auto& s : Samples(pos, l[i], l[i + 1])) {
        const double d = foundSet.Distance(s.first) / lave;
        farthest = std::max(farthest, d);
        len += s.second;
        if (d > 1) missed += s.second;
      }
    r.trueLinesCovered += missed <= 0.5 * len;
    length += len;
    uncovered += missed;
  }
  r.gapPct = length > 0 ? 100 * uncovered / length : 0;
  if (!found.lines.empty()) r.hausdorffSym = std::max(worst, farthest);
  const double linePrecision = found.lines.empty() ? 1 : double(r.linesOnTruth) / found.lines.size();
  r.lineF1 = HarmonicMean(linePrecision, 1 - r.gapPct / 100);
  // patches
  r.patchesFound = found.patches;
  r.patchesTrue = truth.patches;
  const std::pair<double, double> ri = RandIndices(truth.facePatch, found.facePatch);
  r.rand = ri.first;
  r.adjustedRand = ri.second;
  return r;
}

struct BenchMesh {
  std::string name, family;  // family: "synthetic", the CAD size ("export" .. "fine") or "ABC"
  TMesh clean;
  std::vector<Edge> trueEdges;
  unsigned seedBase = 11;  // the noise seeds of the "f1" (77) and "cad" (11) sections
  BenchMesh(const std::string& n, const std::string& f, unsigned seed) : name(n), family(f), seedBase(seed) {}
};

// The .truth file's sharp edges (make_cad_parts.py: after the vertex lines, "edges M" and M
// lines "a b angle convex").
bool TrueEdgesFromCadTruth(const std::string& path, std::vector<Edge>& edges) {
  std::ifstream in(path);
  std::string word;
  while (in >> word && word != "edges") {}
  std::size_t n = 0;
  if (!(in >> n)) return false;
  for (std::size_t i = 0; i < n; ++i) {
    int a, b, convex;
    double angle;
    in >> a >> b >> angle >> convex;
    edges.push_back(EdgeOf(a, b));
  }
  return bool(in);
}

// The ABC file's feature edges ("count", then "a b" per edge).
std::vector<Edge> TrueEdgesFromFea(const std::string& path) {
  std::ifstream in(path);
  int count = 0;
  in >> count;
  std::vector<Edge> edges;
  for (int i = 0; i < count; ++i) {
    int a, b;
    in >> a >> b;
    edges.push_back(EdgeOf(a, b));
  }
  return edges;
}

// Mesh edges whose two ends lie on one crease curve of the synthetic shape.
std::vector<Edge> TrueEdgesOfShape(const CreaseShape& s, const PlainMesh& m) {
  std::vector<unsigned> curves(m.pos.size());
  for (std::size_t v = 0; v < m.pos.size(); ++v)
    curves[v] = CreaseCurvesAt(s, vcg::Point3d(m.pos[v].x(), m.pos[v].y(), m.pos[v].z()));
  std::vector<Edge> edges;
  for (const auto& f : m.face)
    for (int j = 0; j < 3; ++j) {
      const int a = f[j], b = f[(j + 1) % 3];
      if (curves[a] & curves[b]) edges.push_back(EdgeOf(a, b));
    }
  return edges;
}

}  // namespace

int RunNetworks(const std::string& outDir, const std::string& partsDir, bool heldOut) {
  // Held out: other noise draws of the same meshes at the noise levels the defaults were tuned at,
  // to judge a threshold chosen on the first draw (draw 0, the "network" section's) on draws it
  // was not chosen on.
  const std::vector<unsigned> draws = heldOut ? std::vector<unsigned>{1, 2} : std::vector<unsigned>{0};
  const std::vector<double> noises =
      heldOut ? std::vector<double>{0.05, 0.10, 0.20} : std::vector<double>{0, 0.01, 0.05, 0.10, 0.20};
  std::vector<std::pair<unsigned, double>> runs;  // (draw, noise)
  for (unsigned draw : draws)
    for (double noise : noises) runs.emplace_back(draw, noise);
  const std::vector<double> angles = {20, 30, 45, 60};
  std::vector<std::unique_ptr<BenchMesh>> meshes;  // TMesh cannot be copied or moved
  for (double a : {20.0, 40.0, 60.0, 90.0, 120.0, 150.0, 175.0})
    meshes.emplace_back(new BenchMesh("roof " + std::to_string(int(a)) + "°", "synthetic", 77));
  meshes.emplace_back(new BenchMesh("cube", "synthetic", 77));
  meshes.emplace_back(new BenchMesh("capped cylinder", "synthetic", 77));
  {
    const CreaseShape shapes[] = {{"roof 20°", 20, 0}, {"roof 40°", 40, 0}, {"roof 60°", 60, 0}, {"roof 90°", 90, 0},
                                  {"roof 120°", 120, 0}, {"roof 150°", 150, 0}, {"roof 175°", 175, 0},
                                  {"cube", 90, 1}, {"capped cylinder", 90, 2}};
    for (std::size_t i = 0; i < meshes.size(); ++i) {
      BuildCreaseShape(shapes[i], meshes[i]->clean);
      meshes[i]->trueEdges = TrueEdgesOfShape(shapes[i], Context(meshes[i]->clean).plain);
    }
  }
  {
    std::ifstream list(partsDir + "/parts.txt");
    std::string name;
    while (list >> name) {
      std::unique_ptr<BenchMesh> b(new BenchMesh(name, name.substr(name.rfind('_') + 1), 11));
      if (!LoadMesh(partsDir + "/" + name + ".obj", b->clean) ||
          !TrueEdgesFromCadTruth(partsDir + "/" + name + ".truth", b->trueEdges)) {
        std::fprintf(stderr, "network: cannot read %s/%s.obj / .truth\n", partsDir.c_str(), name.c_str());
        return 2;
      }
      meshes.push_back(std::move(b));
    }
    const std::string abc = std::string(NVV_SHARED_MESHES) + "/real/abc_00000006";
    std::unique_ptr<BenchMesh> b(new BenchMesh("abc_00000006", "ABC", 11));
    if (LoadMesh(abc + ".obj", b->clean)) {
      b->trueEdges = TrueEdgesFromFea(abc + ".fea");
      meshes.push_back(std::move(b));
    } else {
      std::printf("<!-- abc_00000006.obj not found under ../shared/meshes/real: left out -->\n");
    }
  }

  const std::string columns =
      "family,mesh,noise,method,angle,edges_found,edges_true,precision,recall,f1,near_precision,near_recall,near_f1,"
      "lines_found,lines_true,lines_on_truth,true_lines_covered,hausdorff_mean,hausdorff_max,hausdorff_sym,gap_pct,"
      "line_f1,patches_found,patches_true,rand,adjusted_rand";
  Csv csv(outDir, heldOut ? "network_heldout.csv" : "network.csv", heldOut ? columns + ",draw" : columns);
  std::unique_ptr<Csv> tcsv;  // the truth's counts, once (with draw 0)
  if (!heldOut) {
    tcsv.reset(new Csv(outDir, "network_truth.csv",
                       "family,mesh,vertices,faces,l_ave,edges,lines,closed_lines,patches,small_patches"));
    std::printf("| family | mesh | vertices | faces | true crease edges | true lines | true patches |\n"
                "|---|---|---|---|---|---|---|\n");
  }
  for (const auto& bp : meshes) {
    const BenchMesh& b = *bp;
    const double lave = nvv_shapes::MeanEdge(b.clean);
    const Context c0(b.clean);
    const Network truth = FromSelectedEdges(c0.plain, b.trueEdges);
    int closed = 0;
    for (const auto& l : truth.lines) closed += l.size() > 2 && l.front() == l.back();
    // true patches smaller than the filter's network keeps apart (tiny ones it merges as noise)
    std::vector<int> patchFaces(std::size_t(truth.patches), 0);
    for (int p : truth.facePatch) ++patchFaces[p];
    const int small = int(std::count_if(patchFaces.begin(), patchFaces.end(),
                                        [](int n) { return n < nvv::tuning::kMinPatchFaces; }));
    if (tcsv) {
      std::printf("| %s | %s | %zu | %zu | %zu | %zu | %d |\n", b.family.c_str(), b.name.c_str(), c0.plain.pos.size(),
                  c0.plain.face.size(), truth.edges.size(), truth.lines.size(), truth.patches);
      std::fprintf(tcsv->f(), "%s,%s,%zu,%zu,%g,%zu,%zu,%d,%d,%d\n", b.family.c_str(), b.name.c_str(),
                   c0.plain.pos.size(), c0.plain.face.size(), lave, truth.edges.size(), truth.lines.size(), closed,
                   truth.patches, small);
    }
    for (const auto& run : runs) {
      const unsigned draw = run.first;
      const double noise = run.second;
      TMesh m;
      vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, const_cast<TMesh&>(b.clean));
      const unsigned seed = b.seedBase + kHeldOutSeedStep * draw +
                            (b.family == "synthetic" ? unsigned(1000 * noise) : unsigned(10000 * noise));
      NoiseAlongNormals(m, noise * lave, seed);
      const Context c(m);
      auto row = [&](const char* method, double angle, const Network& n) {
        const Measures x = Measure(c0.plain, lave, truth, n);
        std::fprintf(csv.f(), "%s,%s,%g,%s,%g,%zu,%zu,%g,%g,%g,%g,%g,%g,%d,%d,%d,%d,%g,%g,%g,%g,%g,%d,%d,%g,%g",
                     b.family.c_str(), b.name.c_str(), noise * 100, method, angle, n.edges.size(), truth.edges.size(),
                     x.precision, x.recall, x.f1, x.nearPrecision, x.nearRecall, x.nearF1, x.linesFound, x.linesTrue,
                     x.linesOnTruth, x.trueLinesCovered, x.hausdorffMean, x.hausdorffMax, x.hausdorffSym, x.gapPct,
                     x.lineF1, x.patchesFound, x.patchesTrue, x.rand, x.adjustedRand);
        if (heldOut) std::fprintf(csv.f(), ",%u", draw);
        std::fputc('\n', csv.f());
      };
      row("NVV defaults", nvv::FilterOptions().core.creaseAngleDeg, FilterNetwork(m));
      for (double a : angles) {
        row("NVV phi", a, FilterNetwork(m, a));
        row("MeshLab dihedral", a, FromSelectedEdges(c.plain, DihedralCreaseEdgesSorted(m, a)));
        Network cg;
        std::vector<Edge> edges;
        cg.patches = CgalSharpEdgesSegmentation(c.plain, a, edges, cg.facePatch);
        cg.edges = edges;
        SortUnique(cg.edges);
        cg.lines = ChainLines(cg.edges, c.plain.pos.size());
        row("CGAL sharp edges", a, cg);
      }
      std::fflush(csv.f());
      std::fprintf(stderr, "network: %s %g %% (draw %u)\n", b.name.c_str(), noise * 100, draw);
    }
  }
  return 0;
}

}  // namespace nvv_bench
