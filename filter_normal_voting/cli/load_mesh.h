// Loading a mesh for the command-line tool with the project's own readers (io/mesh_reader.h:
// PLY, OBJ, OFF, STL, written for untrusted files), then preparing it the way MeshLab does when
// it opens a file, so the tool and the plugin see the same mesh: STL triangle soups are welded,
// and when the file has no vertex normals they are computed angle-weighted and normalized.
// Vertices keep the file's order (except STL welding).
#ifndef NVV_CLI_LOAD_MESH_H
#define NVV_CLI_LOAD_MESH_H

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/normal.h>

#include "io/mesh_reader.h"

namespace nvv_cli {

struct LoadInfo {
  std::string format;           // "PLY", "OBJ", "OFF" or "STL"
  bool fileNormals = false;     // the file had per-vertex normals (kept as they are)
  int weldedVertices = 0;       // STL: vertices merged or dropped by welding
  std::string warning;          // a non-fatal reader message, or empty
};

// Lower-case extension with its dot ("" when there is none).
inline std::string Extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::string();
  std::string e = path.substr(dot);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

// Angle-weighted, normalized vertex normals, as MeshLab computes them when it opens a file
// without normals. Faces touching a non-finite vertex are left out (their NaN normal would spread
// to every neighbour), and where the coordinates are so large or so small that float cross
// products overflow or underflow, the normals are computed on the mesh scaled to unit size (the
// positions are restored bit for bit afterwards).
template <class MeshType>
void ComputeLoadNormals(MeshType& m) {
  typedef typename MeshType::CoordType Coord;
  double extent = 0;
  for (const auto& v : m.vert)
    for (int j = 0; j < 3; ++j)
      if (std::isfinite(v.cP()[j])) extent = std::max(extent, std::abs(double(v.cP()[j])));
  std::vector<Coord> saved;
  const bool rescale = extent > 1e15 || (extent > 0 && extent < 1e-15);
  if (rescale) {
    saved.reserve(m.vert.size());
    for (auto& v : m.vert) {
      saved.push_back(v.cP());
      v.P() = Coord(v.cP()[0] / extent, v.cP()[1] / extent, v.cP()[2] / extent);
    }
  }
  std::vector<std::size_t> hidden;
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    auto& face = m.face[f];
    if (face.IsD()) continue;
    for (int j = 0; j < 3; ++j) {
      const Coord& p = face.cV(j)->cP();
      if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) {
        face.SetD();
        hidden.push_back(f);
        break;
      }
    }
  }
  vcg::tri::UpdateNormal<MeshType>::PerVertexAngleWeighted(m);
  vcg::tri::UpdateNormal<MeshType>::NormalizePerVertex(m);
  for (std::size_t f : hidden) m.face[f].ClearD();
  for (std::size_t i = 0; i < saved.size(); ++i) m.vert[i].P() = saved[i];
  for (auto& v : m.vert)
    if (!(std::isfinite(v.cN()[0]) && std::isfinite(v.cN()[1]) && std::isfinite(v.cN()[2]))) v.N() = Coord(0, 0, 0);
}

// Loads `path` into m. On failure returns false with a short reason in `error`.
template <class MeshType>
bool LoadMesh(const std::string& path, MeshType& m, LoadInfo& info, std::string& error) {
  m.Clear();
  info = LoadInfo();
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) {
    error = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  if (S_ISDIR(st.st_mode)) {
    error = "is a directory, not a mesh file";
    return false;
  }
  nvv::io::MeshFormat format;
  if (!nvv::io::FormatFromPath(path, format)) {
    const std::string ext = Extension(path);
    error = "unsupported file format '" + (ext.empty() ? std::string("(no extension)") : ext) +
            "' (nvv reads .ply, .obj, .off and .stl)";
    return false;
  }
  info.format = nvv::io::FormatName(format);
  nvv::io::MeshData d;
  if (!nvv::io::ReadMeshFile(path, d, error)) return false;

  typedef typename MeshType::ScalarType S;
  const std::size_t nv = d.positions.size();
  if (nv > 0) vcg::tri::Allocator<MeshType>::AddVertices(m, nv);
  for (std::size_t i = 0; i < nv; ++i) {
    auto& v = m.vert[i];
    v.P() = vcg::Point3<S>(S(d.positions[i][0]), S(d.positions[i][1]), S(d.positions[i][2]));
    if (vcg::tri::HasPerVertexNormal(m) && !d.normals.empty())
      v.N() = vcg::Point3<S>(S(d.normals[i][0]), S(d.normals[i][1]), S(d.normals[i][2]));
    // Colour and quality as MeshLab's importers leave them: the file's, else white and, for PLY,
    // quality 1 (the other importers keep the component's default).
    if (vcg::tri::HasPerVertexColor(m))
      v.C() = d.colors.empty() ? vcg::Color4b(vcg::Color4b::White)
                               : vcg::Color4b(d.colors[i][0], d.colors[i][1], d.colors[i][2], d.colors[i][3]);
    if (vcg::tri::HasPerVertexQuality(m)) {
      if (!d.quality.empty()) v.Q() = d.quality[i];
      else if (format == nvv::io::MeshFormat::Ply) v.Q() = typename MeshType::VertexType::QualityType(1);
    }
  }
  if (!d.triangles.empty()) {
    auto fi = vcg::tri::Allocator<MeshType>::AddFaces(m, d.triangles.size());
    for (const auto& t : d.triangles) {
      for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[std::size_t(t[k])];
      ++fi;
    }
  }
  if (d.skippedElements > 0 && format == nvv::io::MeshFormat::Obj)
    info.warning = std::to_string(d.skippedElements) + " line or point elements skipped";

  if (format == nvv::io::MeshFormat::Stl) {
    const int dup = vcg::tri::Clean<MeshType>::RemoveDuplicateVertex(m);
    const int unref = vcg::tri::Clean<MeshType>::RemoveUnreferencedVertex(m);
    vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
    info.weldedVertices = dup + unref;
  }
  info.fileNormals = !d.normals.empty();
  if (!info.fileNormals && vcg::tri::HasPerVertexNormal(m)) ComputeLoadNormals(m);
  return true;
}

}  // namespace nvv_cli

#endif
