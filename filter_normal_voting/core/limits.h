// The ranges of the user's parameters, written once: the parameter table
// (filter/filter_options.cpp) offers them to the dialog, --help, scripts and PyMeshLab, and
// ValidateParams (params.h) checks them with the same numbers in its messages.
#ifndef NVV_CORE_LIMITS_H
#define NVV_CORE_LIMITS_H

namespace nvv {
namespace limits {

constexpr double kMinK = 0.1, kMaxK = 50.0;                  // neighbourhood size, in l_ave
constexpr double kMaxAbsoluteRadius = 1e30;                  // 0 = use k
constexpr double kMinAngleDeg = 1.0, kMaxAngleDeg = 89.0;    // crease and corner angles
constexpr int kMinFitRounds = 1, kMaxFitRounds = 4;
constexpr int kMaxNeighbourhoodCap = 10000000;               // 0 = automatic
constexpr double kMaxClampPercentile = 49.0;

}  // namespace limits
}  // namespace nvv

#endif
