// Loading a mesh for the command-line tool with vcglib's importers (PLY, OBJ, OFF, STL), then
// preparing it the way MeshLab does when it opens a file, so the tool and the plugin see the
// same mesh: STL triangle soups are welded, and when the file has no vertex normals they are
// computed angle-weighted and normalized. Vertices keep the file's order (except STL welding).
#ifndef NVV_CLI_LOAD_MESH_H
#define NVV_CLI_LOAD_MESH_H

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <wrap/io_trimesh/import_obj.h>
#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_ply.h>
#include <wrap/io_trimesh/import_stl.h>

namespace nvv_cli {

struct LoadInfo {
  std::string format;           // "PLY", "OBJ", "OFF" or "STL"
  bool fileNormals = false;     // the file had per-vertex normals (kept as they are)
  int weldedVertices = 0;       // STL: vertices merged or dropped by welding
  std::string warning;          // a non-fatal importer message, or empty
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

// vcglib's STL importer takes any file it cannot parse for an empty ASCII STL; accept only
// files that are either a binary STL of the right size or start with "solid".
inline bool LooksLikeStl(const std::string& path) {
  FILE* fp = std::fopen(path.c_str(), "rb");
  if (!fp) return false;
  std::fseek(fp, 0, SEEK_END);
  const long size = std::ftell(fp);
  std::fseek(fp, 0, SEEK_SET);
  char head[84] = {0};
  const std::size_t got = std::fread(head, 1, sizeof head, fp);
  std::fclose(fp);
  if (got == sizeof head) {
    std::uint32_t n;
    std::memcpy(&n, head + 80, 4);
    if (size == long(84 + 50 * std::uint64_t(n))) return true;
  }
  std::size_t i = 0;
  while (i < got && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
  return got - i >= 5 && std::strncmp(head + i, "solid", 5) == 0;
}

// Loads `path` into m. On failure returns false with a short reason in `error`.
template <class MeshType>
bool LoadMesh(const std::string& path, MeshType& m, LoadInfo& info, std::string& error) {
  namespace io = vcg::tri::io;
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
  FILE* probe = std::fopen(path.c_str(), "rb");
  if (!probe) {
    error = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  std::fclose(probe);

  const std::string ext = Extension(path);
  int mask = 0;
  int err = 0;
  bool critical = false;
  const char* msg = "";
  if (ext == ".ply") {
    info.format = "PLY";
    err = io::ImporterPLY<MeshType>::Open(m, path.c_str(), mask);
    critical = io::ImporterPLY<MeshType>::ErrorCritical(err);
    msg = io::ImporterPLY<MeshType>::ErrorMsg(err);
  } else if (ext == ".off") {
    info.format = "OFF";
    err = io::ImporterOFF<MeshType>::Open(m, path.c_str(), mask);
    critical = err != 0;
    msg = io::ImporterOFF<MeshType>::ErrorMsg(err);
  } else if (ext == ".obj") {
    info.format = "OBJ";
    err = io::ImporterOBJ<MeshType>::Open(m, path.c_str(), mask);
    critical = io::ImporterOBJ<MeshType>::ErrorCritical(err);
    msg = io::ImporterOBJ<MeshType>::ErrorMsg(err);
  } else if (ext == ".stl") {
    info.format = "STL";
    if (!LooksLikeStl(path)) {
      error = "not a valid STL file (neither a binary STL of the right size nor ASCII 'solid')";
      return false;
    }
    err = io::ImporterSTL<MeshType>::Open(m, path.c_str(), mask);
    critical = err != 0;
    msg = io::ImporterSTL<MeshType>::ErrorMsg(err);
  } else {
    error = "unsupported file format '" + (ext.empty() ? std::string("(no extension)") : ext) +
            "' (nvv reads .ply, .obj, .off and .stl)";
    return false;
  }
  if (critical) {
    error = std::string("cannot read ") + info.format + " file: " + msg;
    m.Clear();
    return false;
  }
  // vcglib's OFF importer does not check face indices: refuse faces that point outside the
  // vertex array rather than hand the filter dangling pointers.
  if (!m.vert.empty() || !m.face.empty()) {
    const std::uintptr_t first = reinterpret_cast<std::uintptr_t>(m.vert.data());
    const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(m.vert.data() + m.vert.size());
    for (std::size_t f = 0; f < m.face.size(); ++f)
      for (int j = 0; j < 3; ++j) {
        const std::uintptr_t p = reinterpret_cast<std::uintptr_t>(m.face[f].cV(j));
        if (!m.face[f].IsD() && (p < first || p >= end)) {
          error = "corrupt " + info.format + " file: face " + std::to_string(f) + " refers to a vertex that does not exist";
          m.Clear();
          return false;
        }
      }
  }
  if (err != 0 && !(info.format == "PLY" && err == vcg::tri::io::PlyInfo::E_NO_FACE)) info.warning = msg;

  if (info.format == "STL") {
    const int dup = vcg::tri::Clean<MeshType>::RemoveDuplicateVertex(m);
    const int unref = vcg::tri::Clean<MeshType>::RemoveUnreferencedVertex(m);
    vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
    info.weldedVertices = dup + unref;
  }
  info.fileNormals = (mask & io::Mask::IOM_VERTNORMAL) != 0;
  if (!info.fileNormals && vcg::tri::HasPerVertexNormal(m)) {
    vcg::tri::UpdateNormal<MeshType>::PerVertexAngleWeighted(m);
    vcg::tri::UpdateNormal<MeshType>::NormalizePerVertex(m);
  }
  return true;
}

}  // namespace nvv_cli

#endif
