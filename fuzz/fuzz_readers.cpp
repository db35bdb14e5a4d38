// libFuzzer target over one mesh reader (io/mesh_reader.h), chosen at build time with
// -DNVV_FUZZ_FORMAT=Ply|Obj|Off|Stl. The bytes are the file. Any crash, sanitizer report, hang,
// or a successful read whose triangles refer to vertices that do not exist is a finding.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "io/mesh_reader.h"

#ifndef NVV_FUZZ_FORMAT
#error "define NVV_FUZZ_FORMAT as Ply, Obj, Off or Stl"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  nvv::io::MeshData mesh;
  std::string error;
  nvv::io::ReadLimits limits;
  limits.maxPolygonCorners = 1u << 12;  // keeps single inputs fast; the limit itself is tested elsewhere
  const bool ok = nvv::io::ReadMeshBytes(reinterpret_cast<const char*>(data), size, nvv::io::MeshFormat::NVV_FUZZ_FORMAT,
                                         mesh, error, limits);
  if (!ok) {
    if (error.empty() || !mesh.positions.empty() || !mesh.triangles.empty()) std::abort();
    return 0;
  }
  const std::size_t nv = mesh.positions.size();
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || std::size_t(t[k]) >= nv) std::abort();
  if ((!mesh.normals.empty() && mesh.normals.size() != nv) || (!mesh.colors.empty() && mesh.colors.size() != nv) ||
      (!mesh.quality.empty() && mesh.quality.size() != nv))
    std::abort();
  return 0;
}
