#include "params.h"

#include <cstdio>

namespace nvv {

namespace {

std::string Number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

}  // namespace

// Every range is limits.h's, so these messages quote what the dialog and --help offer.
std::string ValidateParams(const Params& p) {
  auto bad = [](double x) { return !std::isfinite(x); };
  if (bad(p.k) || p.k < limits::kMinK || p.k > limits::kMaxK)
    return "Neighbourhood size k must be between " + Number(limits::kMinK) + " and " + Number(limits::kMaxK) +
           " mean edge lengths (got " + Number(p.k) + ").";
  if (bad(p.absoluteRadius) || p.absoluteRadius < 0.0 || p.absoluteRadius > limits::kMaxAbsoluteRadius)
    return "The absolute radius must be 0 (use k) or a positive number up to " + Number(limits::kMaxAbsoluteRadius) +
           " (got " + Number(p.absoluteRadius) + ").";
  if (bad(p.creaseAngleDeg) || p.creaseAngleDeg < limits::kMinAngleDeg || p.creaseAngleDeg > limits::kMaxAngleDeg)
    return "The crease angle must be between " + Number(limits::kMinAngleDeg) + " and " +
           Number(limits::kMaxAngleDeg) + " degrees (got " + Number(p.creaseAngleDeg) + ").";
  if (bad(p.sharpEdgeAngleDeg) || p.sharpEdgeAngleDeg < 0 || p.sharpEdgeAngleDeg > limits::kMaxAngleDeg)
    return "The sharp edge angle must be 0 (off) or up to " + Number(limits::kMaxAngleDeg) + " degrees (got " +
           Number(p.sharpEdgeAngleDeg) + ").";
  if (bad(p.cornerAngleDeg) || p.cornerAngleDeg < limits::kMinAngleDeg || p.cornerAngleDeg > limits::kMaxAngleDeg)
    return "The corner angle must be between " + Number(limits::kMinAngleDeg) + " and " +
           Number(limits::kMaxAngleDeg) + " degrees (got " + Number(p.cornerAngleDeg) + ").";
  if (bad(p.sigmaFraction) || p.sigmaFraction < 0.01 || p.sigmaFraction > 100.0)
    return "The weight fall-off (sigma / radius) must be between 0.01 and 100 (got " + Number(p.sigmaFraction) + ").";
  if (p.maxNeighbourhood < 0 || p.maxNeighbourhood > limits::kMaxNeighbourhoodCap)
    return "The neighbourhood cap must be 0 (automatic) or a number of vertices up to " +
           std::to_string(limits::kMaxNeighbourhoodCap) + " (got " + std::to_string(p.maxNeighbourhood) + ").";
  if (p.threads < 0 || p.threads > 4096)
    return "The thread count must be 0 (all cores) or between 1 and 4096 (got " + std::to_string(p.threads) + ").";
  if (p.fitRounds < limits::kMinFitRounds || p.fitRounds > limits::kMaxFitRounds)
    return "The number of fit rounds must be between " + std::to_string(limits::kMinFitRounds) + " and " +
           std::to_string(limits::kMaxFitRounds) + " (got " + std::to_string(p.fitRounds) + ").";
  const int fit = static_cast<int>(p.fit);
  if (fit < 0 || fit > 2) return "Unknown curvature fit.";
  const int rule = static_cast<int>(p.classRule);
  if (rule < 0 || rule > 1) return "Unknown classification rule.";
  return std::string();
}

}  // namespace nvv
