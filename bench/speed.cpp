// nvv_bench_speed: wall time, throughput and peak memory of Normal Vector Voting on large meshes,
// with MeshLab's curvature estimators (the vcglib functions behind "Compute curvature principal
// directions": Taubin one-ring, Normal Cycles, Quadric Fitting, PCA) and CGAL's
// Monge_via_jet_fitting timed on the same mesh in the same run, printed as ratios to ours.
// Prints Markdown tables; scripts/run-speed-bench.sh writes them into docs/performance.md.
//
// Meshes: the real scans of ../shared/meshes/real as they are (bunny.off, rocker-arm.obj,
// casting.off; 5-35 k vertices), turbineblade.ply (199 k faces), its 1-to-4 midpoint subdivisions
// (~0.8 M and ~3.2 M faces; each subdivided mesh gets Gaussian noise of 2 % of its l_ave along
// the normals, seeded) and a generated torus of ~1 M vertices (near-equilateral grid, same noise).
//
// The full matrix (4 meshes x k = 1, 3, 5, 8 x threads 1, 2) takes over an hour on two cores, so
// the default plan (about 10 minutes) measures what the speed goals need (docs/performance.md;
// `plan` in main):
//   - time vs k: every k on the blade (both thread counts) and on the torus (all cores);
//   - time vs n: k = 3, one thread, on the blade and its two subdivisions (same surface);
//   - speed-up: k = 3 on one thread and on all cores, on every mesh;
//   - MeshLab's and CGAL's estimators once per mesh; ratios use our k = 3 total on all cores.
// The columns CPU (s) (user + system, all threads) and load (one-minute load average after the
// run) show whether other jobs shared the cores during a run.
// --full runs the full matrix; --quick only the real scans, the blade and the torus at k = 3.
//
// Peak memory is the process's peak resident set during Compute() minus what was resident
// before it (VmHWM after resetting it through /proc/self/clear_refs), i.e. what our graph,
// scratch and results cost on top of the mesh; large blocks are forced to mmap so that memory
// freed by an earlier run cannot hide a later run's allocations. The yardstick "mesh MB" is the
// vcg mesh as this program holds it (sizeof of its vertex and face types times their counts:
// positions, normals, VF/FF adjacency, curvature, colour, quality, flags).
//
// Every run prints a 64-bit hash of all per-vertex results, so different thread counts (and
// different builds of the core) can be checked to give the same bits.
//
// Usage: nvv_bench_speed [SHARED_MESHES_DIR] [--quick | --full] [--only NAME-SUBSTRING] [--ours-only]
//                        [--fit_rounds N] [--cubic_fit 0|1]   (the core's defaults otherwise)
#ifdef NVV_SPEED_CGAL_PART
// CGAL's estimator, compiled in its own translation unit (this file built a second time with
// NVV_SPEED_CGAL_PART): CGAL's build flags (-frounding-math) must not reach our core, and CGAL
// and vcglib headers are kept apart.
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>

#include <array>
#include <chrono>
#include <vector>

namespace nvv_speed {
// Seconds for a degree-2 jet / degree-2 Monge fit at every point, on the points within
// `radius` (Euclidean, found with CGAL's kd-tree; building and querying the tree is timed too).
// Points with fewer than 6 neighbours (a degree-2 jet has 6 coefficients) are skipped.
double CgalJetSeconds(const std::vector<std::array<double, 3>>& p, double radius, std::size_t& fitted) {
  typedef CGAL::Simple_cartesian<double> K;
  typedef CGAL::Search_traits_3<K> Traits;
  typedef CGAL::Kd_tree<Traits> Tree;
  typedef CGAL::Fuzzy_sphere<Traits> Sphere;
  typedef CGAL::Monge_via_jet_fitting<K> Fitting;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<K::Point_3> pts;
  pts.reserve(p.size());
  for (const auto& q : p) pts.push_back(K::Point_3(q[0], q[1], q[2]));
  Tree tree(pts.begin(), pts.end());
  tree.build();
  std::vector<K::Point_3> nb;
  fitted = 0;
  double sink = 0;
  for (const auto& q : pts) {
    nb.clear();
    tree.search(std::back_inserter(nb), Sphere(q, radius, 0.0));
    if (nb.size() < 6) continue;
    try {
      Fitting fit;
      const Fitting::Monge_form mf = fit(nb.begin(), nb.end(), 2, 2);
      sink += mf.principal_curvatures(0);
      ++fitted;
    } catch (...) {  // a CGAL precondition on a degenerate neighbourhood: that point is skipped
    }
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return sink == sink ? s : s;  // keeps the fits from being optimised away
}
}  // namespace nvv_speed

#else  // the benchmark proper

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/curvature.h>
#include <vcg/complex/algorithms/update/curvature_fitting.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <wrap/io_trimesh/import_ply.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/normal_vector_voting.h"
#include "mesh_files.h"
#include "sample_meshes/synthetic_shapes.h"

namespace nvv_speed {
double CgalJetSeconds(const std::vector<std::array<double, 3>>& p, double radius, std::size_t& fitted);
}

namespace {

// A float mesh with what MeshLab's estimators need (as CMeshO has them enabled by that filter).
class BVertex;
class BFace;
struct BTypes : vcg::UsedTypes<vcg::Use<BVertex>::AsVertexType, vcg::Use<BFace>::AsFaceType> {};
class BVertex : public vcg::Vertex<BTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::VFAdj,
                                   vcg::vertex::Curvaturef, vcg::vertex::CurvatureDirf, vcg::vertex::Qualityf,
                                   vcg::vertex::Color4b, vcg::vertex::Mark, vcg::vertex::BitFlags> {};
class BFace : public vcg::Face<BTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::VFAdj,
                               vcg::face::FFAdj, vcg::face::Mark, vcg::face::BitFlags> {};
class BMesh : public vcg::tri::TriMesh<std::vector<BVertex>, std::vector<BFace>> {};

double Now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// Resets the peak resident set (VmHWM) to the current one (Linux >= 4.0).
void ResetPeak() { std::ofstream("/proc/self/clear_refs") << "5"; }
// A field of /proc/self/status in MB (VmHWM: peak resident, VmRSS: current resident).
double StatusMB(const std::string& key) {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind(key + ":", 0) == 0) return std::stod(line.substr(key.size() + 1)) / 1024.0;
  return 0;
}
double MeshMB(const BMesh& m) {
  return (m.vert.size() * double(sizeof(BVertex)) + m.face.size() * double(sizeof(BFace))) / (1024.0 * 1024.0);
}

void Noise(BMesh& m, double fraction, unsigned seed) {
  vcg::tri::UpdateNormal<BMesh>::PerVertexNormalizedPerFace(m);
  const double sigma = fraction * nvv_shapes::MeanEdge(m);
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, sigma);
  for (auto& v : m.vert) v.P() += v.N() * float(g(rng));
}
// vcglib's 1-to-4 midpoint subdivision (every edge split at its midpoint).
void Subdivide(BMesh& m) {
  vcg::tri::UpdateTopology<BMesh>::FaceFace(m);
  vcg::tri::Refine<BMesh, vcg::tri::MidPoint<BMesh>>(m, vcg::tri::MidPoint<BMesh>(&m), 0);
  vcg::tri::Allocator<BMesh>::CompactEveryVector(m);
}

// FNV-1a over every field of every result, in vertex order.
std::uint64_t HashResults(const std::vector<nvv::VertexResult>& res) {
  std::uint64_t h = 1469598103934665603ull;
  auto add = [&h](const void* p, std::size_t n) {
    const unsigned char* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  for (const auto& r : res) {
    add(&r.cls, 1);
    add(&r.flags, 1);
    add(r.lambda, sizeof r.lambda);
    add(r.normal, sizeof r.normal);
    add(&r.k1, 4);
    add(&r.k2, 4);
    add(r.t1, sizeof r.t1);
    add(r.t2, sizeof r.t2);
    add(r.creaseTangent, sizeof r.creaseTangent);
    add(&r.creaseCurvature, 4);
    add(&r.cuspAngle, 4);
  }
  return h;
}

// User + system CPU seconds of the whole process so far.
double CpuSeconds() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}
// One-minute load average of the machine (other jobs show up here).
double Load() {
  double l = 0;
  std::ifstream("/proc/loadavg") >> l;
  return l;
}

struct Run {
  double k = 0;
  int threads = 1;
  double pass1 = 0, pass2 = 0, total = 0, cpu = 0, peakMB = 0, load = 0;
  std::uint64_t hash = 0;
};
int gFitRounds = nvv::Params().fitRounds;  // --fit_rounds N
bool gCubicFit = nvv::Params().cubicFit;    // --cubic_fit 0|1
Run RunNvv(const BMesh& m, double k, int threads) {
  nvv::Params p;
  p.k = k;
  p.fitRounds = gFitRounds;
  p.cubicFit = gCubicFit;
  p.threads = threads;
  std::vector<nvv::VertexResult> res;
  nvv::Summary sum;
  malloc_trim(0);
  const double before = StatusMB("VmRSS");
  ResetPeak();
  const double c0 = CpuSeconds();
  const double t0 = Now();
  const nvv::Status st = vcg::tri::NormalVectorVoting<BMesh>::Compute(m, p, res, sum);
  Run r;
  r.total = Now() - t0;  // wall time of Compute(): graph build + pass 1 + pass 2 + summary
  r.cpu = CpuSeconds() - c0;
  r.load = Load();
  r.peakMB = StatusMB("VmHWM") - before;
  if (!st.ok) std::fprintf(stderr, "nvv failed: %s\n", st.message.c_str());
  r.k = k;
  r.threads = threads;
  r.pass1 = sum.secondsPass1;  // (includes nothing of the graph build: timed inside the core)
  r.pass2 = sum.secondsPass2;
  r.hash = HashResults(res);
  return r;
}

// MeshLab's estimators, called as its filter calls them; topology and normals are prepared
// first (not timed), as MeshLab has them before the filter runs.
double TimeMeshLab(BMesh& m, int method, double radius) {
  vcg::tri::UpdateTopology<BMesh>::VertexFace(m);
  vcg::tri::UpdateTopology<BMesh>::FaceFace(m);
  vcg::tri::UpdateNormal<BMesh>::PerVertexNormalizedPerFace(m);
  const double t0 = Now();
  switch (method) {
    case 0: vcg::tri::UpdateCurvature<BMesh>::PrincipalDirections(m); break;
    case 1: vcg::tri::UpdateCurvature<BMesh>::PrincipalDirectionsPCA(m, float(radius), true); break;
    case 2: vcg::tri::UpdateCurvature<BMesh>::PrincipalDirectionsNormalCycle(m); break;
    case 3: vcg::tri::UpdateCurvatureFitting<BMesh>::computeCurvature(m); break;
  }
  return Now() - t0;
}

// Least-squares slope of log(y) against log(x): the exponent p of y ~ x^p.
double Exponent(const std::vector<double>& x, const std::vector<double>& y) {
  const int n = int(x.size());
  if (n < 2) return NAN;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < n; ++i) {
    const double a = std::log(x[i]), b = std::log(y[i]);
    sx += a; sy += b; sxx += a * a; sxy += a * b;
  }
  const double den = n * sxx - sx * sx;
  return den > 0 ? (n * sxy - sx * sy) / den : NAN;
}

std::string Fmt(double x, const char* f = "%.2f") {
  if (!(x == x) || x < 0) return "–";
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

struct Input {
  std::string name;
  std::function<bool(BMesh&)> make;
  std::vector<std::pair<double, int>> plan;  // (k, threads) runs
  bool pcaMeshLabRadius = false;             // also PCA at MeshLab's default radius bbox/20
};

struct Measured {
  std::string name;
  std::size_t vertices = 0, faces = 0;
  double meshMB = 0;
  std::vector<Run> runs;
  double taubin = -1, cycles = -1, quadric = -1, pcaSame = -1, pcaMeshLab = -1, cgal = -1;
  const Run* Find(double k, int threads) const {
    for (const auto& r : runs)
      if (r.k == k && r.threads == threads) return &r;
    return nullptr;
  }
};

}  // namespace

int main(int argc, char** argv) {
  // Large blocks always from mmap (and back to the system when freed), so the peak of one run
  // is not hidden by heap memory an earlier run left resident.
  mallopt(M_MMAP_THRESHOLD, 256 * 1024);
  std::string shared = NVV_SHARED_MESHES, only;
  bool quick = false, full = false, others = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") quick = true;
    else if (a == "--full") full = true;
    else if (a == "--only" && i + 1 < argc) only = argv[++i];
    else if (a == "--ours-only") others = false;
    else if (a == "--fit_rounds" && i + 1 < argc) gFitRounds = std::atoi(argv[++i]);
    else if (a == "--cubic_fit" && i + 1 < argc) gCubicFit = std::atoi(argv[++i]) != 0;
    else if (a[0] != '-') shared = a;
    else { std::fprintf(stderr, "usage: %s [SHARED_MESHES_DIR] [--quick | --full] [--only NAME] [--ours-only] [--fit_rounds N] [--cubic_fit 0|1]\n", argv[0]); return 2; }
  }
  int allThreads = 1;
#ifdef _OPENMP
  allThreads = omp_get_max_threads();
#endif
  std::printf("%ld cores online, OpenMP threads available: %d; quadric fit rounds: %d; cubic where significant: %s; plan: %s\n\n",
              sysconf(_SC_NPROCESSORS_ONLN),
              allThreads, gFitRounds, gCubicFit ? "on" : "off", quick ? "quick" : full ? "full" : "default");

  const int T = allThreads;
  std::vector<std::pair<double, int>> every;
  for (double k : {1.0, 3.0, 5.0, 8.0}) {
    every.push_back({k, 1});
    if (T > 1) every.push_back({k, T});
  }
  auto plan = [&](std::vector<std::pair<double, int>> p) {
    if (full) return every;
    if (quick) p = {{3, 1}, {3, T}};
    if (T == 1) {  // one core: the all-cores runs are the one-thread runs
      std::vector<std::pair<double, int>> q;
      for (auto& r : p)
        if (r.second == 1) q.push_back(r);
      p = q;
    }
    return p;
  };

  std::vector<Input> inputs;
  // The real scans as they are (their own noise, their own vertex order), k = 3 on one and all cores.
  const std::pair<const char*, const char*> scans[] = {
      {"casting", "casting.off"}, {"rocker arm", "rocker-arm.obj"}, {"bunny", "bunny.off"}};
  for (const auto& scan : scans) {
    const std::string path = shared + "/real/" + scan.second;
    inputs.push_back({scan.first, [path](BMesh& m) {
                        if (!nvv_bench::LoadMesh(path, m)) return false;
                        vcg::tri::Clean<BMesh>::RemoveUnreferencedVertex(m);
                        vcg::tri::Allocator<BMesh>::CompactEveryVector(m);
                        return true;
                      },
                      plan({{3, 1}, {3, T}}), false});
  }
  auto blade = [shared](BMesh& m, int subdivisions) {
    int mask = 0;
    if (vcg::tri::io::ImporterPLY<BMesh>::Open(m, (shared + "/real/turbineblade.ply").c_str(), mask) != 0) return false;
    vcg::tri::Clean<BMesh>::RemoveUnreferencedVertex(m);
    vcg::tri::Allocator<BMesh>::CompactEveryVector(m);
    for (int s = 0; s < subdivisions; ++s) Subdivide(m);
    if (subdivisions > 0) Noise(m, 0.02, 7);
    return true;
  };
  inputs.push_back({"turbine blade", [blade](BMesh& m) { return blade(m, 0); }, plan(every), true});
  if (!quick) {
    inputs.push_back({"blade, 1 subdivision", [blade](BMesh& m) { return blade(m, 1); },
                      plan({{3, 1}, {3, T}}), false});
    inputs.push_back({"blade, 2 subdivisions", [blade](BMesh& m) { return blade(m, 2); },
                      plan({{3, 1}, {3, T}}), false});
  }
  // Major radius 3, minor 1, 1732 x 577 vertices: near-equilateral triangles (~1 M vertices).
  inputs.push_back({"torus 1732x577", [](BMesh& m) {
                      nvv_shapes::Torus(m, 3.0, 1.0, 1732, 577);
                      Noise(m, 0.02, 3);
                      return true;
                    },
                    plan({{1, T}, {3, 1}, {3, T}, {5, T}, {8, T}}), false});

  std::printf("| mesh | vertices | faces | k | threads | pass 1 (s) | pass 2 (s) | total (s) | vertices/s | "
              "CPU (s) | load | peak MB | peak / mesh | result hash |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<Measured> all;
  for (const auto& in : inputs) {
    if (!only.empty() && in.name.find(only) == std::string::npos) continue;
    BMesh m;
    if (!in.make(m)) {
      std::printf("| %s | (not found under %s: skipped) |\n", in.name.c_str(), shared.c_str());
      continue;
    }
    Measured me;
    me.name = in.name;
    me.vertices = m.vert.size();
    me.faces = m.face.size();
    me.meshMB = MeshMB(m);
    for (const auto& kt : in.plan) {
      const Run r = RunNvv(m, kt.first, kt.second);
      std::printf("| %s | %zu | %zu | %g | %d | %.2f | %.2f | %.2f | %.0f | %.2f | %.1f | %.0f | %.2f | %016llx |\n",
                  in.name.c_str(), me.vertices, me.faces, r.k, r.threads, r.pass1, r.pass2, r.total,
                  me.vertices / r.total, r.cpu, r.load, r.peakMB, r.peakMB / me.meshMB,
                  (unsigned long long)r.hash);
      std::fflush(stdout);
      me.runs.push_back(r);
    }
    all.push_back(me);
    if (!others) continue;
    // The others, single-threaded as in MeshLab, on the same mesh. "Same radius" is ours at k = 3.
    const double radius3 = 3 * nvv_shapes::MeanEdge(m);
    vcg::tri::UpdateBounding<BMesh>::Box(m);
    all.back().taubin = TimeMeshLab(m, 0, 0);
    all.back().cycles = TimeMeshLab(m, 2, 0);
    all.back().quadric = TimeMeshLab(m, 3, 0);
    all.back().pcaSame = TimeMeshLab(m, 1, radius3);
    if (in.pcaMeshLabRadius) all.back().pcaMeshLab = TimeMeshLab(m, 1, m.bbox.Diag() / 20.0);
    std::vector<std::array<double, 3>> pts(m.vert.size());
    for (std::size_t i = 0; i < m.vert.size(); ++i) pts[i] = {m.vert[i].P()[0], m.vert[i].P()[1], m.vert[i].P()[2]};
    std::size_t fitted = 0;
    all.back().cgal = nvv_speed::CgalJetSeconds(pts, radius3, fitted);
  }

  std::printf("\nOthers on the same meshes, single-threaded (seconds), and our k = 3 total on %d threads "
              "as a ratio of each (ours / theirs; < 1: ours is faster). PCA and CGAL's jet use our k = 3 "
              "radius (3 l_ave, Euclidean ball); PCA at MeshLab's default radius (bbox/20) only on the "
              "smallest mesh.\n\n", T);
  std::printf("| mesh | ours k=3, 1 thread | ours k=3, %d threads | Taubin | Normal Cycles | Quadric Fitting | "
              "PCA r = 3 l_ave | PCA r = bbox/20 | CGAL jet r = 3 l_ave | ours / Taubin | ours / Quadric | "
              "ours 1 thread / Quadric | ours / PCA (same r) | ours / CGAL jet |\n", T);
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& me : all) {
    const Run* a = me.Find(3, 1);
    const Run* b = me.Find(3, T);
    const double ours = b ? b->total : -1;
    auto ratio = [ours](double theirs) { return ours > 0 && theirs > 0 ? ours / theirs : -1; };
    const double one = a ? a->total : -1;
    const double oneToQuadric = one > 0 && me.quadric > 0 ? one / me.quadric : -1;
    std::printf("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", me.name.c_str(),
                Fmt(a ? a->total : -1).c_str(), Fmt(ours).c_str(), Fmt(me.taubin).c_str(), Fmt(me.cycles).c_str(),
                Fmt(me.quadric).c_str(), Fmt(me.pcaSame).c_str(), Fmt(me.pcaMeshLab).c_str(), Fmt(me.cgal).c_str(),
                Fmt(ratio(me.taubin)).c_str(), Fmt(ratio(me.quadric)).c_str(), Fmt(oneToQuadric).c_str(),
                Fmt(ratio(me.pcaSame), "%.3f").c_str(),
                Fmt(ratio(me.cgal)).c_str());
  }

  std::printf("\nScaling (exponents are least-squares slopes in log-log; threads 1 unless noted):\n\n");
  std::printf("| quantity | value | from |\n|---|---|---|\n");
  {  // time vs n: the blade and its subdivisions, k = 3, one thread
    std::vector<double> n, t;
    std::string from;
    for (const auto& me : all)
      if (me.name.find("blade") != std::string::npos)
        if (const Run* r = me.Find(3, 1)) {
          n.push_back(double(me.vertices));
          t.push_back(r->total);
          from += (from.empty() ? "" : ", ") + std::to_string(me.vertices);
        }
    std::printf("| exponent of total time vs n (k = 3) | %s | blade family, n = %s |\n",
                Fmt(Exponent(n, t)).c_str(), from.c_str());
  }
  for (const auto& me : all)
    for (int threads : {1, T}) {  // time vs k, per mesh and thread count with at least 3 values of k
      std::vector<double> k, t, kHi, tHi;
      for (const auto& r : me.runs)
        if (r.threads == threads) {
          k.push_back(r.k);
          t.push_back(r.total);
          if (r.k >= 3) { kHi.push_back(r.k); tHi.push_back(r.total); }
        }
      if (k.size() >= 3)
        std::printf("| exponent of total time vs k, %d thread(s) | %s (k = 1-8); %s (k = 3-8) | %s |\n", threads,
                    Fmt(Exponent(k, t)).c_str(), Fmt(Exponent(kHi, tHi)).c_str(), me.name.c_str());
      if (threads == T) break;
    }
  for (const auto& me : all) {
    std::string hashes = "same bits";
    for (const auto& r : me.runs)
      if (const Run* o = me.Find(r.k, 1))
        if (o->hash != r.hash) hashes = "DIFFERENT bits";
    const Run* a = me.Find(3, 1);
    const Run* b = me.Find(3, T);
    if (a && b && T > 1)
      std::printf("| parallel speed-up at k = 3, 1 -> %d threads | %.2f (%s) | %s |\n", T, a->total / b->total,
                  hashes.c_str(), me.name.c_str());
  }
  for (const auto& me : all) {
    double worst = 0;
    for (const auto& r : me.runs) worst = std::max(worst, r.peakMB);
    const Run* b = me.Find(3, T);
    std::printf("| peak memory above the mesh / mesh (%.0f MB) | %s at k = 3, %d threads; %s worst | %s |\n",
                me.meshMB, Fmt(b ? b->peakMB / me.meshMB : -1).c_str(), T, Fmt(worst / me.meshMB).c_str(),
                me.name.c_str());
  }
  return 0;
}

#endif  // NVV_SPEED_CGAL_PART
