#include "libquadmesh/cones/smooth_cross_field.h"

#include "libquadmesh/cones/internal/face_geometry.h"
#include "libquadmesh/core/error.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>

namespace qm {

namespace {

using Complex = std::complex<double>;

/// The direction of the directed edge a->b in triangle f's local frame (f holds
/// a and b).
Complex edge_direction(const CornerValues& corners, const Triangle& t, int a, int b) {
  int ia = 0, ib = 0;
  for (int k = 0; k < 3; ++k) {
    if (t[k] == a) ia = k;
    if (t[k] == b) ib = k;
  }
  return corners[static_cast<std::size_t>(ib)] - corners[static_cast<std::size_t>(ia)];
}

/// e^(4 i t): the fourth power of the turn from f's frame to g's across the edge
/// a->b that both hold.
Complex transport(const std::vector<CornerValues>& frames, const TriangleSoup& soup, int f, int g, int a, int b) {
  const auto fs = static_cast<std::size_t>(f), gs = static_cast<std::size_t>(g);
  const Complex in_f = edge_direction(frames[fs], soup.triangles[fs], a, b);
  const Complex in_g = edge_direction(frames[gs], soup.triangles[gs], a, b);
  const Complex turn = in_g / in_f;
  return std::pow(turn / std::abs(turn), 4);
}

double face_area(const CornerValues& c) { return 0.5 * std::abs(image_area2(c)); }

/// Holds the crosses of the triangles round each boundary vertex whose quad count
/// the field might not take by itself (CrossFieldOptions::boundary_quads): from
/// the boundary edge leaving v to the one arriving (counter-clockwise, angle a
/// apart), the cross turns by a - q pi/2 against the surface, in equal steps from
/// one triangle to the next (m triangles: m + 1 steps, the first and the last into
/// the crosses held along the two edges beyond). A triangle round two such
/// vertices keeps the first one's.
void hold_corner_turns(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                       const std::vector<CornerValues>& frames, const CrossFieldOptions& options,
                       SmoothCrossField& out) {
  std::vector<char> turned(soup.triangles.size(), 0);
  for (std::size_t v = 0; v < options.boundary_quads.size() && v < soup.points.size(); ++v) {
    if (!adjacency.boundary_vertex[v] || adjacency.vertex_faces[v].empty()) continue;
    const VertexRing ring = vertex_ring(soup, adjacency, static_cast<int>(v));
    const std::vector<double> angles = ring_angles(soup, ring, static_cast<int>(v));
    double angle = 0;
    for (double a : angles) angle += a;
    const int quads = options.boundary_quads[v];
    const double turn = angle - quads * quarter_turn;
    const bool nearest = quads == static_cast<int>(std::lround(angle / quarter_turn));
    if (nearest && std::abs(turn) < quarter_turn / 2 - options.corner_hold_margin) continue;
    const double steps = static_cast<double>(ring.faces.size() + 1);
    double from_start = 0;  // the angle round v of the edge v -> neighbours[k]
    for (std::size_t k = 0; k < ring.faces.size(); ++k) {
      const auto f = static_cast<std::size_t>(ring.faces[k]);
      const double edge_angle = from_start;
      from_start += angles[k];
      if (turned[f]) continue;
      turned[f] = 1;
      // the cross at turn (k + 1) / steps from the leaving edge's, in f's frame
      // through the edge v -> neighbours[k], edge_angle round v from that edge
      const Complex edge = edge_direction(frames[f], soup.triangles[f], static_cast<int>(v), ring.neighbours[k]);
      const double cross = turn * static_cast<double>(k + 1) / steps - edge_angle;
      out.psi[f] = std::pow(edge / std::abs(edge) * std::polar(1.0, cross), 4);
      out.held[f] = 1;
    }
  }
}

}  // namespace

SmoothCrossField smooth_cross_field(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                    const CrossFieldOptions& options) {
  const std::size_t faces = soup.triangles.size();
  std::vector<CornerValues> frames(faces);
  for (std::size_t f = 0; f < faces; ++f) frames[f] = local_corners(soup, f);

  SmoothCrossField out;
  out.psi.assign(faces, Complex(0, 0));
  out.held.assign(faces, 0);
  // the boundary's crosses: along the longest boundary edge of each triangle
  std::vector<double> held_length(faces, 0);
  for (std::size_t f = 0; f < faces; ++f) {
    const Triangle& t = soup.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (adjacency.find(b, a).face >= 0) continue;
      const Complex d = frames[f][static_cast<std::size_t>((k + 1) % 3)] - frames[f][static_cast<std::size_t>(k)];
      if (std::abs(d) <= held_length[f]) continue;
      held_length[f] = std::abs(d);
      out.held[f] = 1;
      out.psi[f] = std::pow(d / std::abs(d), 4);
    }
  }
  if (std::none_of(out.held.begin(), out.held.end(), [](char h) { return h != 0; }))
    throw Error(ErrorCode::unsupported, "the cross field needs a boundary to align to");
  hold_corner_turns(soup, adjacency, frames, options, out);

  // the free triangles' unknowns, and E's Hermitian matrix on them
  std::vector<int> unknown(faces, -1);
  int n = 0;
  for (std::size_t f = 0; f < faces; ++f)
    if (!out.held[f]) unknown[f] = n++;
  std::vector<Eigen::Triplet<Complex>> entries;
  Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(n);
  for (std::size_t f = 0; f < faces; ++f) {
    const Triangle& t = soup.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const int g = adjacency.find(b, a).face;
      if (g < 0 || static_cast<std::size_t>(g) < f) continue;  // each inner edge once
      const auto gs = static_cast<std::size_t>(g);
      const double length2 = std::norm(frames[f][static_cast<std::size_t>((k + 1) % 3)] - frames[f][static_cast<std::size_t>(k)]);
      const double w = length2 / std::max(face_area(frames[f]) + face_area(frames[gs]), 1e-300);
      const Complex rho = transport(frames, soup, static_cast<int>(f), g, a, b);
      // w |psi_g - rho psi_f|^2: rows of f and g
      const int uf = unknown[f], ug = unknown[gs];
      if (uf >= 0) entries.emplace_back(uf, uf, w);
      if (ug >= 0) entries.emplace_back(ug, ug, w);
      if (uf >= 0 && ug >= 0) {
        entries.emplace_back(ug, uf, -w * rho);
        entries.emplace_back(uf, ug, -w * std::conj(rho));
      } else if (uf >= 0 && ug < 0) {
        rhs[uf] += w * std::conj(rho) * out.psi[gs];
      } else if (ug >= 0 && uf < 0) {
        rhs[ug] += w * rho * out.psi[f];
      }
    }
  }
  if (n > 0) {
    Eigen::SparseMatrix<Complex> a(n, n);
    a.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<Complex>> smoothest(a);
    if (smoothest.info() != Eigen::Success)
      throw Error(ErrorCode::solver, "the cross field's system could not be factored");
    Eigen::VectorXcd x = smoothest.solve(rhs);
    // the crosses made unit and diffused over `length`, in turns: the linear
    // minimizer lets |psi| sag and merges singularities (a disk's four into one
    // of index 1 at its centre); each diffusion step spreads them at the scale
    // of `length` (Merriman-Bence-Osher, as for Ginzburg-Landau fields)
    if (options.diffusion_steps > 0) {
      const double tau = options.length * options.length;
      Eigen::SparseMatrix<Complex> heat = tau * a;
      Eigen::VectorXd mass(n);
      for (std::size_t f = 0; f < faces; ++f)
        if (unknown[f] >= 0) mass[unknown[f]] = face_area(frames[f]);
      for (int i = 0; i < n; ++i) heat.coeffRef(i, i) += mass[i];
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<Complex>> diffusion(heat);
      if (diffusion.info() != Eigen::Success)
        throw Error(ErrorCode::solver, "the cross field's diffusion could not be factored");
      for (int step = 0; step < options.diffusion_steps; ++step) {
        Eigen::VectorXcd b = tau * rhs;
        for (int i = 0; i < n; ++i) {
          const double r = std::abs(x[i]);
          if (r > 0) b[i] += mass[i] * x[i] / r;
        }
        x = diffusion.solve(b);
      }
    }
    for (std::size_t f = 0; f < faces; ++f)
      if (unknown[f] >= 0) out.psi[f] = x[unknown[f]];
  }

  // indices at inner vertices: the jumps around the vertex and 4 x its defect
  out.index.assign(soup.points.size(), 0);
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    if (adjacency.boundary_vertex[v] || adjacency.vertex_faces[v].empty()) continue;
    const VertexRing ring = vertex_ring(soup, adjacency, static_cast<int>(v));
    const std::vector<double> angles = ring_angles(soup, ring, static_cast<int>(v));
    double defect = 2 * M_PI;
    for (double angle : angles) defect -= angle;
    double jumps = 0;
    const std::size_t k = ring.faces.size();
    for (std::size_t i = 0; i < k; ++i) {
      // from faces[i - 1] into faces[i] across the edge v->neighbours[i]
      const int f = ring.faces[(i + k - 1) % k], g = ring.faces[i];
      const Complex rho = transport(frames, soup, f, g, static_cast<int>(v), ring.neighbours[i]);
      jumps += std::arg(out.psi[static_cast<std::size_t>(g)] / (rho * out.psi[static_cast<std::size_t>(f)]));
    }
    out.index[v] = static_cast<int>(std::lround((jumps + 4 * defect) / (2 * M_PI)));
  }
  return out;
}

std::vector<Cone> field_singularities(const SmoothCrossField& field) {
  std::vector<Cone> cones;
  for (std::size_t v = 0; v < field.index.size(); ++v)
    if (field.index[v] != 0) cones.push_back({static_cast<int>(v), 4 - field.index[v]});
  return cones;
}

}  // namespace qm
