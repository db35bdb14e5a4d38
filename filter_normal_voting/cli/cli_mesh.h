// The command-line tool's mesh: float, with the per-vertex components of MeshLab's CMeshO that
// the filter reads or writes (normal, colour, quality, curvature directions, flags), so the
// tool's numbers are those of the MeshLab plugin, which runs on a float CMeshO.
#ifndef NVV_CLI_CLI_MESH_H
#define NVV_CLI_CLI_MESH_H

#include <vcg/complex/complex.h>

namespace nvv_cli {

class CliVertex;
class CliFace;
struct CliUsedTypes : public vcg::UsedTypes<vcg::Use<CliVertex>::AsVertexType, vcg::Use<CliFace>::AsFaceType> {};
class CliVertex : public vcg::Vertex<CliUsedTypes, vcg::vertex::Coord3f, vcg::vertex::BitFlags, vcg::vertex::Normal3f,
                                     vcg::vertex::Qualityf, vcg::vertex::Color4b, vcg::vertex::CurvatureDirf> {};
class CliFace : public vcg::Face<CliUsedTypes, vcg::face::VertexRef, vcg::face::BitFlags, vcg::face::Normal3f> {};
class CliMesh : public vcg::tri::TriMesh<std::vector<CliVertex>, std::vector<CliFace>> {
 public:
  // vcglib's TriMesh destructor leaves the per-vertex attributes (nvv_class, ...) allocated.
  ~CliMesh() { ClearAttributes(); }
};

}  // namespace nvv_cli

#endif
