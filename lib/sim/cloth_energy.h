// The total potential of a cloth model (membrane + bending + gravity + stitches + body
// contact + self-contact), its gradient and its Hessian over the free (unpinned) degrees of
// freedom, assembled into one sparsity pattern so the symbolic factorisation is reused. The
// pattern is fixed unless the model has self-contact: then it grows (never shrinks) to take in
// the vertex-triangle pairs that come into contact, and each growth needs a new analysis.
#pragma once

#include <vector>

#include <Eigen/SparseCore>

#include "sim/cloth_model.h"

namespace foldsketch {

using SparseMatrix = Eigen::SparseMatrix<double>;

struct EnergyTerms {
  double membrane = 0, bending = 0, gravity = 0, stitches = 0, contact = 0, self_contact = 0;
  double total() const { return membrane + bending + gravity + stitches + contact + self_contact; }
};

class ClothEnergy {
public:
  explicit ClothEnergy(const ClothModel& model);

  int free_count() const { return static_cast<int>(free_vertices_.size()); }
  // free_index()[v]: position of drape vertex v among the free vertices, -1 when pinned.
  const std::vector<int>& free_index() const { return free_index_; }
  const std::vector<int>& free_vertices() const { return free_vertices_; }

  // Energy [J] of drape x (#V by 3). gradient (size 3 * free_count) is filled when non-null,
  // hessian (fixed pattern, full symmetric storage) when non-null, with the membrane and the
  // bending Hessians of the given kinds, and body contact's exact (contact_kind Exact) or
  // without the curvature of the distance where it softens (any other kind; see the contact
  // term in the source). Element loops run in parallel (one share per thread).
  EnergyTerms evaluate(const MatrixX3d& x, VectorXd* gradient, SparseMatrix* hessian, HessianKind membrane_kind,
                       HessianKind bending_kind, HessianKind contact_kind) const;
  EnergyTerms evaluate(const MatrixX3d& x, VectorXd* gradient, SparseMatrix* hessian, HessianKind kind) const {
    return evaluate(x, gradient, hessian, kind, kind, kind);
  }

  // A zero matrix with the pattern every Hessian uses.
  const SparseMatrix& pattern() const { return pattern_; }

  // Makes the pattern hold every self-contact pair within reach of contact at drape x; call it
  // before evaluating a Hessian at x. Returns true when the pattern grew (Hessians assembled
  // before are then stale, and a factorisation needs a new analysis). Without self-contact it
  // does nothing.
  bool prepare(const MatrixX3d& x);

  // Lumped masses per free DOF (3 * free_count) [kg].
  const VectorXd& free_mass() const { return free_mass_; }

  // Gravity forces on the free DOFs [N]; with the model's gravity zero, empty.
  VectorXd gravity_force() const;

  // Add lambda * M to the diagonal of a matrix with this pattern.
  void add_mass(SparseMatrix& A, double lambda) const;
  // The rest-shape Laplacian L (the sum over triangles of A grad N_i . grad N_j over the
  // pattern triangle, dimensionless, positive semi-definite), acting on each coordinate:
  // add mu * L to a matrix with this pattern, or give L d for free-DOF displacements d.
  // With `weights` (one per triangle), each triangle's term scaled by its weight.
  void add_laplacian(SparseMatrix& A, double mu, const VectorXd* weights = nullptr) const;
  VectorXd laplacian_times(const VectorXd& d, const VectorXd* weights = nullptr) const;
  // Per triangle, the most compressive principal membrane stress at drape x, as a positive
  // number [N/m] (0 where the triangle is not compressed): the membrane's geometric stiffness
  // A B^T S B is at least minus this times the triangle's Laplacian term.
  VectorXd compressive_stress(const MatrixX3d& x) const;
  // The same L over the free vertices, one unknown per vertex (free_count square).
  SparseMatrix scalar_laplacian() const;

private:
  struct Block {   // where an element's (a, b) 3x3 block lives in the value array
    int base = -1; // value index of entry (0, 0); -1 when a or b is pinned
    int stride = 0;
  };
  Block block(int a, int b) const;  // free vertex indices
  void build_pattern();             // pattern_ and the element blocks from neighbours_
  std::vector<Block> blocks_for(const int* vertices, int count) const;
  template <int N>
  void scatter(const std::vector<Block>& blocks, const Eigen::Matrix<double, 3 * N, 3 * N>& H, double* values) const;

  const ClothModel& model_;
  std::vector<int> free_index_, free_vertices_;
  SparseMatrix pattern_;
  std::vector<std::vector<int>> neighbours_;  // per free vertex (block column): sorted block rows
  std::vector<std::vector<Block>> triangle_blocks_, hinge_blocks_, stitch_blocks_;
  std::vector<Block> diagonal_blocks_;  // per free vertex
  std::vector<Eigen::Matrix3d> laplacians_;  // per triangle: A grad N_i . grad N_j at rest
  VectorXd free_mass_;
  // Body contact "only where it acts": per free vertex, the last point where its body distance
  // was queried and that distance (NaN: none yet). Distance to a surface is 1-Lipschitz, so a
  // vertex within (distance - thickness) of that point is out of contact, exactly, and needs no
  // query. A cache of certificates, not of results: any (point, distance) pair stays true.
  // Each evaluation writes only its own vertices' entries (each vertex is in one thread's share).
  mutable std::vector<Eigen::Vector4d> contact_certificates_;
  // Self-contact: the drape at the last pattern search (prepare). The pattern then held every
  // pair closer than kPatternReach thicknesses; a pair's distance changes by at most twice the
  // largest vertex move, so while no vertex has moved more than (kPatternReach - 1) / 2
  // thicknesses since, every pair in contact now is in the pattern and the search is skipped.
  MatrixX3d prepared_at_;
  int thread_count_ = 1;  // threads per evaluation: the cores, fewer for small models
};

} // namespace foldsketch
