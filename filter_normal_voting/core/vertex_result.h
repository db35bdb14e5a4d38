// The per-vertex result record of Normal Vector Voting and the run summary.
// Adapters copy these out; nothing here refers to a mesh type.
#ifndef NVV_CORE_VERTEX_RESULT_H
#define NVV_CORE_VERTEX_RESULT_H

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace nvv {

// Eq. 10's three classes, plus vertices that could not be classified at all.
enum class VertexClass : std::uint8_t {
  Surface = 0,  // smooth sheet: normal, kappa1 >= kappa2, T1, T2
  Crease = 1,   // two sheets meet: crease tangent, curvature along it, cusp angle
  Corner = 2,   // no preferred orientation (3+ sheets, or noise too strong)
  Invalid = 3,  // deleted, unreferenced, non-finite, or no usable triangle around it
};

inline const char* ClassName(VertexClass c) {
  switch (c) {
    case VertexClass::Surface: return "surface";
    case VertexClass::Crease: return "crease";
    case VertexClass::Corner: return "corner";
    default: return "invalid";
  }
}

// Bits of VertexResult::flags.
enum ResultFlag : std::uint8_t {
  kNormalValid = 1,     // normal holds the (voted or fitted) oriented unit normal
  kCurvatureValid = 2,  // k1, k2, t1, t2 hold a curvature estimate
  kCreaseValid = 4,     // creaseTangent, creaseCurvature, cuspAngle are set
  kNeighbourhoodCapped = 8,  // the march hit Params::maxNeighbourhood
};

// Stored in float: the estimates are far less precise than float, and a million-vertex
// mesh keeps its results in ~70 MB. All computation is in double.
struct VertexResult {
  VertexClass cls = VertexClass::Invalid;
  std::uint8_t flags = 0;
  float lambda[3] = {0, 0, 0};   // vote-matrix eigenvalues, ordered as Eq. 10 used them, sum 1
  float normal[3] = {0, 0, 0};   // oriented unit normal (Surface; bisector for Crease)
  float k1 = 0, k2 = 0;          // principal curvatures, k1 >= k2; sphere of radius R: +1/R
  float t1[3] = {0, 0, 0};       // direction of k1
  float t2[3] = {0, 0, 0};       // direction of k2
  float creaseTangent[3] = {0, 0, 0};
  float creaseCurvature = 0;     // curvature along the crease line
  float cuspAngle = 0;           // angle between the two sheets' normals, radians (par. 6.5)

  bool Has(ResultFlag f) const { return (flags & f) != 0; }
  float SurfaceSaliency() const { return lambda[0] - lambda[1]; }  // Eq. 9
  float CreaseSaliency() const { return lambda[1] - lambda[2]; }
  float CornerSaliency() const { return lambda[2]; }
};

// Crease or corner: where two or more sheets meet.
inline bool IsFeature(const VertexResult& r) { return r.cls == VertexClass::Crease || r.cls == VertexClass::Corner; }

// A result's float[3] as a double vector.
inline Eigen::Vector3d ToVec(const float* p) { return Eigen::Vector3d(p[0], p[1], p[2]); }

struct Summary {
  std::size_t vertices = 0;         // size of the vertex container (results are indexed by it)
  std::size_t perClass[4] = {0, 0, 0, 0};
  std::size_t capped = 0;           // vertices whose march hit the neighbourhood cap
  bool sharpEdges = false;          // a clean mesh: the classes came from its sharp edges (sharp_edges.h)
  bool sharpEdgesAdded = false;     // a noisy mesh: its sharp edges added creases and corners to the votes' classes
  std::size_t sharpEdgeChanged = 0; // vertices whose class the sharp edges changed from the votes'
  std::size_t thinned = 0;          // feature vertices thinning removed: band vertices made surface, less gap vertices made creases (crease_thinning.h)
  std::size_t nonFiniteVertices = 0;
  std::size_t unreferencedVertices = 0;
  std::size_t degenerateFaces = 0;  // zero-area faces: used for distances, not for votes
  std::size_t droppedFaces = 0;     // faces with a repeated or non-finite vertex
  std::size_t repeatedFaces = 0;    // faces with the same three vertices as an earlier one: counted once
  bool consistentlyOriented = true;
  bool signAwareUsed = true;
  double meanEdge = 0, radius = 0, epsilon = 0, eta = 0;
  double k = 0;                     // the k the run used: Params::k, or automatic k's choice
  bool autoK = false;               // k was chosen from the noise (Params::autoK)
  double noiseOverEdge = 0;         // estimated noise along the normals / l_ave (noise_estimate.h)
  double k1Min = 0, k1Max = 0, k2Min = 0, k2Max = 0;  // over vertices with kCurvatureValid
  double secondsPass1 = 0, secondsPass2 = 0, secondsTotal = 0;
  std::vector<std::string> warnings;
};

}  // namespace nvv

#endif
