// The records of the full-result PLY (its format is documented in result_ply.h) and the one
// list of its vertex properties, shared by the writer and the reader. Standard library only.
#ifndef NVV_IO_RESULT_PLY_FORMAT_H
#define NVV_IO_RESULT_PLY_FORMAT_H

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace nvv {

// One vertex of the result file, field for field.
struct ResultPlyVertex {
  float position[3] = {0, 0, 0};
  float normal[3] = {0, 0, 0};
  std::uint8_t color[4] = {0, 0, 0, 0};
  float quality = 0;
  std::uint8_t cls = 3;
  float lambda[3] = {0, 0, 0};
  float k1 = 0, k2 = 0;
  float pd1[3] = {0, 0, 0};
  float pd2[3] = {0, 0, 0};
  float creaseTangent[3] = {0, 0, 0};
  float creaseCurvature = 0;
  float cuspAngleDeg = 0;
  std::uint8_t flags = 0;
  std::uint8_t selected = 0;
};

// One crease edge of the result file (the element "edge", written when the run found the crease
// network): two indices into the vertex element, the cusp angle in radians, the crease line.
struct ResultPlyEdge {
  int vertex[2] = {0, 0};
  float cuspAngle = 0;
  int line = -1;
};

struct ResultPlyData {
  bool binary = true;
  std::vector<std::string> comments;        // header comments, without the "comment " keyword
  std::vector<ResultPlyVertex> vertices;
  std::vector<std::array<int, 3>> faces;
  std::vector<int> facePatch;               // per face, when the file has the face property "patch"
  std::vector<ResultPlyEdge> edges;         // empty when the file has no edge element
};

// Calls f(name, field) for every vertex property, in file order. The writer, the reader and
// the header all come from this one list.
template <class Vertex, class F>
void ForEachResultPlyField(Vertex& v, F&& f) {
  f("x", v.position[0]); f("y", v.position[1]); f("z", v.position[2]);
  f("nx", v.normal[0]); f("ny", v.normal[1]); f("nz", v.normal[2]);
  f("red", v.color[0]); f("green", v.color[1]); f("blue", v.color[2]); f("alpha", v.color[3]);
  f("quality", v.quality);
  f("nvv_class", v.cls);
  f("nvv_lambda1", v.lambda[0]); f("nvv_lambda2", v.lambda[1]); f("nvv_lambda3", v.lambda[2]);
  f("k1", v.k1); f("k2", v.k2);
  f("pd1x", v.pd1[0]); f("pd1y", v.pd1[1]); f("pd1z", v.pd1[2]);
  f("pd2x", v.pd2[0]); f("pd2y", v.pd2[1]); f("pd2z", v.pd2[2]);
  f("nvv_crease_tangent_x", v.creaseTangent[0]);
  f("nvv_crease_tangent_y", v.creaseTangent[1]);
  f("nvv_crease_tangent_z", v.creaseTangent[2]);
  f("nvv_crease_curvature", v.creaseCurvature);
  f("nvv_cusp_angle", v.cuspAngleDeg);
  f("nvv_flags", v.flags);
  f("nvv_selected", v.selected);
}

}  // namespace nvv

#endif
