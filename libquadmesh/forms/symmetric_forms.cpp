#include "libquadmesh/forms/symmetric_forms.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/forms/harmonic_basis.h"

#include <chrono>

namespace qm {

namespace {
class StageClock {
 public:
  explicit StageClock(std::vector<std::pair<std::string, double>>& out) : out_(out) {}
  void lap(const std::string& stage) {
    const auto now = std::chrono::steady_clock::now();
    out_.emplace_back(stage, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }

 private:
  std::vector<std::pair<std::string, double>>& out_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

bool has_border(const Mesh& m) {
  for (Mesh::Halfedge_index h : m.halfedges())
    if (m.is_border(h)) return true;
  return false;
}
}  // namespace

SymmetricForms compute_symmetric_forms(const Mesh& surface) {
  SymmetricForms r;
  StageClock clock(r.timings);
  const bool closed = !has_border(surface);
  r.doubled = closed ? identity_double(surface) : double_surface(surface);
  clock.lap("doubling");
  const Mesh& D = r.doubled.mesh;
  r.weights = cotan_weights(D);
  const HarmonicSolver solver(D, r.weights);
  clock.lap("factorization");
  r.cohomology = cohomology_basis(D);
  r.doubled_genus = static_cast<int>(r.cohomology.generator_edges.size() / 2);
  if (r.doubled_genus < 1)
    throw Error(ErrorCode::unsupported, "the doubled surface has genus 0: no holomorphic 1-form");
  clock.lap("cohomology");
  r.harmonic = solver.harmonic(r.cohomology.forms);
  clock.lap("harmonic");
  r.star = galerkin_hodge_star(D, r.harmonic);
  clock.lap("hodge_star");
  r.symmetric = symmetric_basis(r.doubled, r.harmonic, r.star, closed);
  clock.lap("symmetric_basis");
  r.zeros = form_zeros(r.doubled, r.symmetric.real_part.col(0), r.symmetric.imaginary_part.col(0));
  clock.lap("zeros");
  r.residuals.closedness = max_face_curl(D, r.harmonic);
  r.residuals.coclosedness = solver.coclosedness(r.harmonic);
  r.residuals.hodge_star_squared = r.star.squared_residual;
  r.residuals.boundary_imaginary = closed ? 0.0 : boundary_imaginary_residual(r.doubled, r.symmetric);
  r.residuals.symmetry = closed ? 0.0 : symmetry_residual(r.doubled, r.symmetric);
  clock.lap("residuals");
  return r;
}

}  // namespace qm
