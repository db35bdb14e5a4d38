// Shared by the MeshLab 2025.07 scripted-use tests: paths given by the build, a Session that
// has loaded the plugins, a float mesh type like MeshLab 2020.09's CMeshO for reference runs of
// the core, and snapshots to prove that a refused run left the mesh as it was.
#ifndef NVV_TESTS_MESHLAB2025_TEST_SUPPORT_2025_H
#define NVV_TESTS_MESHLAB2025_TEST_SUPPORT_2025_H

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "pymeshlab_session.h"

namespace nvv2025 {

inline std::string Samples() { return NVV_SAMPLE_MESHES; }
inline std::string Cad() { return Samples() + "/cad_part_noise5.ply"; }
inline std::string CleanCad() { return Samples() + "/cad_part.ply"; }
inline std::string Scalar() { return NVV_MESHLAB_SCALAR_NAME; }
inline std::string TempDir() {
  static std::string dir;
  if (dir.empty()) {
    char tmpl[] = "/tmp/nvv_ml2025_XXXXXX";
    dir = mkdtemp(tmpl);
  }
  return dir;
}
inline std::string Env(const char* name) {
  const char* v = std::getenv(name);
  return v ? v : "";
}

// Saves the session's current mesh as NAME.ply into $NVV_ARTEFACTS (when set), for the pictures.
inline void KeepArtefact(Session& s, const std::string& name) {
  const std::string dir = Env("NVV_ARTEFACTS");
  if (!dir.empty()) s.SaveCurrentMesh(dir + "/" + name + ".ply");
}

// A session with MeshLab's five plugins and ours loaded (once per process).
inline Session& NewSession(Session& s) {
  LoadPluginsOnce(NVV_MESHLAB_PLUGIN_DIR, NVV_PLUGIN_FILE, TempDir());
  return s;
}

// A float mesh with what MeshLab 2020.09's CMeshO offers the filter.
class FVertex;
class FFace;
struct FTypes : vcg::UsedTypes<vcg::Use<FVertex>::AsVertexType, vcg::Use<FFace>::AsFaceType> {};
class FVertex : public vcg::Vertex<FTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::Color4b,
                                   vcg::vertex::Qualityf, vcg::vertex::CurvatureDirf, vcg::vertex::BitFlags> {};
class FFace : public vcg::Face<FTypes, vcg::face::VertexRef, vcg::face::BitFlags> {};
class FMesh : public vcg::tri::TriMesh<std::vector<FVertex>, std::vector<FFace>> {};

// The same vertices (rounded to float, as the sample files are) and faces, in the same order.
inline void CopyToFloat(const CMeshO& in, FMesh& out) {
  out.Clear();
  vcg::tri::Allocator<FMesh>::AddVertices(out, in.vert.size());
  for (std::size_t i = 0; i < in.vert.size(); ++i) {
    out.vert[i].P().Import(in.vert[i].cP());
    out.vert[i].N().Import(in.vert[i].cN());
  }
  vcg::tri::Allocator<FMesh>::AddFaces(out, in.face.size());
  for (std::size_t f = 0; f < in.face.size(); ++f)
    for (int j = 0; j < 3; ++j) out.face[f].V(j) = &out.vert[vcg::tri::Index(in, in.face[f].cV(j))];
}

// Everything a run could change, to compare before and after.
struct MeshSnapshot {
  int dataMask = 0;
  std::vector<Point3m> positions, normals;
  std::vector<Scalarm> quality;
  std::vector<vcg::Color4b> colours;
  std::vector<bool> selected;
  std::size_t attributes = 0;
  explicit MeshSnapshot(const MeshModel& m) : dataMask(m.dataMask()) {
    for (const auto& v : m.cm.vert) {
      positions.push_back(v.cP());
      normals.push_back(v.cN());
      if (m.hasDataMask(MeshModel::MM_VERTQUALITY)) quality.push_back(v.cQ());
      if (m.hasDataMask(MeshModel::MM_VERTCOLOR)) colours.push_back(v.cC());
      selected.push_back(v.IsS());
    }
    attributes = m.cm.vert_attr.size();
  }
  bool operator==(const MeshSnapshot& o) const {
    return dataMask == o.dataMask && positions == o.positions && normals == o.normals && quality == o.quality &&
           colours == o.colours && selected == o.selected && attributes == o.attributes;
  }
};

}  // namespace nvv2025

#endif
