// Pass 1 of Normal Vector Voting (par. 6.2-6.3): every triangle of the geodesic
// neighbourhood M_v votes for the normal at v; the votes' covariance classifies v.
//
//   u = (c_i - v) / |c_i - v|,  cos(theta_i) = -N' u
//   N_i = N + 2 cos(theta_i) u                                (Eq. 6, N reflected along the arc)
//   w_i = (A_i / A_max) exp(-g_i / sigma),  sigma = g_m / 3   (Eq. 8)
//   V_v = sum w_i N_i N_i'                                    (Eq. 7)
//   lambda1 >= lambda2 >= lambda3, E1, E2, E3 = eig(V_v)
//   S_s = l1 - l2, S_c = l2 - l3, S_n = l3                    (Eq. 9)
//   class = argmax {S_s, eps S_c, eps eta S_n}                (Eq. 10)
//
// M_v holds the triangles whose three vertices are within g_m, plus v's one-ring always.
// In the paper's form (Params::floodFirst false) g_m and g_i are geodesic: the fast march of
// par. 6.1, g_i the mean of the three vertex distances (the centroid's, approximately). By
// default each vertex is voted first over the Euclidean ball (the vertices joined to v inside
// |x - v| <= g_m, ball_flood.h) with g_i = |c_i - v|, and where those votes do not make v a
// surface vertex with a margin, or a face of the ball turns from v's one-ring normal by more
// than 3/4 of the crease angle, it is voted again over the geodesic neighbourhood
// (normal_votes.cpp, VoteNormal): on a smooth sheet the two differ by g^3 / (24 R^2), while
// beside a crease the Euclidean ball weighs the other sheet more.
#ifndef NVV_CORE_NORMAL_VOTES_H
#define NVV_CORE_NORMAL_VOTES_H

#include <vector>

#include "geodesic_march.h"
#include "parallel_pass.h"
#include "params.h"
#include "vertex_result.h"

namespace nvv {

// Eq. 10's surface case: S_s beats both eps S_c and eps eta S_n. Pass 1 classifies with it, and
// the ridge confirmation (crease_thinning.cpp) asks it at another angle.
inline bool SurfaceByEq10(double Ss, double Sc, double Sn, double epsilon, double eta) {
  return Ss >= epsilon * Sc && Ss >= epsilon * eta * Sn;
}

struct Pass1Settings {
  double radius = 0;     // g_m
  double sigma = 0;      // Eq. 8
  double epsilon = 2, eta = 2;
  bool signAware = true;
  int maxNeighbourhood = 1024;
  double noiseSigma = 0;  // the noise along the normals (noise_estimate.h), in the mesh's units
  bool floodFirst = true;  // Params::floodFirst
  double cosFloodTurn = 0; // the most a face of a flooded ball may turn (tuning::kFloodTurnOfCreaseAngle)
};

// Pass 1 over every vertex, in parallel: out[v]'s cls, lambda, normal, creaseTangent and
// cuspAngle.
PassEnd VoteNormals(const SurfaceGraph& g, const Pass1Settings& s, int threads, PassProgress& progress,
                    std::vector<VertexResult>& out);

}  // namespace nvv

#endif
