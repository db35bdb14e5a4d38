// Mesh and truth files of the real-mesh and CAD sections: OFF and OBJ (vertices as double,
// polygons fanned, every index checked) and ABC-style feature files.
#ifndef NVV_BENCH_MESH_FILES_H
#define NVV_BENCH_MESH_FILES_H

#include <algorithm>
#include <array>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_mesh.h"

namespace nvv_bench {

// Into any vcglib triangle mesh (the speed benchmark's is float).
template <class MeshT>
bool LoadMesh(const std::string& path, MeshT& m) {
  std::ifstream in(path);
  if (!in) return false;
  std::vector<vcg::Point3d> v;
  std::vector<std::array<int, 3>> f;
  const bool off = path.size() > 4 && path.substr(path.size() - 4) == ".off";
  if (off) {
    std::string head;
    int nv = 0, nf = 0, ne = 0;
    in >> head >> nv >> nf >> ne;
    if (nv < 0 || nf < 0) return false;
    v.resize(nv);
    for (auto& p : v) in >> p[0] >> p[1] >> p[2];
    for (int i = 0; i < nf; ++i) {
      int n = 0;
      in >> n;
      std::vector<int> idx(std::max(n, 0));
      for (int& x : idx) in >> x;
      for (std::size_t j = 2; j < idx.size(); ++j) f.push_back({idx[0], idx[j - 1], idx[j]});
    }
  } else {
    std::string line;
    while (std::getline(in, line)) {
      std::istringstream ls(line);
      std::string tag;
      ls >> tag;
      if (tag == "v") {
        vcg::Point3d p;
        ls >> p[0] >> p[1] >> p[2];
        v.push_back(p);
      } else if (tag == "f") {
        std::vector<int> idx;
        std::string s;
        while (ls >> s) idx.push_back(std::stoi(s.substr(0, s.find('/'))) - 1);
        for (std::size_t j = 2; j < idx.size(); ++j) f.push_back({idx[0], idx[j - 1], idx[j]});
      }
    }
  }
  m.Clear();
  auto vi = vcg::tri::Allocator<MeshT>::AddVertices(m, v.size());
  for (std::size_t i = 0; i < v.size(); ++i) (vi + i)->P() = MeshT::CoordType::Construct(v[i]);
  for (const auto& t : f) {
    if (std::min({t[0], t[1], t[2]}) < 0 || std::size_t(std::max({t[0], t[1], t[2]})) >= v.size()) return false;
    vcg::tri::Allocator<MeshT>::AddFace(m, &m.vert[t[0]], &m.vert[t[1]], &m.vert[t[2]]);
  }
  return !v.empty() && !f.empty();
}

// The crease vertices of an ABC-style feature file (.fea): an edge count, then vertex pairs.
inline std::vector<char> TruthFromFea(const std::string& path, std::size_t n) {
  std::vector<char> t(n, 0);
  std::ifstream in(path);
  int count = 0;
  in >> count;
  for (int i = 0; i < count; ++i) {
    int a, b;
    in >> a >> b;
    if (a >= 0 && b >= 0 && std::size_t(a) < n && std::size_t(b) < n) t[a] = t[b] = 1;
  }
  return t;
}

}  // namespace nvv_bench

#endif
