// Runs Debian's real meshlabserver (2020.09) from the private prefix the test fixture made,
// headless under xvfb-run, and reads the meshes it writes.
#ifndef NVV_TESTS_MESHLAB_RUNNER_H
#define NVV_TESTS_MESHLAB_RUNNER_H

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/import_ply.h>

namespace nvv_ml {

// A float mesh like MeshLab's CMeshO, for reading what meshlabserver saved.
class MVertex;
class MFace;
struct MTypes : vcg::UsedTypes<vcg::Use<MVertex>::AsVertexType, vcg::Use<MFace>::AsFaceType> {};
class MVertex : public vcg::Vertex<MTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::Color4b,
                                   vcg::vertex::Qualityf, vcg::vertex::BitFlags> {};
class MFace : public vcg::Face<MTypes, vcg::face::VertexRef, vcg::face::Color4b, vcg::face::BitFlags> {};
class MMesh : public vcg::tri::TriMesh<std::vector<MVertex>, std::vector<MFace>> {};

// An edge mesh, for reading a polyline layer or a crease-lines file.
class EVertex;
class EEdge;
struct ETypes : vcg::UsedTypes<vcg::Use<EVertex>::AsVertexType, vcg::Use<EEdge>::AsEdgeType> {};
class EVertex : public vcg::Vertex<ETypes, vcg::vertex::Coord3f, vcg::vertex::Color4b, vcg::vertex::BitFlags> {};
class EEdge : public vcg::Edge<ETypes, vcg::edge::VertexRef, vcg::edge::BitFlags> {};
class EMesh : public vcg::tri::TriMesh<std::vector<EVertex>, std::vector<EEdge>> {};

inline std::string Prefix() { return NVV_MESHLAB_PREFIX; }
inline std::string TempDir() {
  static std::string dir;
  if (dir.empty()) {
    char tmpl[] = "/tmp/nvv_mlserver_XXXXXX";
    dir = mkdtemp(tmpl);
  }
  return dir;
}

struct ServerRun {
  int exitCode = -1;
  std::string output;  // stdout and stderr of meshlabserver
};

// meshlabserver -i in -o out -m mask -s script.mlx (script given as text).
inline ServerRun RunServer(const std::string& in, const std::string& out, const std::string& mlxText,
                           const std::string& mask = "vc vq vn") {
  static int counter = 0;
  const std::string base = TempDir() + "/run" + std::to_string(++counter);
  std::ofstream(base + ".mlx") << mlxText;
  const std::string cmd = "xvfb-run -a " + Prefix() + "/bin/meshlabserver -i '" + in + "' -o '" + out + "' -m " + mask +
                          " -s '" + base + ".mlx' > '" + base + ".log' 2>&1";
  ServerRun r;
  const int status = std::system(cmd.c_str());
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::ifstream log(base + ".log");
  std::stringstream ss;
  ss << log.rdbuf();
  r.output = ss.str();
  return r;
}

template <class MeshType>
bool ReadPly(const std::string& path, MeshType& m) {
  m.Clear();
  int mask = 0;
  vcg::tri::io::ImporterPLY<MeshType>::LoadMask(path.c_str(), mask);
  return vcg::tri::io::ImporterPLY<MeshType>::Open(m, path.c_str(), mask) == 0;
}

}  // namespace nvv_ml

#endif
