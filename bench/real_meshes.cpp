// Real meshes with crease ground truth (from ../shared/meshes/real, never copied):
//   fandisk.off (the paper's Fig. 9): no feature file ships with it, so the truth is the clean
//     mesh's edges whose normal-angle is >= 40 deg (its creases are 40..100 deg; the smooth
//     parts' edges are below 30 deg);
//   abc_00000006.obj with abc_00000006.fea (ground-truth feature edges, 0-based vertex pairs).
// Noise 0, 0.1 (the paper's noisy fandisk), 1, 5 and 10 % of l_ave along the clean mesh's
// normals; every method with the same crease angle of 30 deg; crease precision / recall / F1
// per vertex. Also writes fandisk's classes for the pictures.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "crease_shapes.h"
#include "estimators.h"
#include "mesh_files.h"
#include "report.h"
#include "sections.h"

#ifndef NVV_SHARED_MESHES
#define NVV_SHARED_MESHES "../shared/meshes"
#endif

namespace nvv_bench {
namespace {

std::vector<char> TruthFromDihedral(const TMesh& clean, double minAngleDeg) { return DihedralCreaseVertices(clean, minAngleDeg); }

std::vector<unsigned char> NvvClasses(const TMesh& m, double k, double phi, bool thin = true, bool ridgeFit = true,
                                      bool autoK = false) {
  nvv::Params p = nvv_test::WithK(k);
  p.autoK = autoK;
  p.creaseAngleDeg = phi;
  p.thinCreases = thin;
  p.ridgeFit = ridgeFit;
  const nvv_test::NvvRun r = nvv_test::RunNvv(m, p);
  std::vector<unsigned char> c(m.vert.size(), 3);
  for (std::size_t i = 0; i < r.res.size(); ++i) c[i] = static_cast<unsigned char>(r.res[i].cls);
  return c;
}
std::vector<char> IsFeature(const std::vector<unsigned char>& c) {
  std::vector<char> f(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) f[i] = c[i] == 1 || c[i] == 2;
  return f;
}

}  // namespace

int RunReal(const std::string& outDir) {
  const std::string dir = std::string(NVV_SHARED_MESHES) + "/real/";
  const double phi = 30;
  const std::vector<double> noises = {0, 0.001, 0.01, 0.05, 0.10};
  const char* names[] = {"NVV k=1", "NVV k=3", "NVV k=5", "NVV k=3 strength thinning", "NVV k=3 paper band",
                         "MeshLab dihedral", "CGAL sharp edges", "NVV auto k"};
  const int methods = int(sizeof(names) / sizeof(names[0]));
  Csv csv(outDir, "real_f1.csv", "mesh,noise,method,precision,recall,f1");
  std::printf("| mesh | noise | NVV k=1 | NVV k=3 | NVV k=5 | NVV k=3 strength thinning | NVV k=3 paper band | MeshLab dihedral | CGAL sharp edges | NVV auto k |\n"
              "|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string name : {"fandisk.off", "abc_00000006.obj"}) {
    TMesh clean;
    if (!LoadMesh(dir + name, clean)) {
      std::printf("| %s | – | not found under %s | | | | | |\n", name.c_str(), dir.c_str());
      continue;
    }
    const bool fan = name == "fandisk.off";
    const std::vector<char> truth =
        fan ? TruthFromDihedral(clean, 40) : TruthFromFea(dir + "abc_00000006.fea", clean.vert.size());
    const std::vector<char> use(clean.vert.size(), 1);
    const double lave = nvv_shapes::MeanEdge(clean);
    for (double noise : noises) {
      TMesh m;
      vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, clean);
      NoiseAlongNormals(m, noise * lave, 5 + unsigned(10000 * noise));
      Context c(m);
      std::vector<std::vector<unsigned char>> cls = {NvvClasses(m, 1, phi), NvvClasses(m, 3, phi), NvvClasses(m, 5, phi)};
      std::vector<std::vector<char>> found = {IsFeature(cls[0]), IsFeature(cls[1]), IsFeature(cls[2]),
                                              IsFeature(NvvClasses(m, 3, phi, true, false)),
                                              IsFeature(NvvClasses(m, 3, phi, false)),
                                              DihedralCreaseVertices(m, phi), CgalSharpVertices(c.plain, phi),
                                              IsFeature(NvvClasses(m, 3, phi, true, true, true))};
      std::printf("| %s | %g %% |", name.c_str(), noise * 100);
      for (int j = 0; j < methods; ++j) {
        const F1 f = ScoreFeatures(found[j], truth, use);
        std::printf(" %.2f (%.2f / %.2f) |", f.f1, f.precision, f.recall);
        std::fprintf(csv.f(), "%s,%g,%s,%g,%g,%g\n", name.c_str(), noise * 100, names[j], f.precision, f.recall, f.f1);
      }
      std::printf("\n");
      std::fflush(stdout);
      if (fan && (noise == 0 || noise == 0.05)) {
        const std::string tag = noise == 0 ? "clean" : "noise5";
        Csv pts(outDir, "fandisk_" + tag + "_vertices.csv", "x,y,z,truth,nvv_k1,nvv_k3,nvv_k5,dihedral,cgal");
        for (std::size_t i = 0; i < m.vert.size(); ++i)
          std::fprintf(pts.f(), "%g,%g,%g,%d,%d,%d,%d,%d,%d\n", m.vert[i].cP()[0], m.vert[i].cP()[1], m.vert[i].cP()[2],
                       truth[i], cls[0][i], cls[1][i], cls[2][i], found[5][i], found[6][i]);
        Csv fs(outDir, "fandisk_faces.csv", "a,b,c");
        for (const auto& f : c.plain.face) std::fprintf(fs.f(), "%d,%d,%d\n", f[0], f[1], f[2]);
      }
    }
  }
  return 0;
}

}  // namespace nvv_bench
