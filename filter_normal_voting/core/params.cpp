#include "params.h"

namespace nvv {

std::string ValidateParams(const Params& p) {
  auto bad = [](double x) { return !std::isfinite(x); };
  if (bad(p.k) || p.k <= 0.0 || p.k > 50.0)
    return "Neighbourhood size k must be a number in (0, 50] mean edge lengths (got " +
           std::to_string(p.k) + ").";
  if (bad(p.absoluteRadius) || p.absoluteRadius < 0.0)
    return "The absolute radius must be 0 (use k) or a positive number.";
  if (bad(p.creaseAngleDeg) || p.creaseAngleDeg < 1.0 || p.creaseAngleDeg > 89.0)
    return "The crease angle must be between 1 and 89 degrees (got " +
           std::to_string(p.creaseAngleDeg) + ").";
  if (bad(p.cornerAngleDeg) || p.cornerAngleDeg < 1.0 || p.cornerAngleDeg > 89.0)
    return "The corner angle must be between 1 and 89 degrees (got " +
           std::to_string(p.cornerAngleDeg) + ").";
  if (bad(p.sigmaFraction) || p.sigmaFraction < 0.01 || p.sigmaFraction > 100.0)
    return "The weight fall-off (sigma / radius) must be in [0.01, 100].";
  if (p.maxNeighbourhood != 0 && (p.maxNeighbourhood < 16 || p.maxNeighbourhood > tuning::kMaxCap))
    return "The neighbourhood cap must be 0 (automatic) or between 16 and 10,000,000 vertices.";
  if (p.threads < 0 || p.threads > 4096) return "The thread count must be 0 (all) or positive.";
  if (p.fitRounds < 1 || p.fitRounds > 4) return "The number of fit rounds must be between 1 and 4.";
  const int fit = static_cast<int>(p.fit);
  if (fit < 0 || fit > 2) return "Unknown curvature fit.";
  const int rule = static_cast<int>(p.classRule);
  if (rule < 0 || rule > 1) return "Unknown classification rule.";
  return std::string();
}

}  // namespace nvv
