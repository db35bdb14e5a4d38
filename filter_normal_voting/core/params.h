// Parameters of Normal Vector Voting (Page et al. 2002) and their validation.
//
// The user thinks in angles; the paper's system constants follow from them (Eq. 11-12):
//   tan(phi/2) = sqrt(1/(eps+1))  =>  eps = 1/tan^2(phi/2) - 1
//   tan(psi/2) = sqrt(1/(eta+1))  =>  eta = 1/tan^2(psi/2) - 1
// phi = psi = 60 deg gives the paper's robust default eps = eta = 2. Both constants must be
// positive, so both angles lie in (0, 90) degrees.
#ifndef NVV_CORE_PARAMS_H
#define NVV_CORE_PARAMS_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "tuning.h"

namespace nvv {

// How pass 2 turns the neighbourhood into principal curvatures and directions.
enum class CurvatureFit : int {
  // Weighted least-squares quadratic height field over the same-sheet neighbours, in the
  // frame of the voted normal, with one height row and two slope rows (voted normals) per
  // neighbour. Also refines the normal. The default: it wins the accuracy benchmark.
  SheetQuadric = 0,
  // The paper's form: Taubin's matrix B_v (Eq. 5) from the curvature votes (Eq. 13-17) and
  // the eigenvalue relation of Eq. 4.
  PaperTaubin = 1,
  // The same curvature votes, fitted to Euler's formula kappa_i = T_i' II T_i by weighted
  // least squares (no assumption that votes spread evenly over all directions).
  EulerLeastSquares = 2,
};

// How pass 1 orders the two largest eigenpairs before Eq. 10.
enum class ClassRule : int {
  // Put first the eigenpair most aligned with the oriented mean vote, so creases with a
  // normal-angle above 90 deg are not mistaken for surfaces (ALGORITHM.md). Falls back to
  // PaperOrder on meshes that are not consistently oriented.
  SignAware = 0,
  PaperOrder = 1,  // eigenvalues in decreasing order, as in the paper
};

// The quadric fit's levers beyond the plain weighted quadratic (sheet_fit.cpp), each on by
// default and each switchable alone, for tests and for measuring what each buys.
struct SheetFitLevers {
  bool reweightSlopes = true;  // slope rows down-weighted where the heights fit far better
  bool slopeCurvature = true;  // second-order terms from the slopes where they fit far better
  bool tiltTest = true;        // first rounds beside creases keep the heights' normal where the slopes tilt it
  bool circleTerm = true;      // one-sided fits beside creases follow circles exactly
};

struct Params {
  double k = 3.0;               // neighbourhood radius g_m = k * mean edge length ...
  bool autoK = false;           // ... with k chosen from the mesh's noise (noise_estimate.h) if set ...
  double absoluteRadius = 0.0;  // ... unless this is > 0: then g_m = absoluteRadius
  // phi: smallest angle between two sheets' normals that is a crease. It drives four things:
  //  - Eq. 10's epsilon (EpsilonFromAngle), i.e. pass 1's classes (normal_votes.cpp);
  //  - the ridge fit's kink test: a ridge's two fitted sheets are at least phi apart, and where
  //    only an angle below 60 deg makes v a crease of the votes they also fit v's heights within
  //    the noise (crease_thinning.cpp, ScoreRidges; tuning.h);
  //  - the sharp-edge veto of thinning: an edge whose faces are more than phi apart (or five
  //    median edge angles, tuning.h) is a crease of the mesh itself (crease_thinning.cpp);
  //  - the quadric fit's sample weights: a neighbour whose normal is phi or more off v's gets no
  //    weight, and never one within 50 deg (sheet_fit.cpp, SampleInFrame; tuning.h).
  // 40 by default: under noise the votes alone find the 45 deg chamfers of CAD parts (the paper
  // leaves phi to the user; docs/accuracy.md measures 40 against 60).
  double creaseAngleDeg = 40.0;
  // On a clean mesh (a CAD export) every class comes from the mesh edges whose dihedral angle is at
  // least this (capped by the crease angle) and that stand out from the lines beside them
  // (sharp_edges.h), not from the votes; on a noisy mesh the sharp edges only add creases and
  // corners (from about 9 % noise only edges that turn much more than the lines beside them, or far
  // more than the noise tilts their faces); 0: the votes everywhere, as in the paper.
  // docs/accuracy.md's CAD section measures both.
  double sharpEdgeAngleDeg = 10.0;
  double cornerAngleDeg = 60.0; // psi: the same for the third direction (corners)
  bool stopAtCreases = true;    // pass 2 does not march through non-surface vertices (par. 6.5)
  bool thinCreases = true;      // keep only the ridge of each crease band (crease_thinning.h); paper: false
  bool ridgeFit = true;         // thinCreases only: find the ridge by a two-plane fit (ridge_fit.h), not by Eq. 7's strength
  CurvatureFit fit = CurvatureFit::SheetQuadric;
  // SheetQuadric only: how many times pass 2 fits. Round 1 fits the voted normals of pass 1;
  // each further round fits again, in the frame of v's fitted normal, with the neighbours'
  // fitted normals in the slope rows (re-voting with refined normals). See docs/accuracy.md
  // for what each round buys and costs.
  int fitRounds = 2;
  // SheetQuadric only: where the neighbourhood reaches no crease vertex and the mesh's border is
  // not within g_m / 2, a cubic height field replaces the quadratic if its extra terms are
  // significant (sheet_fit.h, normal_vector_voting.h); false: always quadratic.
  bool cubicFit = true;
  SheetFitLevers levers;        // SheetQuadric only; not in the parameter table
  // Pass 1 votes first over the Euclidean ball and marches only where those votes do not settle
  // a surface vertex (normal_votes.cpp); false: the geodesic march everywhere, as in the paper.
  // Not in the parameter table: for tests and for measuring what it changes.
  bool floodFirst = true;
  ClassRule classRule = ClassRule::SignAware;
  double sigmaFraction = 1.0 / 3.0;  // Eq. 8: sigma = sigmaFraction * g_m (paper: 1/3)
  // Cap on the vertices one march may accept; 0 = automatic, AutoNeighbourhoodCap(). Bounds the
  // cost of pathological input (a 100,000-valence fan) without truncating ordinary neighbourhoods.
  int maxNeighbourhood = 0;
  int threads = 0;              // 0: OpenMP's default
};

// A uniform triangulation puts about (2 / sqrt 3) pi k^2 ~ 3.6 k^2 vertices within g_m = k l_ave;
// the automatic cap allows four times that (regions up to 4x denser than average keep their whole
// neighbourhood), and never less than 1,024. On a large mesh it allows no more than the mesh's
// share of tuning::kAutoVisitBudget either: k = 50 on a million vertices would otherwise march
// 9,000 vertices from each (hours); it marches the nearest 1,024 (effective k about 17) and the
// summary says how many neighbourhoods were truncated.
inline int AutoNeighbourhoodCap(double kEffective, std::size_t vertexCount) {
  // An absolute radius far beyond the mesh's edges costs what the largest k costs, not more.
  if (!(kEffective <= tuning::kAutoCapMaxK)) kEffective = tuning::kAutoCapMaxK;  // NaN too
  double c = tuning::kAutoCapPerK2 * kEffective * kEffective;
  if (vertexCount > 0) c = std::min(c, tuning::kAutoVisitBudget / double(vertexCount));
  return c > double(tuning::kMaxCap) ? tuning::kMaxCap : (c < double(tuning::kAutoCapMin) ? tuning::kAutoCapMin : int(c));
}

// The weight of a vote cast from geodesic distance g (Eq. 8's fall-off, sigma = sigmaFraction *
// g_m; pass 1 multiplies it by the triangle's relative area). Written once for the three kinds of
// votes: pass 1's normal votes, the paper's curvature votes, and the crease-curvature votes.
inline double VoteWeight(double g, double sigma) { return std::exp(-g / sigma); }

inline double DegToRad(double d) { return d * 3.14159265358979323846 / 180.0; }
inline double RadToDeg(double r) { return r * 180.0 / 3.14159265358979323846; }

// Eq. 11 / 12 solved for the constant.
inline double EpsilonFromAngle(double angleDeg) {
  const double t = std::tan(DegToRad(angleDeg) / 2.0);
  return 1.0 / (t * t) - 1.0;
}
inline double AngleFromEpsilon(double eps) {
  return RadToDeg(2.0 * std::atan(std::sqrt(1.0 / (eps + 1.0))));
}

// Empty when the parameters are usable; otherwise a sentence for the user.
std::string ValidateParams(const Params& p);

}  // namespace nvv

#endif
