#include "crease_network.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>

#include "params.h"
#include "tuning.h"

namespace nvv {
namespace {

using Edge = std::array<int, 2>;

Edge Key(int a, int b) { return a < b ? Edge{{a, b}} : Edge{{b, a}}; }

bool IsCrease(const VertexResult& r) { return r.cls == VertexClass::Crease && r.Has(kCreaseValid); }

// Calls fn(a, b, f, o) once for every edge held by exactly two faces f < o.
template <class Fn>
void ForEachInteriorEdge(const SurfaceGraph& g, Fn fn) {
  for (int f = 0; f < g.FaceCount(); ++f)
    for (int j = 0; j < 3; ++j) {
      if ((g.nonManifoldEdges[f] >> j) & 1) continue;
      const int a = g.face[f][j], b = g.face[f][j == 2 ? 0 : j + 1];
      g.ForEachFaceAcross(f, a, b, [&](int o) {
        if (o > f) fn(a, b, f, o);
      });
    }
}

// True when the edge (a, b) between faces f and o lies on a crease; cusp: its angle (radians).
// cosCornerPair: the cosine of the angle the faces of an edge between two corners must reach.
bool CreaseEdgeTest(const SurfaceGraph& g, const std::vector<VertexResult>& res, int a, int b, int f, int o,
                    double cosCornerPair, double& cusp) {
  const VertexResult &ra = res[a], &rb = res[b];
  if (!IsFeature(ra) || !IsFeature(rb) || !(g.faceArea[f] > 0) || !(g.faceArea[o] > 0)) return false;
  const Eigen::Vector3d& Nf = g.faceNormal[f];
  const Eigen::Vector3d& No = g.faceNormal[o];
  if (!IsCrease(ra) && !IsCrease(rb)) {  // two corners: no tangent, only the faces can say
    const double c = std::max(-1.0, std::min(1.0, Nf.dot(No)));
    cusp = std::acos(c);
    return c < cosCornerPair;
  }
  // The two sheets as pass 1 saw them at the edge's crease end(s): tangent T, bisector n, cusp angle.
  Eigen::Vector3d T = Eigen::Vector3d::Zero(), n = Eigen::Vector3d::Zero();
  double alpha = 0;
  int count = 0;
  for (const VertexResult* r : {&ra, &rb}) {
    if (!IsCrease(*r)) continue;
    Eigen::Vector3d t = ToVec(r->creaseTangent), nn = ToVec(r->normal);
    if (count > 0 && t.dot(T) < 0) t = -t;
    if (count > 0 && nn.dot(n) < 0) nn = -nn;
    T += t;
    n += nn;
    alpha += r->cuspAngle;
    ++count;
  }
  alpha /= count;
  const Eigen::Vector3d d = g.pos[b] - g.pos[a];
  if (!(T.norm() > 0) || !(d.norm() > 0)) return false;
  T.normalize();
  if (std::abs(d.normalized().dot(T)) < tuning::kCreaseEdgeMinCosToTangent) return false;
  Eigen::Vector3d across = T.cross(n);
  if (!(across.norm() > 0)) return false;
  across.normalize();
  // Two sheets alpha apart have normals whose components across the line differ by 2 sin(alpha/2);
  // faces of one sheet, by noise only.
  cusp = alpha;
  return std::abs((Nf - No).dot(across)) >= tuning::kCreaseEdgeMinLean * 2.0 * std::sin(alpha / 2);
}

// Crease edges per vertex, CSR.
struct Incidence {
  std::vector<int> start, edge;
  Incidence(int n, const std::vector<Edge>& edges) : start(std::size_t(n) + 1, 0), edge(2 * edges.size()) {
    for (const auto& e : edges) ++start[e[0] + 1], ++start[e[1] + 1];
    for (int v = 0; v < n; ++v) start[v + 1] += start[v];
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int i = 0; i < int(edges.size()); ++i) edge[fill[edges[i][0]]++] = i, edge[fill[edges[i][1]]++] = i;
  }
  int Degree(int v) const { return start[v + 1] - start[v]; }
};

std::vector<CreaseLine> TraceLines(const SurfaceGraph& g, const std::vector<VertexResult>& res,
                                   const std::vector<Edge>& edges, const std::vector<float>& cusp,
                                   std::vector<int>& edgeLine) {
  const int n = g.VertexCount();
  const Incidence inc(n, edges);
  auto junction = [&](int v) { return res[v].cls == VertexClass::Corner || inc.Degree(v) != 2; };
  edgeLine.assign(edges.size(), -1);
  std::vector<CreaseLine> lines;
  auto walk = [&](int from, int e) {
    CreaseLine line;
    const int id = int(lines.size());
    line.vertices.push_back(from);
    double cuspSum = 0;
    int cur = from;
    while (true) {
      edgeLine[e] = id;
      const int next = edges[e][0] == cur ? edges[e][1] : edges[e][0];
      const double len = (g.pos[next] - g.pos[cur]).norm();
      line.length += len;
      cuspSum += len * cusp[e];
      if (next == from) { line.closed = true; break; }
      line.vertices.push_back(next);
      if (junction(next)) break;
      int onward = -1;
      for (int i = inc.start[next]; i < inc.start[next + 1]; ++i)
        if (edgeLine[inc.edge[i]] < 0) onward = inc.edge[i];
      if (onward < 0) break;
      cur = next;
      e = onward;
    }
    line.meanCuspAngle = line.length > 0 ? cuspSum / line.length : 0;
    if (!line.closed) {
      if (res[line.vertices.front()].cls == VertexClass::Corner) line.endCorner[0] = line.vertices.front();
      if (res[line.vertices.back()].cls == VertexClass::Corner) line.endCorner[1] = line.vertices.back();
    }
    lines.push_back(std::move(line));
  };
  for (int v = 0; v < n; ++v)
    if (inc.Degree(v) > 0 && junction(v))
      for (int i = inc.start[v]; i < inc.start[v + 1]; ++i)
        if (edgeLine[inc.edge[i]] < 0) walk(v, inc.edge[i]);
  for (int e = 0; e < int(edges.size()); ++e)  // what is left is closed loops of plain crease vertices
    if (edgeLine[e] < 0) walk(edges[e][0], e);
  return lines;
}

// Continues each line that stops at a crease vertex off the border (a gap, not an end): the
// shortest path (through feature vertices and along edges that turn where it can), within `radius`
// and ahead of the line's direction, to a vertex of another line (or of its own, when that closes a
// line longer than 2 g_m) or of the border: under noise the last vertices before the border may
// vote like one sheet, and a line one edge short of it leaves its two sheets one patch. A crease
// vertex whose line runs parallel to this one, beside it rather than ahead, is not a target: that is
// the other line of a chamfer, not this line's continuation. Returns the edges added.
std::vector<Edge> GapEdges(const SurfaceGraph& g, const std::vector<VertexResult>& res, const std::vector<Edge>& edges,
                           const std::vector<CreaseLine>& lines, const std::vector<int>& edgeLine, double radius,
                           double creaseAngleDeg) {
  const double cosFlatEdge = std::cos(DegToRad(tuning::kGapFlatEdgeOverCreaseAngle * creaseAngleDeg));
  const int n = g.VertexCount();
  const Incidence inc(n, edges);
  std::vector<int> lineOf(n, -1);
  for (int e = 0; e < int(edges.size()); ++e) lineOf[edges[e][0]] = lineOf[edges[e][1]] = edgeLine[e];
  std::vector<Edge> added;
  std::vector<double> dist(n, -1);
  std::vector<int> parent(n, -1), touched;
  for (int v = 0; v < n; ++v) {
    if (inc.Degree(v) != 1 || !IsCrease(res[v]) || g.OnBorder(v)) continue;
    const int e0 = inc.edge[inc.start[v]];
    const int prev = edges[e0][0] == v ? edges[e0][1] : edges[e0][0];
    const CreaseLine& own = lines[edgeLine[e0]];
    // The line's direction at v, from a few vertices back (one noisy edge can turn 45 deg).
    const std::vector<int>& lv = own.vertices;
    const int back = std::min<int>(tuning::kGapDirectionEdges, int(lv.size()) - 1);
    const int from = lv.front() == v ? lv[back] : lv[lv.size() - 1 - back];
    const Eigen::Vector3d ahead = (g.pos[v] - g.pos[from]).normalized();
    // Dijkstra over edges between feature vertices, from v, within the radius.
    typedef std::pair<double, int> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> front;
    dist[v] = 0;
    touched.push_back(v);
    front.push({0.0, v});
    int target = -1;
    while (!front.empty() && target < 0) {
      const Item it = front.top();
      front.pop();
      const int x = it.second;
      if (it.first > dist[x]) continue;
      if (x != v && (lineOf[x] >= 0 || g.OnBorder(x))) {
        const bool sameLine = lineOf[x] == edgeLine[e0];
        const Eigen::Vector3d step = g.pos[x] - g.pos[v];
        const bool ahead45 = step.normalized().dot(ahead) >= tuning::kCreaseEdgeMinCosToTangent;
        const bool beside = !sameLine && IsCrease(res[x]) &&
                            std::abs(ToVec(res[x].creaseTangent).normalized().dot(ahead)) >= tuning::kCosSameLine &&
                            (step - step.dot(ahead) * ahead).norm() > tuning::kGapSideStepEdges * g.meanEdge;
        if (ahead45 && !beside && (!sameLine || own.length > 2 * radius)) target = x;
        continue;  // a line or border vertex ends the search there either way
      }
      for (int i = g.FaceBegin(x); i < g.FaceEnd(x); ++i)
        for (int y : g.face[g.vfList[i]]) {
          if (y == x || y == prev || (g.pos[y] - g.pos[v]).norm() > radius) continue;
          // Through feature vertices where it can: a surface vertex costs its edge twice; and along
          // edges that turn: one whose faces turn less than kGapFlatEdgeOverCreaseAngle times the
          // crease angle costs kGapFlatEdgeCost times more (a path across a face cuts a corner).
          const int f = g.vfList[i];
          double cosTurn = 1;
          g.ForEachFaceAcross(f, x, y,
                              [&](int o) { cosTurn = std::min(cosTurn, g.faceNormal[f].dot(g.faceNormal[o])); });
          const double flat = cosTurn > cosFlatEdge ? tuning::kGapFlatEdgeCost : 1.0;
          const double d = dist[x] + (g.pos[y] - g.pos[x]).norm() * (IsFeature(res[y]) ? 1.0 : 2.0) * flat;
          if (dist[y] >= 0 && dist[y] <= d) continue;
          if (dist[y] < 0) touched.push_back(y);
          dist[y] = d;
          parent[y] = x;
          front.push({d, y});
        }
    }
    if (target >= 0)
      for (int x = target; x != v; x = parent[x]) added.push_back(Key(x, parent[x]));
    for (int x : touched) dist[x] = -1, parent[x] = -1;
    touched.clear();
  }
  std::sort(added.begin(), added.end());
  added.erase(std::unique(added.begin(), added.end()), added.end());
  return added;
}

// Drops the lines that stop at a crease vertex off the border (a free end) and are shorter than
// g_m: what is left of noise around a crease once its gaps are closed. Returns how many edges.
std::size_t DropSpurs(const SurfaceGraph& g, const std::vector<VertexResult>& res, std::vector<Edge>& edges,
                      std::vector<float>& cusp, const std::vector<CreaseLine>& lines, const std::vector<int>& edgeLine,
                      double radius) {
  const Incidence inc(g.VertexCount(), edges);
  auto freeEnd = [&](int v) { return inc.Degree(v) == 1 && IsCrease(res[v]) && !g.OnBorder(v); };
  std::vector<char> drop(lines.size(), 0);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const CreaseLine& l = lines[i];
    drop[i] = !l.closed && l.length < radius && (freeEnd(l.vertices.front()) || freeEnd(l.vertices.back()));
  }
  std::size_t kept = 0, dropped = 0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (drop[edgeLine[e]]) { ++dropped; continue; }
    edges[kept] = edges[e];
    cusp[kept++] = cusp[e];
  }
  edges.resize(kept);
  cusp.resize(kept);
  return dropped;
}

int Find(std::vector<int>& up, int x) {
  while (up[x] != x) x = up[x] = up[up[x]];
  return x;
}

// Two faces across an interior edge (f < o), and what parts them there (a LinkKind).
using FaceLink = std::array<int, 3>;
enum LinkKind : int {
  kJoined = 0,       // nothing: a patch's faces join across it
  kCreaseLink = 1,   // a crease edge
  kNormalsJump = 2,  // no crease edge, but the faces' smoothed normals jump (NormalsJump)
};

// Each face's smoothed normal: the sum of the final normals of its SURFACE vertices (voted, or fitted
// by pass 2), normalised; zero where it has none. Feature vertices carry a bisector, not a sheet's normal.
std::vector<Eigen::Vector3d> SmoothedFaceNormals(const SurfaceGraph& g, const std::vector<VertexResult>& res) {
  std::vector<Eigen::Vector3d> n(g.FaceCount(), Eigen::Vector3d::Zero());
  for (int f = 0; f < g.FaceCount(); ++f) {
    for (int v : g.face[f])
      if (res[v].cls == VertexClass::Surface && res[v].Has(kNormalValid))
        n[f] += Eigen::Vector3d(res[v].normal[0], res[v].normal[1], res[v].normal[2]);
    if (n[f].squaredNorm() > 0) n[f].normalize();
  }
  return n;
}

// True when the smoothed normals of two faces (SmoothedFaceNormals) are more than the angle of
// cosine cosJump apart: under noise a crease the votes saw only in part (a gap gap closing could not
// bridge, a stretch no vertex of which stayed a crease) still parts the normals of the surface
// vertices on its two sides, each estimated from its own sheet.
bool NormalsJump(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double cosJump) {
  return a.squaredNorm() > 0 && b.squaredNorm() > 0 && a.dot(b) < cosJump;
}

// The faces next to each face across the links that pass `keep`, CSR.
struct FaceNeighbours {
  std::vector<int> start, face;
  template <class Keep>
  FaceNeighbours(int nf, const std::vector<FaceLink>& links, Keep keep) : start(std::size_t(nf) + 1, 0) {
    for (const auto& l : links)
      if (keep(l)) ++start[l[0] + 1], ++start[l[1] + 1];
    for (int f = 0; f < nf; ++f) start[f + 1] += start[f];
    face.resize(start[nf]);
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (const auto& l : links)
      if (keep(l)) face[fill[l[0]]++] = l[1], face[fill[l[1]]++] = l[0];
  }
};

// How far each face's centroid is from the nearest of the source faces, walking centroid to
// centroid between neighbours (Dijkstra); +inf where none is reached.
std::vector<double> FaceDistance(const std::vector<Eigen::Vector3d>& centroid, const FaceNeighbours& next,
                                 const std::vector<int>& sources) {
  std::vector<double> dist(centroid.size(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  for (int f : sources)
    if (dist[f] > 0) dist[f] = 0, heap.push({0.0, f});
  while (!heap.empty()) {
    const double d = heap.top().first;
    const int f = heap.top().second;
    heap.pop();
    if (d > dist[f]) continue;
    for (int i = next.start[f]; i < next.start[f + 1]; ++i) {
      const int o = next.face[i];
      const double nd = d + (centroid[o] - centroid[f]).norm();
      if (nd < dist[o]) dist[o] = nd, heap.push({nd, o});
    }
  }
  return dist;
}

// Faces grouped into patches bounded by the crease edges. On a noisy mesh a crease line can keep a
// gap of a few edges that gap closing could not bridge, and a plain flood across every non-crease
// edge then runs through it and makes two sheets one patch. So two faces whose smoothed normals jump
// by more than tuning::kPatchNormalJumpOverCreaseAngle times the crease angle do not join across
// their edge (NormalsJump), and the faces join in a priority flood
// from the farthest from any crease inwards (a watershed of the distance to the crease edges): a
// face joins the patch of a neighbour across a non-crease edge, and where it touches two patches it
// joins them too, unless it stands in a gap: a line's free end about as near as the crease edges
// (AtALineEnd), and a neck narrower than tuning::kPatchNeckRatio times the smaller patch's widest
// point (its distance to the creases against that patch's largest). On a clean mesh (watershed
// false) every face joins every neighbour across a non-crease edge. Patches smaller than minFaces
// are then merged into the neighbour they share the longest border with.
void GrowPatches(const SurfaceGraph& g, const std::vector<VertexResult>& res, const std::vector<Edge>& edges,
                 double creaseAngleDeg, int minFaces, bool watershed, CreaseNetwork& net) {
  const int nf = g.FaceCount();
  std::vector<int> up(nf);
  std::iota(up.begin(), up.end(), 0);
  auto isCrease = [&](int a, int b) { return std::binary_search(edges.begin(), edges.end(), Key(a, b)); };
  std::vector<FaceLink> links;
  ForEachInteriorEdge(g, [&](int a, int b, int f, int o) {
    links.push_back({{f, o, isCrease(a, b) ? kCreaseLink : kJoined}});
  });
  if (watershed) {
    const std::vector<Eigen::Vector3d> normal = SmoothedFaceNormals(g, res);
    const double cosJump = std::cos(DegToRad(tuning::kPatchNormalJumpOverCreaseAngle * creaseAngleDeg));
    for (auto& l : links)
      if (l[2] == kJoined && NormalsJump(normal[l[0]], normal[l[1]], cosJump)) l[2] = kNormalsJump;
  }
  // The faces around the lines' free ends (a gap's two sides); without one no line has a gap.
  std::vector<int> ends;
  if (watershed) {
    const Incidence inc(g.VertexCount(), edges);
    for (int v = 0; v < g.VertexCount(); ++v)
      if (inc.Degree(v) == 1 && !g.OnBorder(v))
        for (int i = g.FaceBegin(v); i < g.FaceEnd(v); ++i) ends.push_back(g.vfList[i]);
  }
  if (ends.empty()) {
    for (const auto& l : links)
      if (l[2] == kJoined) up[Find(up, l[1])] = Find(up, l[0]);
  } else {
    // The distances are to the crease edges only: a jump of the normals parts two faces but is no line.
    std::vector<int> sides;
    for (const auto& l : links)
      if (l[2] == kCreaseLink) sides.push_back(l[0]), sides.push_back(l[1]);
    std::vector<Eigen::Vector3d> centroid(nf);
    for (int f = 0; f < nf; ++f) centroid[f] = (g.pos[g.face[f][0]] + g.pos[g.face[f][1]] + g.pos[g.face[f][2]]) / 3.0;
    const FaceNeighbours acrossAny(nf, links, [](const FaceLink&) { return true; });
    const std::vector<double> dist = FaceDistance(centroid, acrossAny, sides);
    const std::vector<double> endDist = FaceDistance(centroid, acrossAny, ends);
    // A neck is a gap when a line's free end is about as near as the crease edges are.
    auto AtALineEnd = [&](int f) {
      return endDist[f] <= tuning::kPatchGapEndDistance * dist[f] + tuning::kPatchGapEndSlackEdges * g.meanEdge;
    };
    std::vector<int> order(nf);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int x, int y) { return dist[x] != dist[y] ? dist[x] > dist[y] : x < y; });
    const FaceNeighbours across(nf, links, [](const FaceLink& l) { return l[2] == kJoined; });
    std::vector<double> peak(nf, 0);  // per root: the patch's largest distance
    std::vector<char> done(nf, 0);
    std::vector<int> roots;
    for (int f : order) {
      done[f] = 1;
      peak[f] = dist[f];
      roots.clear();
      for (int i = across.start[f]; i < across.start[f + 1]; ++i)
        if (done[across.face[i]]) roots.push_back(Find(up, across.face[i]));
      if (roots.empty()) continue;
      // The deepest patch first (ties by root), then every other one it may join.
      std::sort(roots.begin(), roots.end(), [&](int x, int y) { return peak[x] != peak[y] ? peak[x] > peak[y] : x < y; });
      roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
      const int deepest = roots[0];
      up[f] = deepest;
      for (std::size_t i = 1; i < roots.size(); ++i) {
        const int r = Find(up, roots[i]), m = Find(up, deepest);
        if (r == m || (AtALineEnd(f) && dist[f] < tuning::kPatchNeckRatio * std::min(peak[r], peak[m]))) continue;
        up[r] = m;
        peak[m] = std::max(peak[m], peak[r]);
      }
    }
  }
  std::vector<int> size(nf, 0);
  for (int f = 0; f < nf; ++f) ++size[Find(up, f)];
  // The faces on either side of each patch border (crease edges, and the necks the watershed kept),
  // per patch as first grown (CSR by root), so merging costs what the small patches' borders hold,
  // not their number times every border edge.
  std::vector<std::array<int, 2>> creasePairs;
  for (const auto& l : links)
    if (Find(up, l[0]) != Find(up, l[1])) creasePairs.push_back({{l[0], l[1]}});
  std::vector<int> pairStart(std::size_t(nf) + 1, 0), pairList(2 * creasePairs.size());
  for (const auto& fo : creasePairs) ++pairStart[Find(up, fo[0]) + 1], ++pairStart[Find(up, fo[1]) + 1];
  for (int f = 0; f < nf; ++f) pairStart[f + 1] += pairStart[f];
  {
    std::vector<int> fill(pairStart.begin(), pairStart.end() - 1);
    for (int i = 0; i < int(creasePairs.size()); ++i)
      pairList[fill[Find(up, creasePairs[i][0])]++] = i, pairList[fill[Find(up, creasePairs[i][1])]++] = i;
  }
  // Small patches, smallest first (ties by root), each into its best-connected neighbour.
  std::vector<int> small;
  for (int f = 0; f < nf; ++f)
    if (Find(up, f) == f && size[f] < minFaces) small.push_back(f);
  std::sort(small.begin(), small.end(), [&](int x, int y) { return size[x] != size[y] ? size[x] < size[y] : x < y; });
  std::vector<int> neighbours;
  for (int p : small) {
    const int root = Find(up, p);
    if (size[root] >= minFaces) continue;  // grown by an earlier merge
    neighbours.clear();
    for (int i = pairStart[p]; i < pairStart[p + 1]; ++i) {
      const int x = Find(up, creasePairs[pairList[i]][0]), y = Find(up, creasePairs[pairList[i]][1]);
      if (x == root && y != root) neighbours.push_back(y);
      if (y == root && x != root) neighbours.push_back(x);
    }
    if (neighbours.empty()) continue;
    std::sort(neighbours.begin(), neighbours.end());
    int best = -1, bestCount = 0;
    for (std::size_t i = 0; i < neighbours.size();) {
      std::size_t j = i;
      while (j < neighbours.size() && neighbours[j] == neighbours[i]) ++j;
      if (int(j - i) > bestCount) best = neighbours[i], bestCount = int(j - i);
      i = j;
    }
    size[best] += size[root];
    up[root] = best;
  }
  // Patch ids in the order of each patch's first face.
  net.facePatch.assign(nf, -1);
  std::vector<int> id(nf, -1), count;
  for (int f = 0; f < nf; ++f) {
    const int r = Find(up, f);
    if (id[r] < 0) id[r] = int(count.size()), count.push_back(0);
    net.facePatch[f] = id[r];
    ++count[id[r]];
  }
  net.patchCount = int(count.size());
  net.smallestPatch = count.empty() ? 0 : *std::min_element(count.begin(), count.end());
  net.largestPatch = count.empty() ? 0 : *std::max_element(count.begin(), count.end());
}

}  // namespace

CreaseNetwork FindCreaseNetwork(const SurfaceGraph& g, const std::vector<VertexResult>& res, double radius,
                                double creaseAngleDeg, bool cleanMesh) {
  CreaseNetwork net;
  const double cosCornerPair = std::cos(DegToRad(std::max(creaseAngleDeg, tuning::kCornerPairEdgeMinAngleDeg)));
  std::vector<std::pair<Edge, float>> found;
  ForEachInteriorEdge(g, [&](int a, int b, int f, int o) {
    double cusp = 0;
    if (CreaseEdgeTest(g, res, a, b, f, o, cosCornerPair, cusp)) found.push_back({Key(a, b), float(cusp)});
  });
  std::sort(found.begin(), found.end());
  for (const auto& e : found) net.edges.push_back(e.first), net.edgeCuspAngle.push_back(e.second);

  // Gaps: lines first, then the edges that continue them, then the lines again.
  net.lines = TraceLines(g, res, net.edges, net.edgeCuspAngle, net.edgeLine);
  const std::vector<Edge> gaps = GapEdges(g, res, net.edges, net.lines, net.edgeLine, tuning::kGapReachOverRadius * radius,
                                            creaseAngleDeg);
  if (!gaps.empty()) {
    std::vector<std::pair<Edge, float>> all;
    for (std::size_t i = 0; i < net.edges.size(); ++i) all.push_back({net.edges[i], net.edgeCuspAngle[i]});
    for (const auto& e : gaps) {
      if (std::binary_search(net.edges.begin(), net.edges.end(), e)) continue;
      const VertexResult &ra = res[e[0]], &rb = res[e[1]];
      const float cusp = IsCrease(ra) && IsCrease(rb) ? 0.5f * (ra.cuspAngle + rb.cuspAngle)
                                                      : (IsCrease(ra) ? ra.cuspAngle : rb.cuspAngle);
      all.push_back({e, cusp});
      ++net.gapEdges;
    }
    std::sort(all.begin(), all.end());
    net.edges.clear();
    net.edgeCuspAngle.clear();
    for (const auto& e : all) net.edges.push_back(e.first), net.edgeCuspAngle.push_back(e.second);
    net.lines = TraceLines(g, res, net.edges, net.edgeCuspAngle, net.edgeLine);
  }
  net.spurEdges = DropSpurs(g, res, net.edges, net.edgeCuspAngle, net.lines, net.edgeLine, radius);
  if (net.spurEdges > 0) net.lines = TraceLines(g, res, net.edges, net.edgeCuspAngle, net.edgeLine);
  GrowPatches(g, res, net.edges, creaseAngleDeg, cleanMesh ? 1 : tuning::kMinPatchFaces, !cleanMesh, net);
  return net;
}

}  // namespace nvv
