// The crease lines of a run as a polyline file, for CAD and plotting tools that take curves, not
// meshes. The format follows the file name's extension:
//
//   .obj  "v x y z" for every vertex of a line, then one "l i j k ..." record per line (1-based
//         indices, in order along the line; a closed line repeats its first index at its end),
//         each after a comment "# line <id>: length <l>, mean cusp angle <deg> deg, closed" or
//         "..., ends <corner|free> <corner|free>".
//   .ply  ascii; "element vertex" (x y z float) with the lines' vertices, and "element edge"
//         (vertex1 vertex2 int, cusp_angle float in radians, line int): each line's edges in order
//         along it, so the edges of line i are those with line == i.
//
// The vertices are those the lines pass through, each once, numbered in the order the lines
// first reach them. Only vcglib and the standard library are used here.
#ifndef NVV_IO_CREASE_LINES_FILE_H
#define NVV_IO_CREASE_LINES_FILE_H

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/params.h"
#include "filter/crease_outputs.h"
#include "io/close_output.h"

namespace nvv {

// The format a crease-lines file name asks for: ".obj" or ".ply" (the extension in any case), or
// empty when it names neither.
inline std::string CreaseLinesFormat(const std::string& path) {
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : std::string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".obj" || ext == ".ply" ? ext : std::string();
}

// Empty when `path` names a crease-lines file; otherwise the sentence that refuses it.
inline std::string CreaseLinesNameError(const std::string& path) {
  return CreaseLinesFormat(path).empty() ? "the crease lines file name must end in .obj or .ply (got '" + path + "')"
                                         : std::string();
}

// Writes the lines of `crease` (vertex indices into m.vert) to `path`, .obj or .ply by its
// extension. On failure returns false, sets `error` to one sentence and removes a partial
// regular file.
template <class MeshType>
bool WriteCreaseLines(const std::string& path, const MeshType& m, const CreaseOutputs& crease, std::string& error) {
  const std::string ext = CreaseLinesFormat(path);
  if (ext.empty()) {
    error = CreaseLinesNameError(path);
    return false;
  }
  const std::vector<CreaseLine>& lines = crease.net.lines;
  const CreaseLineEdges le = LinesAsEdges(crease, m.vert.size());
  const std::vector<int>& vertices = le.meshVertex;
  const std::vector<std::vector<int>>& polylines = le.polylines;
  auto position = [&](int fileVertex) {
    char buf[96];
    const auto& p = m.vert[vertices[fileVertex]].cP();
    std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g", double(p[0]), double(p[1]), double(p[2]));
    return std::string(buf);
  };
  std::string out;
  if (ext == ".obj") {
    out += "# Normal Vector Voting crease lines: " + std::to_string(lines.size()) + " lines\n";
    for (std::size_t i = 0; i < vertices.size(); ++i) out += "v " + position(int(i)) + "\n";
    for (std::size_t l = 0; l < lines.size(); ++l) {
      const CreaseLine& line = lines[l];
      char buf[256];
      std::snprintf(buf, sizeof buf, "# line %zu: length %.9g, mean cusp angle %.6g deg, ", l, line.length,
                    RadToDeg(line.meanCuspAngle));
      out += buf;
      out += line.closed ? std::string("closed")
                         : std::string("ends ") + (line.endCorner[0] >= 0 ? "corner " : "free ") +
                               (line.endCorner[1] >= 0 ? "corner" : "free");
      out += "\nl";
      for (int v : polylines[l]) out += " " + std::to_string(v + 1);
      if (line.closed) out += " " + std::to_string(polylines[l].front() + 1);
      out += "\n";
    }
  } else {
    std::string body;
    for (const CreaseLineEdges::Edge& e : le.edges) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%d %d %.9g %d\n", e.a, e.b, double(e.cuspAngle), e.line);
      body += buf;
    }
    const std::size_t edges = le.edges.size();
    out += "ply\nformat ascii 1.0\ncomment Normal Vector Voting crease lines\n";
    out += "element vertex " + std::to_string(vertices.size()) + "\n";
    out += "property float x\nproperty float y\nproperty float z\n";
    out += "element edge " + std::to_string(edges) + "\n";
    out += "property int vertex1\nproperty int vertex2\nproperty float cusp_angle\nproperty int line\nend_header\n";
    for (std::size_t i = 0; i < vertices.size(); ++i) out += position(int(i)) + "\n";
    out += body;
  }
  FILE* fp = std::fopen(path.c_str(), "wb");
  if (!fp) {
    error = "cannot open '" + path + "' for writing: " + std::strerror(errno);
    return false;
  }
  const int writeErrno = std::fwrite(out.data(), 1, out.size(), fp) == out.size() ? 0 : (errno ? errno : EIO);
  return CloseOutput(fp, writeErrno, path, error);
}

}  // namespace nvv

#endif
