// The full-result PLY of Normal Vector Voting: one file that holds the mesh with everything the
// filter computed per vertex. Written by the command-line tool; readable by MeshLab and any PLY
// reader (unknown properties are ignored by them), and read back by ReadResultPly below.
//
// FORMAT
//   PLY 1.0, "format binary_little_endian 1.0" (default) or "format ascii 1.0".
//   Header comments: "comment Normal Vector Voting results (nvv_format 1)", then any comments
//   the writer was given (the CLI records its input file and every parameter value).
//   Two elements, in this order, and a third when the run found the crease network (the
//   option crease_edges):
//
//   element vertex <V>   one per non-deleted vertex, in the mesh's order
//     property  type   meaning (units)
//     x y z     float  position, in the mesh's units
//     nx ny nz  float  normal as it is on the mesh after the results were applied: the voted
//                      (or fitted) unit normal of surface vertices, the sheets' bisector on
//                      creases, the mesh's own normal elsewhere. Meshes without normals: the
//                      result's normal, or 0 0 0 where it has none.
//     red green blue alpha
//               uchar  vertex colour, 0-255, as applied (default: class colours, surface grey
//                      190, crease red 220 30 30, corner blue 30 80 235, unclassified magenta).
//                      Meshes without colour: the class colour.
//     quality   float  vertex quality as applied (default: mean curvature (k1+k2)/2, 1/units).
//                      Meshes without quality: the mean curvature, 0 where there is none.
//     nvv_class uchar  0 surface, 1 crease, 2 corner, 3 unclassified (deleted, unreferenced,
//                      non-finite, or without a usable triangle)
//     nvv_lambda1 nvv_lambda2 nvv_lambda3
//               float  eigenvalues of the normal-vote matrix in the order the classification
//                      used them; they sum to 1 (0 0 0 for unclassified vertices). Surface
//                      saliency = lambda1 - lambda2, crease saliency = lambda2 - lambda3,
//                      corner saliency = lambda3.
//     k1 k2     float  principal curvatures, k1 >= k2, in 1/units; a sphere of radius R with
//                      outward normals has k1 = k2 = +1/R. 0 where bit 2 of nvv_flags is clear.
//     pd1x pd1y pd1z
//               float  unit direction of k1 (maximum curvature), 0 0 0 when k1 is not valid
//     pd2x pd2y pd2z
//               float  unit direction of k2 (minimum curvature), 0 0 0 when k2 is not valid
//     nvv_crease_tangent_x nvv_crease_tangent_y nvv_crease_tangent_z
//               float  unit tangent of the crease line at crease vertices, else 0 0 0
//     nvv_crease_curvature
//               float  curvature of the crease line along its tangent, 1/units (creases only)
//     nvv_cusp_angle
//               float  angle between the normals of the two sheets meeting at a crease,
//                      degrees (creases only, else 0)
//     nvv_flags uchar  bits of nvv::ResultFlag: 1 normal valid, 2 curvature (k1 k2 pd1 pd2)
//                      valid, 4 crease values valid, 8 neighbourhood truncated at the cap
//     nvv_selected
//               uchar  1 if the vertex is selected on the mesh (see the "selection" option), else 0
//
//   element face <F>     one per non-deleted face whose vertices are all present
//     property list uchar int vertex_indices
//                      three 0-based indices into the vertex element (deleted vertices are
//                      skipped and the indices renumbered accordingly)
//     patch     int    with the crease network only: the smooth patch of the face, bounded by
//                      crease lines (0-based), or -1 for a face the filter skipped (repeated
//                      vertex, non-finite vertex, repeated face)
//
//   element edge <E>     with the crease network only: one per crease edge, sorted by vertices
//     vertex1 vertex2
//               int    0-based indices into the vertex element, vertex1 < vertex2
//     cusp_angle
//               float  angle between the two sheets' normals along the edge, radians
//     line      int    the crease line the edge belongs to (0-based)
//
// MeshLab (and vcglib's importer) reads x y z nx ny nz red green blue alpha quality and the
// faces (and, on meshes with edges, the edges' vertex pairs); the other properties are extra
// data that it ignores.
//
// Only vcglib and the standard library are used here (no Qt).
#ifndef NVV_IO_RESULT_PLY_H
#define NVV_IO_RESULT_PLY_H

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>

#include "filter/apply_results.h"
#include "filter/crease_outputs.h"
#include "io/close_output.h"
#include "core/vertex_result.h"
#include "io/result_ply_format.h"
#include "io/result_ply_reader.h"  // ReadResultPly

namespace nvv {

namespace ply_detail {

inline const char* TypeName(float) { return "float"; }
inline const char* TypeName(std::uint8_t) { return "uchar"; }

inline void AppendLE(std::string& out, const void* p, std::size_t n) {
  const unsigned char* b = static_cast<const unsigned char*>(p);
  const std::uint16_t probe = 1;
  const bool little = *reinterpret_cast<const unsigned char*>(&probe) == 1;
  for (std::size_t i = 0; i < n; ++i) out.push_back(char(b[little ? i : n - 1 - i]));
}
inline void AppendBinary(std::string& out, float x) { AppendLE(out, &x, 4); }
inline void AppendBinary(std::string& out, std::uint8_t x) { out.push_back(char(x)); }
inline void AppendBinary(std::string& out, std::int32_t x) { AppendLE(out, &x, 4); }
inline void AppendAscii(std::string& out, std::int32_t x) { out += std::to_string(x); }

// 9 significant digits give back the same float.
inline void AppendAscii(std::string& out, float x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", double(x));
  out += buf;
}
inline void AppendAscii(std::string& out, std::uint8_t x) { out += std::to_string(unsigned(x)); }

inline std::string OneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

}  // namespace ply_detail

// The file's vertex record for mesh vertex i and its result r.
template <class MeshType>
ResultPlyVertex MakeResultPlyVertex(const MeshType& m, std::size_t i, const VertexResult& r) {
  const auto& v = m.vert[i];
  ResultPlyVertex o;
  for (int j = 0; j < 3; ++j) o.position[j] = float(v.cP()[j]);
  if (vcg::tri::HasPerVertexNormal(m)) {
    for (int j = 0; j < 3; ++j) o.normal[j] = float(v.cN()[j]);
  } else if (r.Has(kNormalValid)) {
    for (int j = 0; j < 3; ++j) o.normal[j] = r.normal[j];
  }
  const vcg::Color4b c = vcg::tri::HasPerVertexColor(m) ? v.cC() : ClassColor(r.cls);
  for (int j = 0; j < 4; ++j) o.color[j] = c[j];
  bool valid;
  o.quality = vcg::tri::HasPerVertexQuality(m) ? float(v.cQ())
                                                : float(QualityValue(r, QualityMode::MeanCurvature, valid));
  o.cls = std::uint8_t(r.cls);
  for (int j = 0; j < 3; ++j) o.lambda[j] = r.lambda[j];
  if (r.Has(kCurvatureValid)) {
    o.k1 = r.k1;
    o.k2 = r.k2;
    for (int j = 0; j < 3; ++j) {
      o.pd1[j] = r.t1[j];
      o.pd2[j] = r.t2[j];
    }
  }
  if (r.Has(kCreaseValid)) {
    for (int j = 0; j < 3; ++j) o.creaseTangent[j] = r.creaseTangent[j];
    o.creaseCurvature = r.creaseCurvature;
    o.cuspAngleDeg = float(RadToDeg(r.cuspAngle));
  }
  o.flags = r.flags;
  o.selected = v.IsS() ? 1 : 0;
  return o;
}

namespace ply_detail {

// The live vertices' new indices (-1 for deleted ones; returns their count) and the live faces
// whose three vertices are live, renumbered, with their slots in m.face.
template <class MeshType>
int LiveElements(const MeshType& m, std::vector<int>& newIndex, std::vector<std::array<int, 3>>& faces,
                 std::vector<std::size_t>& faceSlot) {
  newIndex.assign(m.vert.size(), -1);
  int nv = 0;
  for (std::size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD()) newIndex[i] = nv++;
  faces.clear();
  faces.reserve(m.face.size());
  faceSlot.clear();
  for (std::size_t s = 0; s < m.face.size(); ++s) {
    const auto& f = m.face[s];
    if (f.IsD()) continue;
    std::array<int, 3> t;
    bool ok = true;
    for (int j = 0; j < 3 && ok; ++j) {
      const auto* vp = f.cV(j);
      const std::ptrdiff_t k = vp - &m.vert[0];
      ok = vp != nullptr && k >= 0 && std::size_t(k) < m.vert.size() && newIndex[k] >= 0;
      if (ok) t[j] = newIndex[k];
    }
    if (ok) faces.push_back(t), faceSlot.push_back(s);
  }
  return nv;
}

// edges: the number of crease edges, or -1 for a file without the crease network.
inline std::string Header(bool binary, const std::vector<std::string>& comments, int vertices, std::size_t faces,
                          long edges) {
  std::string header = "ply\n";
  header += binary ? "format binary_little_endian 1.0\n" : "format ascii 1.0\n";
  header += "comment Normal Vector Voting results (nvv_format 1)\n";
  for (const auto& c : comments) header += "comment " + OneLine(c) + "\n";
  header += "element vertex " + std::to_string(vertices) + "\n";
  ResultPlyVertex probe;
  ForEachResultPlyField(probe, [&](const char* name, auto& field) {
    header += std::string("property ") + TypeName(field) + " " + name + "\n";
  });
  header += "element face " + std::to_string(faces) + "\n";
  header += "property list uchar int vertex_indices\n";
  if (edges >= 0) {
    header += "property int patch\nelement edge " + std::to_string(edges) + "\n";
    header += "property int vertex1\nproperty int vertex2\nproperty float cusp_angle\nproperty int line\n";
  }
  return header + "end_header\n";
}

}  // namespace ply_detail

// Writes mesh m with results res (one per slot of m.vert) to `path`, with extra header
// comments, and the crease network's patches and edges when `crease` is given. On failure
// returns false, sets `error` to one sentence and removes a partial regular file.
template <class MeshType>
bool WriteResultPly(const std::string& path, const MeshType& m, const std::vector<VertexResult>& res, bool binary,
                    const std::vector<std::string>& comments, std::string& error,
                    const CreaseOutputs* crease = nullptr) {
  using namespace ply_detail;
  if (res.size() != m.vert.size()) {
    error = "the results do not match the mesh (" + std::to_string(res.size()) + " results for " +
            std::to_string(m.vert.size()) + " vertex slots)";
    return false;
  }
  std::vector<int> newIndex;
  std::vector<std::array<int, 3>> faces;
  std::vector<std::size_t> faceSlot;
  const int nv = LiveElements(m, newIndex, faces, faceSlot);
  const std::string header = Header(binary, comments, nv, faces.size(), crease ? long(crease->net.edges.size()) : -1L);
  FILE* fp = std::fopen(path.c_str(), "wb");
  if (!fp) {
    error = "cannot open '" + path + "' for writing: " + std::strerror(errno);
    return false;
  }
  int writeErrno = 0;
  auto put = [&](const std::string& s) {
    if (writeErrno == 0 && std::fwrite(s.data(), 1, s.size(), fp) != s.size()) writeErrno = errno ? errno : EIO;
  };
  put(header);
  std::string buf;
  auto flush = [&](bool force) {
    if (force || buf.size() > (1u << 20)) {
      put(buf);
      buf.clear();
    }
  };
  for (std::size_t i = 0; i < m.vert.size() && writeErrno == 0; ++i) {
    if (newIndex[i] < 0) continue;
    const ResultPlyVertex rec = MakeResultPlyVertex(m, i, res[i]);
    bool first = true;
    ForEachResultPlyField(rec, [&](const char*, const auto& field) {
      if (binary) {
        AppendBinary(buf, field);
      } else {
        if (!first) buf += ' ';
        AppendAscii(buf, field);
      }
      first = false;
    });
    if (!binary) buf += '\n';
    flush(false);
  }
  for (std::size_t i = 0; i < faces.size() && writeErrno == 0; ++i) {
    const auto& t = faces[i];
    if (binary) {
      AppendBinary(buf, std::uint8_t(3));
      for (int j = 0; j < 3; ++j) AppendBinary(buf, std::int32_t(t[j]));
      if (crease) AppendBinary(buf, std::int32_t(crease->meshFacePatch[faceSlot[i]]));
    } else {
      buf += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]);
      if (crease) buf += " " + std::to_string(crease->meshFacePatch[faceSlot[i]]);
      buf += "\n";
    }
    flush(false);
  }
  // The network's vertices are live (the graph never uses a deleted one), so each has a new index.
  for (std::size_t e = 0; crease && e < crease->net.edges.size() && writeErrno == 0; ++e) {
    const std::int32_t a = newIndex[crease->net.edges[e][0]], b = newIndex[crease->net.edges[e][1]];
    const float cusp = crease->net.edgeCuspAngle[e];
    const std::int32_t line = crease->net.edgeLine[e];
    if (binary) {
      AppendBinary(buf, a), AppendBinary(buf, b), AppendBinary(buf, cusp), AppendBinary(buf, line);
    } else {
      AppendAscii(buf, a), buf += ' ', AppendAscii(buf, b), buf += ' ', AppendAscii(buf, cusp), buf += ' ';
      AppendAscii(buf, line), buf += '\n';
    }
    flush(false);
  }
  flush(true);
  return CloseOutput(fp, writeErrno, path, error);
}

template <class MeshType>
bool WriteResultPly(const std::string& path, const MeshType& m, const std::vector<VertexResult>& res, bool binary,
                    std::string& error) {
  return WriteResultPly(path, m, res, binary, std::vector<std::string>(), error);
}

}  // namespace nvv


#endif
