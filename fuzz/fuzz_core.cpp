// libFuzzer target over mesh + parameters: the bytes choose the parameters (through the same
// table the filter's dialog uses, so out-of-range values are refused there as in MeshLab), then
// vertices (raw floats: NaN, inf, huge, tiny, duplicates) and faces (raw indices, possibly out
// of range or repeated). The core runs and, when it succeeds, the crease network is found and the
// results are written onto the mesh, as the run sequence does. Any crash, sanitizer report or
// hang is a finding.
#include <cstdint>
#include <cstring>
#include <vector>

#include "../tests/test_mesh.h"
#include "filter/apply_results.h"
#include "filter/crease_outputs.h"
#include "core/normal_vector_voting.h"

namespace {
struct Reader {
  const std::uint8_t* p;
  std::size_t n;
  template <class T>
  T Take() {
    T v{};
    const std::size_t k = n < sizeof(T) ? n : sizeof(T);
    std::memcpy(&v, p, k);
    p += k;
    n -= k;
    return v;
  }
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in{data, size};
  nvv::FilterOptions o = nvv::DefaultOptions();
  const auto& table = nvv::FilterParameterTable();
  const int overrides = in.Take<std::uint8_t>() % 5;
  for (int i = 0; i < overrides; ++i) {
    const auto& spec = table[in.Take<std::uint8_t>() % table.size()];
    const float value = in.Take<float>();
    nvv::SetOption(o, spec.name, value);  // refused values keep the default, as in the dialog
  }
  // Now and then bypass the table and hand the core raw values, as a caller of the core would:
  // its own validation must refuse what is absurd.
  const std::uint8_t raw = in.Take<std::uint8_t>();
  if (raw & 1) o.core.k = in.Take<float>();
  if (raw & 2) o.core.absoluteRadius = in.Take<float>();
  if (raw & 4) o.core.creaseAngleDeg = in.Take<float>();
  if (raw & 8) o.core.cornerAngleDeg = in.Take<float>();
  if (raw & 16) o.core.sigmaFraction = in.Take<float>();
  if (raw & 32) o.core.maxNeighbourhood = in.Take<std::int32_t>();
  o.core.threads = 1 + in.Take<std::uint8_t>() % 2;
  nvv_test::TMesh m;
  const int nv = in.Take<std::uint8_t>() % 64, nf = in.Take<std::uint8_t>() % 128;
  if (nv > 0) vcg::tri::Allocator<nvv_test::TMesh>::AddVertices(m, nv);
  for (int i = 0; i < nv; ++i) m.vert[i].P() = vcg::Point3d(in.Take<float>(), in.Take<float>(), in.Take<float>());
  for (int f = 0; f < nf && nv > 0; ++f) {
    const int a = in.Take<std::uint8_t>() % nv, b = in.Take<std::uint8_t>() % nv, c = in.Take<std::uint8_t>() % nv;
    vcg::tri::Allocator<nvv_test::TMesh>::AddFace(m, &m.vert[a], &m.vert[b], &m.vert[c]);
  }
  std::vector<nvv::VertexResult> res;
  nvv::Summary sum;
  nvv::SurfaceGraph g;
  const nvv::Status st = vcg::tri::NormalVectorVoting<nvv_test::TMesh>::Compute(m, o.core, res, sum, g);
  if (!st.ok) return 0;
  const nvv::CreaseOutputs crease = nvv::FindCreaseOutputs(m, g, res, sum, o.core.creaseAngleDeg);
  nvv::ApplyResults<nvv_test::TMesh>::Apply(m, res, o, &crease);
  return 0;
}
