// An orthonormal tangent basis (e1, e2) for a unit normal N, with e1 x e2 = N.
#ifndef NVV_CORE_TANGENT_FRAME_H
#define NVV_CORE_TANGENT_FRAME_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace nvv {

struct TangentFrame {
  Eigen::Vector3d e1, e2, n;
  explicit TangentFrame(const Eigen::Vector3d& normal) : n(normal) {
    // Cross with the coordinate axis least aligned with N: never near-parallel.
    int axis = 0;
    if (std::abs(n.y()) < std::abs(n(axis))) axis = 1;
    if (std::abs(n.z()) < std::abs(n(axis))) axis = 2;
    const Eigen::Vector3d a = Eigen::Vector3d::Unit(axis);
    e1 = n.cross(a).normalized();
    e2 = n.cross(e1);
  }
  Eigen::Vector2d ToPlane(const Eigen::Vector3d& d) const { return {e1.dot(d), e2.dot(d)}; }
  Eigen::Vector3d FromPlane(const Eigen::Vector2d& t) const { return t.x() * e1 + t.y() * e2; }
};

}  // namespace nvv

#endif
