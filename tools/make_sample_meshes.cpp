// nvv_make_samples: writes the project's sample meshes (sample_meshes/*.ply) from the shape
// generators in sample_meshes/synthetic_shapes.h. Deterministic: the same files every run.
//
// Usage: nvv_make_samples OUTPUT_DIR
#include <cstdio>
#include <random>
#include <string>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <wrap/io_trimesh/export_ply.h>

#include "sample_meshes/synthetic_shapes.h"

namespace {
class SVertex;
class SFace;
struct STypes : vcg::UsedTypes<vcg::Use<SVertex>::AsVertexType, vcg::Use<SFace>::AsFaceType> {};
class SVertex : public vcg::Vertex<STypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::BitFlags> {};
class SFace : public vcg::Face<STypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::BitFlags> {};
class SMesh : public vcg::tri::TriMesh<std::vector<SVertex>, std::vector<SFace>> {};

// Noise that is the same bits with every C++ standard library: std::mt19937's output is fixed by
// the standard, std::normal_distribution's algorithm is not. The sum of twelve uniforms less 6 has
// mean 0 and variance 1 (Irwin-Hall, within 0.01 of a Gaussian's distribution function), and every
// step is exact in double up to the final product with sigma.
class PortableNoise {
 public:
  PortableNoise(unsigned seed, double sigma) : rng_(seed), sigma_(sigma) {}
  double operator()() {
    double sum = 0;
    for (int i = 0; i < 12; ++i) sum += double(rng_()) / 4294967296.0;
    return sigma_ * (sum - 6.0);
  }

 private:
  std::mt19937 rng_;
  double sigma_;
};

// Noise along z (the paper's grids).
void AddNoiseAlongZ(SMesh& m, unsigned seed) {
  PortableNoise noise(seed, 0.05 * nvv_shapes::MeanEdge(m));
  for (auto& v : m.vert) v.P()[2] = float(double(v.P()[2]) + noise());
}

bool Save(SMesh& m, const std::string& dir, const char* name) {
  vcg::tri::UpdateNormal<SMesh>::PerVertexAngleWeighted(m);
  vcg::tri::UpdateNormal<SMesh>::NormalizePerVertex(m);
  const std::string path = dir + "/" + name;
  const int err = vcg::tri::io::ExporterPLY<SMesh>::Save(m, path.c_str(), vcg::tri::io::Mask::IOM_VERTNORMAL, true);
  std::printf("%-28s %6d vertices %6d faces%s\n", name, m.vn, m.fn, err ? "  WRITE FAILED" : "");
  return err == 0;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: nvv_make_samples OUTPUT_DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  bool ok = true;
  SMesh m;
  // The paper's 32x32 grids (1 mm spacing, R = 31 mm) with noise on z, sigma = 5 % of l_ave.
  nvv_shapes::PaperPlane(m);
  AddNoiseAlongZ(m, 1);
  ok &= Save(m, dir, "paper_plane_noise5.ply");
  nvv_shapes::PaperSphere(m, 31);
  AddNoiseAlongZ(m, 2);
  ok &= Save(m, dir, "paper_sphere_noise5.ply");
  nvv_shapes::PaperCylinder(m, 31);
  AddNoiseAlongZ(m, 3);
  ok &= Save(m, dir, "paper_cylinder_noise5.ply");
  // The paper's Fig. 10: a marching-cubes torus.
  nvv_shapes::MarchingCubesTorus(m, 6, 2.5, 64);
  ok &= Save(m, dir, "torus_marching_cubes.ply");
  // A CAD-like part with sharp (90 deg) and shallow (18-37 deg) creases, a cylindrical roof and
  // corners, clean and with noise along the normals (sigma = 5 % of l_ave).
  nvv_shapes::CadPart(m);
  ok &= Save(m, dir, "cad_part.ply");
  vcg::tri::UpdateNormal<SMesh>::PerVertexAngleWeighted(m);
  vcg::tri::UpdateNormal<SMesh>::NormalizePerVertex(m);
  {
    PortableNoise noise(4, 0.05 * nvv_shapes::MeanEdge(m));
    for (auto& v : m.vert) v.P() += v.N() * float(noise());
  }
  ok &= Save(m, dir, "cad_part_noise5.ply");
  return ok ? 0 : 1;
}
