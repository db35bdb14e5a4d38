#include "normal_vector_voting.h"

#include <algorithm>
#include <chrono>

#include "crease_curvature.h"
#include "crease_thinning.h"
#include "huge_pages.h"
#include "noise_estimate.h"
#include "normal_votes.h"
#include "sharp_edges.h"
#include "surface_curvature.h"

namespace nvv {
namespace {

typedef std::chrono::steady_clock Clock;

double SecondsSince(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

Status Refused(const std::string& why) {
  Status st;
  st.message = why;
  return st;
}

// The Status of a pass that did not finish.
Status Unfinished(PassEnd end) {
  Status st;
  st.cancelled = end == PassEnd::Cancelled;
  st.message = st.cancelled ? "Cancelled." : "Out of memory: the neighbourhoods did not fit. Try a smaller k.";
  return st;
}

// What the graph says of the input, before anything is computed.
void DescribeInput(const SurfaceGraph& g, Summary& sum) {
  sum.vertices = g.pos.size();
  sum.nonFiniteVertices = g.nonFinite;
  sum.unreferencedVertices = g.unreferenced;
  sum.degenerateFaces = g.degenerate;
  sum.droppedFaces = g.dropped;
  sum.repeatedFaces = g.repeated;
  sum.consistentlyOriented = g.consistentlyOriented;
  sum.meanEdge = g.meanEdge;
}

// Stage "validate": empty when the parameters and the mesh can run; otherwise why not.
std::string ValidateRun(const SurfaceGraph& g, const Params& p) {
  const std::string bad = ValidateParams(p);
  if (!bad.empty()) return bad;
  if (g.VertexCount() == 0) return "The mesh is empty.";
  if (g.FaceCount() == 0)
    return "The mesh has no faces (a point cloud?) or no usable triangles (every face is deleted, repeats a "
           "vertex or has a non-finite coordinate): normal vector voting needs a triangle mesh; reconstruct "
           "a surface first.";
  if (!(g.maxArea > 0) || !(g.meanEdge > 0) || !std::isfinite(g.meanEdge))
    return "Every triangle of the mesh has zero area: there is no surface to vote on.";
  return std::string();
}

// The radius, Eq. 8's sigma, Eq. 10's constants, the neighbourhood cap and the noise for this mesh.
Pass1Settings SettingsFor(const SurfaceGraph& g, const Params& p, const NoiseEstimate& noise) {
  Pass1Settings s;
  s.noiseSigma = noise.sigmaOverEdge * g.meanEdge;
  s.radius = p.absoluteRadius > 0 ? p.absoluteRadius : p.k * g.meanEdge;
  s.sigma = p.sigmaFraction * s.radius;
  s.epsilon = EpsilonFromAngle(p.creaseAngleDeg);
  s.eta = EpsilonFromAngle(p.cornerAngleDeg);
  s.signAware = p.classRule == ClassRule::SignAware && g.consistentlyOriented;
  s.floodFirst = p.floodFirst && s.radius >= tuning::kFloodFirstMinK * g.meanEdge;
  s.cosFloodTurn = std::cos(DegToRad(p.creaseAngleDeg * tuning::kFloodTurnOfCreaseAngle));
  s.maxNeighbourhood = p.maxNeighbourhood > 0 ? p.maxNeighbourhood
                                              : AutoNeighbourhoodCap(s.radius / g.meanEdge, std::size_t(g.VertexCount()));
  return s;
}

void RecordSettings(const SurfaceGraph& g, const Params& p, const Pass1Settings& s, Summary& sum) {
  sum.radius = s.radius;
  sum.epsilon = s.epsilon;
  sum.eta = s.eta;
  sum.signAwareUsed = s.signAware;
  if (p.classRule == ClassRule::SignAware && !g.consistentlyOriented)
    sum.warnings.push_back("The faces are not consistently oriented: the paper's classification rule "
                           "was used instead of the sign-aware one (creases above 120 degrees may be missed).");
}

// Stage "creases": only where there is a crease (the march is the costly part).
PassEnd CreaseStage(const SurfaceGraph& g, const Pass1Settings& s, int threads, const Progress& cb,
                    std::vector<VertexResult>& out) {
  if (std::none_of(out.begin(), out.end(), [](const VertexResult& r) { return r.cls == VertexClass::Crease; }))
    return PassEnd::Done;
  PassProgress progress(cb, g.VertexCount(), 100, 100, "Normal vector voting: curvature along creases");
  return CurvatureAlongCreases(g, s, threads, progress, out);
}

// Stage "summarise": counts per class, curvature ranges, warnings about the input.
void Summarise(const SurfaceGraph& g, const Pass1Settings& s, const std::vector<VertexResult>& out, Summary& sum) {
  bool first = true;
  for (const auto& r : out) {
    ++sum.perClass[int(r.cls)];
    if (r.Has(kNeighbourhoodCapped)) ++sum.capped;
    if (!r.Has(kCurvatureValid)) continue;
    if (first) { sum.k1Min = sum.k1Max = r.k1; sum.k2Min = sum.k2Max = r.k2; first = false; }
    sum.k1Min = std::min<double>(sum.k1Min, r.k1);
    sum.k1Max = std::max<double>(sum.k1Max, r.k1);
    sum.k2Min = std::min<double>(sum.k2Min, r.k2);
    sum.k2Max = std::max<double>(sum.k2Max, r.k2);
  }
  if (sum.capped > 0)
    sum.warnings.push_back(std::to_string(sum.capped) + " vertices reached the neighbourhood cap of " +
                           std::to_string(s.maxNeighbourhood) + " vertices; their neighbourhood was truncated "
                           "(max_neighbourhood raises the cap).");
  if (g.nonFinite > 0)
    sum.warnings.push_back(std::to_string(g.nonFinite) + " vertices have non-finite coordinates and were left out.");
  if (g.unreferenced > 0)
    sum.warnings.push_back(std::to_string(g.unreferenced) + " vertices belong to no face and were left unclassified.");
  if (g.degenerate > 0)
    sum.warnings.push_back(std::to_string(g.degenerate) + " faces have zero area and cast no vote.");
  if (g.dropped > 0)
    sum.warnings.push_back(std::to_string(g.dropped) + " faces repeat a vertex or touch a non-finite one and were ignored.");
  if (g.repeated > 0)
    sum.warnings.push_back(std::to_string(g.repeated) + " faces have the same three vertices as another face and were "
                           "counted once.");
  const std::size_t unclassified = sum.perClass[int(VertexClass::Invalid)];
  // Deleted, non-finite and unreferenced vertices are unclassified by definition.
  const std::size_t explained = std::size_t(std::count(g.usable.begin(), g.usable.end(), 0)) + g.unreferenced;
  if (unclassified > explained)
    sum.warnings.push_back(std::to_string(unclassified - explained) + " vertices of usable faces could not be "
                           "classified (their neighbourhood held no triangle with an area); check the radius "
                           "and the mesh's scale.");
  if (g.closed && g.volume < 0)
    sum.warnings.push_back("The mesh is closed and its faces point inward (negative volume): normals point in and "
                           "every curvature sign is flipped. Invert the faces' orientation first (MeshLab: "
                           "Invert Faces Orientation).");
}

}  // namespace

Status RunNormalVectorVoting(const SurfaceGraph& g, const Params& p, std::vector<VertexResult>& res, Summary& sum,
                             const Progress& cb) {
  const auto t0 = Clock::now();
  res.clear();
  sum = Summary();
  DescribeInput(g, sum);
  const std::string refusal = ValidateRun(g, p);
  if (!refusal.empty()) return Refused(refusal);
  // The noise along the normals (noise_estimate.h): reported always, and automatic k's input.
  const NoiseEstimate noise = EstimateNoise(g, p.threads);
  sum.noiseOverEdge = noise.sigmaOverEdge;
  Params withK = p;
  if (p.autoK) withK.k = AutoK(sum.noiseOverEdge);
  sum.k = withK.k;
  sum.autoK = p.autoK;
  const Pass1Settings s = SettingsFor(g, withK, noise);
  if (!std::isfinite(s.radius) || !(s.radius > 0))
    return Refused("The neighbourhood radius is not a positive finite number for this mesh.");
  RecordSettings(g, p, s, sum);

  const int threads = ThreadCount(p.threads);
  std::vector<VertexResult> out;
  AssignOnHugePages(out, g.VertexCount());
  // Progress: pass 1 and each pass over the surface vertices get an equal share.
  const int share = 100 / (1 + CurvatureRounds(p));

  PassProgress voting(cb, g.VertexCount(), 0, share, "Normal vector voting: normals and classes");
  PassEnd end = VoteNormals(g, s, threads, voting, out);
  if (end != PassEnd::Done) return Unfinished(end);
  // On a clean mesh the sharp edges decide every class (sharp_edges.h): the ridge fits that would
  // thin the votes' band are skipped, since every class they set would be overwritten.
  const SharpEdgeRole sharp = SharpEdgeRoleFor(p, noise.noiseAngle);
  if (sharp != SharpEdgeRole::DecideAll) {
    PassProgress ridges(cb, g.VertexCount(), share, share, "Normal vector voting: crease ridges");
    end = ThinCreases(g, p, s, threads, ridges, out, sum.thinned);
    if (end != PassEnd::Done) return Unfinished(end);
  }
  ClassifyBySharpEdges(g, p, sharp, noise.noiseAngle, threads, out, sum.sharpEdgeChanged);
  sum.sharpEdges = sharp == SharpEdgeRole::DecideAll;
  sum.sharpEdgesAdded = sharp == SharpEdgeRole::AddFeatures || sharp == SharpEdgeRole::AddIsolated;
  sum.secondsPass1 = SecondsSince(t0);

  const auto t1 = Clock::now();
  end = FitSurfaceCurvature(g, p, s, threads, cb, share, share, out);
  if (end != PassEnd::Done) return Unfinished(end);
  end = CreaseStage(g, s, threads, cb, out);
  if (end != PassEnd::Done) return Unfinished(end);
  sum.secondsPass2 = SecondsSince(t1);

  Summarise(g, s, out, sum);
  res.swap(out);
  sum.secondsTotal = SecondsSince(t0);
  Status st;
  st.ok = true;
  return st;
}

}  // namespace nvv
