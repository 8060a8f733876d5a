#include "libquadmesh/quality/verdict.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace qm {

namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

double clamped(double value) { return std::clamp(value, -kVerdictHuge, kVerdictHuge); }

/// Verdict's test for a quad stored as a triangle: its last two points are equal.
bool collapsed(const QuadPoints& x) { return x[3] == x[2]; }

TrianglePoints first_three(const QuadPoints& x) { return {x[0], x[1], x[2]}; }

/// e_i = x_{i+1} - x_i (indices mod 4).
std::array<Vec3, 4> quad_edges(const QuadPoints& x) {
  return {x[1] - x[0], x[2] - x[1], x[3] - x[2], x[0] - x[3]};
}

/// Verdict's signed corner areas: corner i's cross product e_{i-1} x e_i dotted
/// with the unit normal of the principal axes (e0 - e2) x (e1 - e3), which is
/// that of the diagonals; all zero when that normal vanishes.
std::array<double, 4> signed_corner_areas(const QuadPoints& x) {
  const std::array<Vec3, 4> e = quad_edges(x);
  Vec3 normal = (e[0] - e[2]).cross(e[1] - e[3]);
  if (const double length = normal.norm(); length != 0) normal /= length;
  std::array<double, 4> areas{};
  for (std::size_t i = 0; i < 4; ++i) areas[i] = normal.dot(e[(i + 3) % 4].cross(e[i]));
  return areas;
}

/// The four corner angles of a quad (radians, in [0, pi], from acos as Verdict
/// takes them); false when an edge is shorter than kVerdictTiny.
bool corner_angles(const QuadPoints& x, std::array<double, 4>& angles) {
  const std::array<Vec3, 4> e = quad_edges(x);
  std::array<double, 4> length{};
  for (std::size_t i = 0; i < 4; ++i) {
    length[i] = e[i].norm();
    if (length[i] <= kVerdictTiny) return false;
  }
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t next = (i + 1) % 4;
    angles[i] = std::acos(std::clamp(-e[i].dot(e[next]) / (length[i] * length[next]), -1.0, 1.0));
  }
  return true;
}

/// The principal axes x1 + x2 - x3 - x0 and x2 + x3 - x0 - x1.
std::array<Vec3, 2> principal_axes(const QuadPoints& x) {
  return {x[1] + x[2] - x[3] - x[0], x[2] + x[3] - x[0] - x[1]};
}

/// Verdict's VerdictVector::interior_angle: the angle between a and b, degrees.
double interior_angle_deg(const Vec3& a, const Vec3& b) {
  const double cosine = a.dot(b) / (a.norm() * b.norm());
  return std::acos(std::clamp(cosine, -1.0, 1.0)) * kDegrees;
}

/// Verdict's triangle angle opposite the shortest (largest: false) side; 0 with a zero side.
double triangle_extreme_angle(const TrianglePoints& x, bool smallest) {
  const Vec3 side0 = x[1] - x[0], side1 = x[2] - x[1], side2 = x[2] - x[0];
  const double l0 = side0.squaredNorm(), l1 = side1.squaredNorm(), l2 = side2.squaredNorm();
  if (l0 == 0.0 || l1 == 0.0 || l2 == 0.0) return 0.0;
  const auto before = [smallest](double a, double b) { return smallest ? a < b : a > b; };
  int side = 0;
  double chosen = l0;
  if (before(l1, chosen)) side = 1, chosen = l1;
  if (before(l2, chosen)) side = 2;
  double angle = 0;
  if (side == 0)
    angle = interior_angle_deg(side2, side1);
  else if (side == 1)
    angle = interior_angle_deg(side0, side2);
  else
    angle = interior_angle_deg(side0, -side1);
  return clamped(angle);
}

}  // namespace

double quad_scaled_jacobian(const QuadPoints& x) {
  if (collapsed(x)) return triangle_scaled_jacobian(first_three(x));
  const std::array<double, 4> areas = signed_corner_areas(x);
  const std::array<Vec3, 4> e = quad_edges(x);
  std::array<double, 4> length{};
  for (std::size_t i = 0; i < 4; ++i) {
    length[i] = e[i].norm();
    if (length[i] < kVerdictTiny) return 0.0;
  }
  double worst = kVerdictHuge;
  for (std::size_t i = 0; i < 4; ++i) worst = std::min(worst, areas[i] / (length[i] * length[(i + 3) % 4]));
  return clamped(worst);
}

double quad_minimum_angle(const QuadPoints& x) {
  if (collapsed(x)) return triangle_minimum_angle(first_three(x));
  std::array<double, 4> angles{};
  if (!corner_angles(x, angles)) return 360.0;
  return clamped(*std::min_element(angles.begin(), angles.end()) * kDegrees);
}

double quad_maximum_angle(const QuadPoints& x) {
  if (collapsed(x)) return triangle_maximum_angle(first_three(x));
  std::array<double, 4> angles{};
  if (!corner_angles(x, angles)) return 0.0;
  double largest = *std::max_element(angles.begin(), angles.end()) * kDegrees;
  // a re-entrant corner: acos gave the angle outside the quad
  const std::array<double, 4> areas = signed_corner_areas(x);
  if (std::any_of(areas.begin(), areas.end(), [](double a) { return a < 0; })) largest = 360 - largest;
  return clamped(largest);
}

double quad_warpage(const QuadPoints& x) {
  const std::array<Vec3, 4> e = quad_edges(x);
  std::array<Vec3, 4> normals;
  for (std::size_t i = 0; i < 4; ++i) {
    normals[i] = e[(i + 3) % 4].cross(e[i]);
    const double length = normals[i].norm();
    if (length < kVerdictTiny) return kVerdictTiny;
    normals[i] /= length;
  }
  return clamped(std::pow(std::min(normals[0].dot(normals[2]), normals[1].dot(normals[3])), 3));
}

double quad_aspect_ratio(const QuadPoints& x) {
  const std::array<Vec3, 4> e = quad_edges(x);
  const double a = e[0].norm(), b = e[1].norm(), c = e[2].norm(), d = e[3].norm();
  const double longest = std::max({a, b, c, d});
  const double denominator = e[0].cross(e[1]).norm() + e[2].cross(e[3]).norm();
  if (denominator < kVerdictTiny) return kVerdictHuge;
  return clamped(0.5 * longest * (a + b + c + d) / denominator);
}

double quad_skew(const QuadPoints& x) {
  std::array<Vec3, 2> axes = principal_axes(x);
  for (Vec3& axis : axes) {
    const double length = axis.norm();
    if (length < kVerdictTiny) return 0.0;
    axis /= length;
  }
  return std::min(std::abs(axes[0].dot(axes[1])), kVerdictHuge);
}

double quad_taper(const QuadPoints& x) {
  const std::array<Vec3, 2> axes = principal_axes(x);
  const Vec3 cross_derivative = x[0] + x[2] - x[1] - x[3];
  const double shorter = std::min(axes[0].norm(), axes[1].norm());
  if (shorter < kVerdictTiny) return kVerdictHuge;
  return std::min(cross_derivative.norm() / shorter, kVerdictHuge);
}

QuadVerdict quad_verdict(const QuadPoints& x) {
  QuadVerdict v;
  v.scaled_jacobian = quad_scaled_jacobian(x);
  v.minimum_angle = quad_minimum_angle(x);
  v.maximum_angle = quad_maximum_angle(x);
  v.warpage = quad_warpage(x);
  v.aspect_ratio = quad_aspect_ratio(x);
  v.skew = quad_skew(x);
  v.taper = quad_taper(x);
  return v;
}

double triangle_scaled_jacobian(const TrianglePoints& x) {
  const Vec3 e0 = x[1] - x[0], e1 = x[2] - x[0], e2 = x[2] - x[1];
  const double l0 = e0.norm(), l1 = e1.norm(), l2 = e2.norm();
  const double product = std::max({l0 * l1, l1 * l2, l0 * l2});
  if (product < kVerdictTiny) return 0.0;
  const double jacobian = (e1 - e0).cross(e2 - e0).norm();
  return clamped(jacobian * (2.0 / std::sqrt(3.0)) / product);
}

double triangle_minimum_angle(const TrianglePoints& x) { return triangle_extreme_angle(x, true); }

double triangle_maximum_angle(const TrianglePoints& x) { return triangle_extreme_angle(x, false); }

double triangle_aspect_ratio(const TrianglePoints& x) {
  const Vec3 a = x[1] - x[0], b = x[2] - x[1], c = x[0] - x[2];
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double denominator = a.cross(b).norm();
  if (denominator < kVerdictTiny) return kVerdictHuge;
  return clamped(std::sqrt(3.0) / 6.0 * std::max({la, lb, lc}) * (la + lb + lc) / denominator);
}

TriangleVerdict triangle_verdict(const TrianglePoints& x) {
  TriangleVerdict v;
  v.scaled_jacobian = triangle_scaled_jacobian(x);
  v.minimum_angle = triangle_minimum_angle(x);
  v.maximum_angle = triangle_maximum_angle(x);
  v.aspect_ratio = triangle_aspect_ratio(x);
  return v;
}

}  // namespace qm
