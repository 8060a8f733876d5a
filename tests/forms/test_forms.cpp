// The forms stage (method.md sections 1-6): invariants with explicit tolerances.
#include "io/read_surface.h"
#include "libquadmesh/forms/boundary_chords.h"
#include "libquadmesh/forms/cotan_repair.h"
#include "libquadmesh/forms/cut_integration.h"
#include "libquadmesh/forms/edge_forms.h"
#include "libquadmesh/forms/harmonic_basis.h"
#include "libquadmesh/forms/named_loops.h"
#include "libquadmesh/forms/remesh.h"
#include "libquadmesh/forms/symmetric_forms.h"
#include "libquadmesh/topology/applicability.h"
#include "libquadmesh/topology/internal/edge_incidence.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>
#include <Eigen/Dense>

#include <algorithm>
#include <map>

using namespace qm;

namespace {

Mesh mesh_of(const TriangleSoup& soup) {
  AnalyzedSurface s = analyze_topology(soup);
  require_supported(s);
  split_boundary_chords(s.soup);
  return to_surface_mesh(s.soup);
}

Mesh load_mesh(const std::string& path) { return mesh_of(io::read_surface(path).soup); }

/// One 1-to-4 midpoint subdivision.
TriangleSoup subdivide(const TriangleSoup& in) {
  TriangleSoup out;
  out.points = in.points;
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto found = midpoint.find(key);
    if (found != midpoint.end()) return found->second;
    out.points.push_back((in.points[a] + in.points[b]) / 2);
    return midpoint[key] = static_cast<int>(out.points.size()) - 1;
  };
  for (const Triangle& t : in.triangles) {
    const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
    out.triangles.push_back({t[0], ab, ca});
    out.triangles.push_back({ab, t[1], bc});
    out.triangles.push_back({ca, bc, t[2]});
    out.triangles.push_back({ab, bc, ca});
  }
  return out;
}

}  // namespace

TEST_CASE("doubling: counts, closedness, mirror-symmetric cotangent weights") {
  const Mesh s = load_mesh(test::shared_mesh("kitten-2holes.obj"));
  std::size_t boundary_vertices = 0;
  for (auto v : s.vertices()) boundary_vertices += s.is_border(v) ? 1 : 0;
  const DoubledSurface d = double_surface(s);
  CHECK(d.mesh.number_of_vertices() == 2 * s.number_of_vertices() - boundary_vertices);
  CHECK(d.mesh.number_of_faces() == 2 * s.number_of_faces());
  for (auto h : d.mesh.halfedges()) REQUIRE_FALSE(d.mesh.is_border(h));
  const long chi = static_cast<long>(d.mesh.number_of_vertices()) -
                   static_cast<long>(d.mesh.number_of_edges()) +
                   static_cast<long>(d.mesh.number_of_faces());
  CHECK(chi == 2 * -2);  // chi(D) = 2 chi(S)
  for (std::size_t v = 0; v < d.vertex_mirror.size(); ++v)
    CHECK(d.vertex_mirror[d.vertex_mirror[v]] == static_cast<int>(v));
  const Eigen::VectorXd w = cotan_weights(d.mesh);
  double worst = 0;
  for (Eigen::Index e = 0; e < w.size(); ++e)
    worst = std::max(worst, std::abs(w[e] - w[d.edge_mirror[e]]));
  CHECK(worst <= 1e-12 * w.cwiseAbs().maxCoeff());
}

TEST_CASE("boundary chords are split until none is left; topology is unchanged") {
  // a 3 x 3 grid of split squares: its corner triangles are ears (their inner edges are chords)
  TriangleSoup soup = test::grid(3);
  // one chord is also a CAD curve edge: it is split with its curve
  const EdgeIncidence inc = edge_incidence(soup);
  std::vector<char> on_boundary(soup.points.size(), 0);
  for (std::size_t e = 0; e < inc.edge_count(); ++e)
    if (inc.is_boundary(static_cast<int>(e))) on_boundary[inc.edges[e][0]] = on_boundary[inc.edges[e][1]] = 1;
  std::array<int, 2> chord{-1, -1};
  for (std::size_t e = 0; e < inc.edge_count() && chord[0] < 0; ++e)
    if (inc.valence(static_cast<int>(e)) == 2 && on_boundary[inc.edges[e][0]] && on_boundary[inc.edges[e][1]])
      chord = inc.edges[e];
  REQUIRE(chord[0] >= 0);
  soup.cad.edges.push_back({chord[0], chord[1], 5});
  const AnalyzedSurface before = analyze_topology(soup);
  const std::size_t splits = split_boundary_chords(soup);
  CHECK(splits > 0);
  CHECK(split_boundary_chords(soup) == 0);
  REQUIRE(soup.cad.edges.size() == 2);
  const CurveEdge first = soup.cad.edges[0], second = soup.cad.edges[1];
  CHECK(first.curve == 5);
  CHECK(second.curve == 5);
  CHECK(first.a == chord[0]);
  CHECK(first.b == second.a);
  CHECK(second.b == chord[1]);
  CHECK(soup.points[first.b] == (soup.points[chord[0]] + soup.points[chord[1]]) / 2);
  const AnalyzedSurface after = analyze_topology(soup);
  CHECK(after.report.euler_characteristic == before.report.euler_characteristic);
  CHECK(after.report.faces == before.report.faces + 2 * splits);
  CHECK(after.report.vertices == before.report.vertices + splits);
  CHECK(after.report.manifold());
  CHECK(after.report.orientation.consistent);
}

TEST_CASE("cotangent Laplacian rows sum to zero, and it is symmetric") {
  const DoubledSurface d = double_surface(load_mesh(test::shared_mesh("pig.off")));
  const SparseMatrix L = cotan_laplacian(d.mesh, cotan_weights(d.mesh));
  const Eigen::VectorXd rows = L * Eigen::VectorXd::Ones(L.cols());
  const double scale = Eigen::MatrixXd(L).cwiseAbs().maxCoeff();
  CHECK(rows.cwiseAbs().maxCoeff() <= 1e-12 * scale);
  CHECK((Eigen::MatrixXd(L) - Eigen::MatrixXd(L).transpose()).cwiseAbs().maxCoeff() <= 1e-14 * scale);
}

TEST_CASE("cohomology basis: 2G closed forms; harmonic forms closed and co-closed") {
  const DoubledSurface d = double_surface(load_mesh(test::shared_mesh("chipped-torus.obj")));
  const CohomologyBasis c = cohomology_basis(d.mesh);
  CHECK(c.forms.cols() == 2 * 2);  // g = 1, n = 1: G = 2
  CHECK(max_face_curl(d.mesh, c.forms) <= 1e-12);
  const HarmonicSolver solver(d.mesh, cotan_weights(d.mesh));
  const Eigen::MatrixXd omega = solver.harmonic(c.forms);
  CHECK(max_face_curl(d.mesh, omega) <= 1e-12);
  CHECK(solver.coclosedness(omega) <= 1e-10);
  CHECK(solver.coclosedness(c.forms) > 1e-3);  // the cohomology forms themselves are not harmonic
}

TEST_CASE("every shared open mesh: dimension, zero orders, boundary and symmetry residuals") {
  for (const test::ManifestEntry& m : test::manifest()) {
    if (!m.manifold || m.boundary_loops == 0 || m.faces > 100000) continue;
    CAPTURE(m.file);
    const SymmetricForms f = compute_symmetric_forms(load_mesh(test::shared_mesh(m.file)));
    const int G = 2 * m.genus + m.boundary_loops - 1;
    CHECK(f.doubled_genus == G);
    CHECK(f.symmetric.dimension() == G);
    CHECK(f.zeros.order_sum == -2 * m.euler_characteristic);
    CHECK(f.residuals.boundary_imaginary < 1e-8);
    CHECK(f.residuals.symmetry < 1e-8);
    CHECK(f.residuals.closedness < 1e-12);
    CHECK(f.residuals.coclosedness < 1e-9);
    // the invariance spectrum is G ones and G zeros: phi* is an involutive isometry
    for (Eigen::Index i = 0; i < f.symmetric.invariance_spectrum.size(); ++i) {
      const double s = f.symmetric.invariance_spectrum[i];
      CHECK(std::min(std::abs(s), std::abs(s - 1)) < 1e-8);
    }
  }
}

TEST_CASE("closed surfaces: the forms live on the surface itself") {
  const SymmetricForms f = compute_symmetric_forms(load_mesh(test::shared_mesh("kitten.off")));
  CHECK(f.doubled_genus == 1);
  CHECK(f.symmetric.dimension() == 1);
  CHECK(f.zeros.order_sum == 0);
  CHECK(f.zeros.flipped_count == 0);
  const SymmetricForms t = compute_symmetric_forms(mesh_of(test::torus(3.0, 1.0, 48, 24)));
  CHECK(t.doubled_genus == 1);
  CHECK(t.residuals.hodge_star_squared < 0.01);
}

TEST_CASE("the Hodge star residual shrinks under 1-to-4 subdivision") {
  const TriangleSoup soup = io::read_surface(test::shared_mesh("chipped-torus.obj")).soup;
  const double coarse = compute_symmetric_forms(mesh_of(soup)).residuals.hodge_star_squared;
  const double fine = compute_symmetric_forms(mesh_of(subdivide(soup))).residuals.hodge_star_squared;
  CAPTURE(coarse);
  CAPTURE(fine);
  CHECK(fine < 0.6 * coarse);
}

TEST_CASE("analytic annulus: |h| r is constant (h proportional to -i dz / z)") {
  const Mesh mesh = mesh_of(test::annulus(1.0, 2.0, 24, 160));
  const SymmetricForms f = compute_symmetric_forms(mesh);
  REQUIRE(f.symmetric.dimension() == 1);
  CHECK(f.zeros.order_sum == 0);
  CHECK(f.zeros.flipped_count == 0);
  const auto re = face_covectors(f.doubled.mesh, f.symmetric.real_part);
  const auto im = face_covectors(f.doubled.mesh, f.symmetric.imaginary_part);
  double lo = 1e300, hi = 0, sum = 0;
  int count = 0;
  for (auto face : mesh.faces()) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (auto v : mesh.vertices_around_face(mesh.halfedge(face)))
      c += Eigen::Vector3d(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()) / 3;
    const double r = c.head<2>().norm();
    if (r < 1.2 || r > 1.8) continue;
    const Eigen::Index i = static_cast<Eigen::Index>(face);
    const double magnitude = std::hypot(re[0].row(i).norm(), im[0].row(i).norm()) / std::sqrt(2.0);
    lo = std::min(lo, magnitude * r);
    hi = std::max(hi, magnitude * r);
    sum += magnitude * r;
    ++count;
    // real and imaginary covectors are orthogonal and of equal length (conformality)
    CHECK(std::abs(re[0].row(i).dot(im[0].row(i))) <= 0.02 * re[0].row(i).squaredNorm());
  }
  const double spread = (hi - lo) / (sum / count);
  CAPTURE(spread);
  CHECK(spread < 0.02);
  CHECK(f.residuals.hodge_star_squared < 1e-2);
}

TEST_CASE("integration on the cut surface: exact forms give back their potential") {
  const Mesh mesh = load_mesh(test::shared_mesh("kitten-2holes.obj"));
  Eigen::VectorXd f(static_cast<Eigen::Index>(mesh.number_of_vertices()));
  for (auto v : mesh.vertices()) f[static_cast<Eigen::Index>(v)] = mesh.point(v).x() - 2 * mesh.point(v).z();
  const Eigen::VectorXd df = exterior_derivative_0(mesh) * f;
  const Eigen::MatrixX3d values = integrate_on_cut_surface(mesh, df, mesh.number_of_faces());
  const double offset = values(0, 0) - f[face_corners(mesh, Mesh::Face_index(0))[0]];
  double worst = 0;
  for (auto face : mesh.faces()) {
    const auto corners = face_corners(mesh, face);
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, std::abs(values(static_cast<Eigen::Index>(face), k) - offset - f[corners[k]]));
  }
  CHECK(worst < 1e-9 * f.cwiseAbs().maxCoeff());
}

TEST_CASE("integration on the cut surface: a harmonic form jumps by its period across the cut") {
  // annulus: h ~ -i dz/z = d(theta) - i dr/r; the real part integrates to the angle
  // (a period around the hole), the imaginary part is exact (constant on each boundary)
  const Mesh mesh = mesh_of(test::annulus(1.0, 2.0, 6, 48));
  const SymmetricForms f = compute_symmetric_forms(mesh);
  const Eigen::MatrixX3d im = integrate_on_cut_surface(f.doubled.mesh, f.symmetric.real_part.col(0),
                                                       f.doubled.input_faces);
  // the values seen at one vertex differ by 0 or by the period, nothing else
  const std::size_t faces = f.doubled.input_faces;
  std::map<int, std::vector<double>> at_vertex;
  for (std::size_t face = 0; face < faces; ++face) {
    const auto corners = face_corners(f.doubled.mesh, Mesh::Face_index(static_cast<Mesh::size_type>(face)));
    for (int k = 0; k < 3; ++k) at_vertex[corners[k]].push_back(im(static_cast<Eigen::Index>(face), k));
  }
  double period = 0;
  for (const auto& [v, list] : at_vertex) {
    const auto [lo, hi] = std::minmax_element(list.begin(), list.end());
    period = std::max(period, *hi - *lo);
  }
  REQUIRE(period > 1e-6);
  for (const auto& [v, list] : at_vertex)
    for (double x : list) {
      const double jump = std::abs(x - list.front());
      CHECK(std::min(jump, std::abs(jump - period)) < 1e-9 * period);
    }
}

namespace {
/// Distance from p to the segment ab.
double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}
}  // namespace

TEST_CASE("--remesh cures poor triangulations: pig and hinge reach ||Lambda^2 + I|| <= 0.1") {
  for (const char* name : {"pig.off", "hinge.stl"}) {
    CAPTURE(name);
    const AnalyzedSurface before = analyze_topology(io::read_surface(test::shared_mesh(name)).soup);
    const double raw = compute_symmetric_forms(mesh_of(before.soup)).residuals.hodge_star_squared;
    CHECK(raw > 0.3);  // the documented poor starting point
    const AnalyzedSurface after = analyze_topology(remesh_isotropic(before.soup));
    CHECK(after.report.euler_characteristic == before.report.euler_characteristic);
    CHECK(after.report.boundary_loop_count() == before.report.boundary_loop_count());
    CHECK(after.report.genus == before.report.genus);
    CHECK(after.report.manifold());
    const SymmetricForms f = compute_symmetric_forms(mesh_of(after.soup));
    CHECK(f.residuals.hodge_star_squared <= 0.1);
    CHECK(f.zeros.order_sum == 2 * f.doubled_genus - 2);
  }
}

TEST_CASE("--remesh keeps the boundary polyline: old corners kept, new points on old segments") {
  const AnalyzedSurface before = analyze_topology(io::read_surface(test::shared_mesh("pig.off")).soup);
  const AnalyzedSurface after = analyze_topology(remesh_isotropic(before.soup));
  std::vector<std::pair<Vec3, Vec3>> segments;
  for (const auto& loop : before.report.boundary.loops)
    for (std::size_t i = 0; i < loop.size(); ++i)
      segments.push_back({before.soup.points[loop[i]], before.soup.points[loop[(i + 1) % loop.size()]]});
  const double scale = mean_edge_length(before.soup);
  for (const auto& loop : after.report.boundary.loops)
    for (int p : loop) {
      double best = 1e300;
      for (const auto& [a, b] : segments) best = std::min(best, segment_distance(after.soup.points[p], a, b));
      CHECK(best < 1e-9 * scale);
    }
  std::size_t kept = 0, corners = 0;
  for (const auto& loop : before.report.boundary.loops)
    for (int p : loop) {
      ++corners;
      for (const Vec3& q : after.soup.points)
        if ((q - before.soup.points[p]).norm() < 1e-12 * scale) {
          ++kept;
          break;
        }
    }
  CHECK(kept == corners);
}

TEST_CASE("named loops: n boundaries, n - 1 bridges, 2g independent handle loops") {
  for (const char* name : {"kitten-2holes.obj", "fertility-3holes.obj", "chipped-torus.obj", "flatmesh.off"}) {
    CAPTURE(name);
    const test::ManifestEntry* m = nullptr;
    for (const auto& e : test::manifest())
      if (e.file == name) m = &e;
    REQUIRE(m != nullptr);
    const Mesh s = load_mesh(test::shared_mesh(name));
    const NamedLoops loops = named_loops(s);
    CHECK(static_cast<int>(loops.boundaries.size()) == m->boundary_loops);
    CHECK(static_cast<int>(loops.bridges.size()) == m->boundary_loops - 1);
    CHECK(static_cast<int>(loops.handles.size()) == 2 * m->genus);
    auto adjacent = [&](int a, int b) {
      return s.halfedge(Mesh::Vertex_index(a), Mesh::Vertex_index(b)) != Mesh::null_halfedge();
    };
    for (const auto& loop : loops.handles)
      for (std::size_t i = 0; i < loop.size(); ++i) CHECK(adjacent(loop[i], loop[(i + 1) % loop.size()]));
    // the vertex-to-loop map numbers the boundaries as the list does, and holds
    // exactly the boundary vertices
    const std::vector<int> loop_of = boundary_loop_of_vertex(loops, s.number_of_vertices());
    std::size_t on_boundary = 0;
    for (std::size_t k = 0; k < loops.boundaries.size(); ++k)
      for (int v : loops.boundaries[k]) CHECK(loop_of[static_cast<std::size_t>(v)] == static_cast<int>(k));
    for (Mesh::Vertex_index v : s.vertices()) {
      CHECK((loop_of[v] >= 0) == s.is_border(v));
      on_boundary += loop_of[v] >= 0;
    }
    std::size_t listed = 0;
    for (const auto& loop : loops.boundaries) listed += loop.size();
    CHECK(on_boundary == listed);
    for (std::size_t k = 0; k < loops.bridges.size(); ++k) {
      const auto& path = loops.bridges[k];
      for (std::size_t i = 0; i + 1 < path.size(); ++i) CHECK(adjacent(path[i], path[i + 1]));
      const auto& b0 = loops.boundaries[0];
      const auto& bk = loops.boundaries[k + 1];
      CHECK(std::find(b0.begin(), b0.end(), path.front()) != b0.end());
      CHECK(std::find(bk.begin(), bk.end(), path.back()) != bk.end());
    }
    // the handle loops are independent cycles: their periods of the harmonic forms on
    // the double (S+ is embedded in D with the same vertex numbers) have rank 2g
    if (m->genus > 0) {
      const SymmetricForms f = compute_symmetric_forms(s);
      const Mesh& D = f.doubled.mesh;
      Eigen::MatrixXd periods(static_cast<Eigen::Index>(loops.handles.size()), f.harmonic.cols());
      for (std::size_t l = 0; l < loops.handles.size(); ++l) {
        Eigen::RowVectorXd sum = Eigen::RowVectorXd::Zero(f.harmonic.cols());
        const auto& loop = loops.handles[l];
        for (std::size_t i = 0; i < loop.size(); ++i) {
          const auto h = D.halfedge(Mesh::Vertex_index(loop[i]), Mesh::Vertex_index(loop[(i + 1) % loop.size()]));
          sum += along_sign(D, h) * f.harmonic.row(static_cast<Eigen::Index>(D.edge(h)));
        }
        periods.row(static_cast<Eigen::Index>(l)) = sum;
      }
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(periods);
      const auto& sv = svd.singularValues();
      CHECK(sv[sv.size() - 1] > 1e-3 * sv[0]);
    }
  }
}

namespace {
/// Real symplectic Gram-Schmidt: columns a_1..a_g, b_1..b_g with S^T A S = [[0, I], [-I, 0]]
/// for an invertible antisymmetric A.
Eigen::MatrixXd symplectic_basis(const Eigen::MatrixXd& A) {
  const Eigen::Index n = A.rows(), g = n / 2;
  std::vector<Eigen::VectorXd> rest;
  for (Eigen::Index i = 0; i < n; ++i) rest.push_back(Eigen::VectorXd::Unit(n, i));
  Eigen::MatrixXd S(n, n);
  for (Eigen::Index k = 0; k < g; ++k) {
    // the pair (u, w) with the largest pairing keeps the reduction well conditioned
    std::size_t iu = 0, iw = 1;
    double best = 0;
    for (std::size_t i = 0; i < rest.size(); ++i)
      for (std::size_t j = i + 1; j < rest.size(); ++j) {
        const double p = std::abs(rest[i].dot(A * rest[j]));
        if (p > best) best = p, iu = i, iw = j;
      }
    const Eigen::VectorXd a = rest[iu];
    const Eigen::VectorXd b = rest[iw] / a.dot(A * rest[iw]);
    rest.erase(rest.begin() + static_cast<long>(std::max(iu, iw)));
    rest.erase(rest.begin() + static_cast<long>(std::min(iu, iw)));
    for (Eigen::VectorXd& v : rest) v = v - v.dot(A * b) * a + v.dot(A * a) * b;
    S.col(k) = a;
    S.col(g + k) = b;
  }
  return S;
}
}  // namespace

TEST_CASE("closed genus 2: integral wedge pairing and a Riemann period matrix") {
  // the double of a pair of pants (a plate with two holes) is a closed genus-2 surface
  io::ReadOptions options;
  options.cad_mesh_size = 3.0;
  const DoubledSurface pants = double_surface(mesh_of(io::read_surface(test::example("plate-two-holes.geo"), options).soup));
  const SymmetricForms f = compute_symmetric_forms(pants.mesh);
  REQUIRE(f.doubled_genus == 2);
  const Eigen::MatrixXd& A = f.star.wedge;
  // the wedge of PL closed forms is topological: an integer, unimodular, antisymmetric matrix
  const Eigen::MatrixXd rounded = A.array().round().matrix();
  CHECK((A - rounded).cwiseAbs().maxCoeff() < 1e-8);
  CHECK(std::abs(std::abs(rounded.determinant()) - 1.0) < 1e-9);
  CHECK((A + A.transpose()).cwiseAbs().maxCoeff() < 1e-9);

  const Eigen::MatrixXd S = symplectic_basis(A);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(4, 4);
  J.topRightCorner(2, 2) = Eigen::MatrixXd::Identity(2, 2);
  J.bottomLeftCorner(2, 2) = -Eigen::MatrixXd::Identity(2, 2);
  CHECK((S.transpose() * A * S - J).cwiseAbs().maxCoeff() < 1e-9);

  // periods of the holomorphic basis h_j = omega(x_j) + i *omega(x_j) in canonical coordinates
  REQUIRE(f.symmetric.dimension() == 2);
  const Eigen::MatrixXd& X = f.symmetric.coefficients;
  const Eigen::MatrixXcd C = X.cast<std::complex<double>>() +
                             std::complex<double>(0, 1) * (f.star.lambda * X).cast<std::complex<double>>();
  const Eigen::MatrixXcd Q = S.inverse().cast<std::complex<double>>() * C;
  const Eigen::MatrixXcd Pa = Q.topRows(2), Pb = Q.bottomRows(2);
  const Eigen::MatrixXcd tau = Pb * Pa.inverse();
  CAPTURE(tau);
  CHECK((tau - tau.transpose()).norm() < 1e-8 * tau.norm());  // symmetric (Riemann's first relation)
  const Eigen::MatrixXd im = (tau.imag() + tau.imag().transpose()) / 2;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(im);
  CHECK(eig.eigenvalues().minCoeff() > 0);  // positive definite (the second relation)
}

TEST_CASE("repairing negative cotangent weights keeps the topology and improves the star") {
  const AnalyzedSurface before = analyze_topology(io::read_surface(test::shared_mesh("pig.off")).soup);
  Mesh mesh = to_surface_mesh(before.soup);
  const CotanRepairReport report = repair_cotan_weights(mesh);
  CHECK(report.negative_before == 184);  // pig.off as shipped
  CHECK(report.negative_after * 10 < report.negative_before);
  CHECK(report.boundary_splits > 0);  // obtuse angles opposite boundary edges: flips cannot help
  CHECK(mesh.is_valid(false));
  const TriangleSoup repaired = soup_of(mesh, before.soup);
  CHECK(repaired.point_labels[0] == before.soup.point_label(0));
  CHECK(repaired.point_labels.back() == -1);
  const AnalyzedSurface after = analyze_topology(repaired);
  CHECK(after.report.euler_characteristic == before.report.euler_characteristic);
  CHECK(after.report.boundary_loop_count() == before.report.boundary_loop_count());
  CHECK(after.report.manifold());
  const double raw = compute_symmetric_forms(mesh_of(before.soup)).residuals.hodge_star_squared;
  const SymmetricForms f = compute_symmetric_forms(mesh_of(repaired));
  CHECK(f.residuals.hodge_star_squared < 0.7 * raw);
  CHECK(f.zeros.order_sum == 10);
}
