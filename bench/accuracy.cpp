// nvv_bench_accuracy: this project's estimators against MeshLab's (vcglib) and CGAL's, in
// process, on the same meshes. Usage: nvv_bench_accuracy SECTION OUTDIR, SECTION one of
//   grids     the paper's 32x32 plane / sphere / cylinder at 0..20 % noise (smooth.cpp)
//   variants  irregular and finer grids, a torus (smooth.cpp)
//   f1        crease precision / recall / F1 on roofs, a cube, a capped cylinder (creases.cpp)
//   near      accuracy of surface vertices near those creases (creases.cpp)
//   real      fandisk and the ABC model with ground-truth features (real_meshes.cpp)
//   export    writes the meshes of grids and variants as PLY with the truth and this project's
//             estimates, for bench/python_peers.py (smooth.cpp)
//   cad       parts made by gmsh's OpenCASCADE kernel and the ABC model: crease F1 and the
//             surfaces next to creases (cad_parts.cpp); needs PARTSDIR, bench/cad/make_cad_parts.py's output
//   network   crease edges, lines and patches against the truth on the crease shapes, the CAD
//             parts and the ABC model (crease_networks.cpp); needs PARTSDIR as cad does
//   heldout   the same at 5, 10 and 20 % on two other noise draws of every mesh, on which no
//             threshold was chosen (crease_networks.cpp); needs PARTSDIR
// Prints markdown tables; writes CSV files for the plots into OUTDIR.
#include <cstdio>
#include <string>

#include "sections.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s grids|variants|f1|near|real|export OUTDIR | cad|network|heldout OUTDIR PARTSDIR\n",
                 argv[0]);
    return 2;
  }
  const std::string s = argv[1], out = argv[2];
  if (s == "grids" || s == "variants") return nvv_bench::RunSmooth(out, s);
  if (s == "f1" || s == "near") return nvv_bench::RunCreases(out, s);
  if (s == "real") return nvv_bench::RunReal(out);
  if (s == "export") return nvv_bench::ExportSmooth(out);
  if (s == "cad" && argc >= 4) return nvv_bench::RunCad(out, argv[3]);
  if (s == "network" && argc >= 4) return nvv_bench::RunNetworks(out, argv[3], false);
  if (s == "heldout" && argc >= 4) return nvv_bench::RunNetworks(out, argv[3], true);
  std::fprintf(stderr, "unknown section %s\n", s.c_str());
  return 2;
}
