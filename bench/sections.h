// The sections of the accuracy benchmark; each prints markdown and writes CSV into outDir.
#ifndef NVV_BENCH_SECTIONS_H
#define NVV_BENCH_SECTIONS_H

#include <string>

namespace nvv_bench {
int RunSmooth(const std::string& outDir, const std::string& which);  // "grids" or "variants"
int ExportSmooth(const std::string& outDir);  // their meshes as PLY, for bench/python_peers.py
int RunCreases(const std::string& outDir, const std::string& which); // "f1" or "near"
int RunReal(const std::string& outDir);
int RunCad(const std::string& outDir, const std::string& partsDir);  // bench/cad/make_cad_parts.py's output
// crease edges, lines and patches against the truth, beside MeshLab's and CGAL's
int RunNetworks(const std::string& outDir, const std::string& partsDir, bool heldOut);  // heldOut: draws 1, 2
}  // namespace nvv_bench

#endif
