#pragma once
/// \file
/// \brief A block tridiagonal linear system with fixed-size square blocks, solved in O(n) by block LU
///        without pivoting between blocks (block Thomas), partial pivoting inside each diagonal block.

#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/StdVector>

namespace cable_dynamics {

/// Rows i = 0 .. n-1: lower(i) x_{i-1} + diagonal(i) x_i + upper(i) x_{i+1} = rhs_i (lower(0) and
/// upper(n-1) are unused). All storage is sized by resize(); solve() does not allocate.
template <int B>
class BlockTridiagonal {
 public:
  using Block = Eigen::Matrix<double, B, B>;
  using Vector = Eigen::Matrix<double, B, 1>;

  void resize(int n) {
    n_ = n;
    lower_.assign(n, Block::Zero());
    diagonal_.assign(n, Block::Zero());
    upper_.assign(n, Block::Zero());
    eliminated_.assign(n, Block::Zero());
    factors_.resize(n);
    forward_.resize(B, n);
  }
  int size() const { return n_; }
  Block& lower(int i) { return lower_[i]; }
  Block& diagonal(int i) { return diagonal_[i]; }
  Block& upper(int i) { return upper_[i]; }

  /// Solves in place: `x` (B x n) holds the right-hand sides on entry, the solution on return. Returns
  /// false when a pivot block is singular (or not finite). Destroys the diagonal blocks' values.
  bool solve(Eigen::Matrix<double, B, Eigen::Dynamic>& x) {
    // Forward: G_i = D_i - L_i E_{i-1}, g_i = G_i^-1 (r_i - L_i g_{i-1}), E_i = G_i^-1 U_i.
    for (int i = 0; i < n_; ++i) {
      Vector r = x.col(i);
      if (i > 0) {
        diagonal_[i].noalias() -= lower_[i] * eliminated_[i - 1];
        r.noalias() -= lower_[i] * forward_.col(i - 1);
      }
      factors_[i].compute(diagonal_[i]);
      const double pivot = factors_[i].matrixLU().diagonal().cwiseAbs().minCoeff();
      const double largest = factors_[i].matrixLU().diagonal().cwiseAbs().maxCoeff();
      if (!(pivot > 1e-300) || !(pivot > 1e-15 * largest)) return false;
      forward_.col(i) = factors_[i].solve(r);
      if (i + 1 < n_) eliminated_[i] = factors_[i].solve(upper_[i]);
    }
    // Backward: x_{n-1} = g_{n-1}, x_i = g_i - E_i x_{i+1}.
    x.col(n_ - 1) = forward_.col(n_ - 1);
    for (int i = n_ - 2; i >= 0; --i) x.col(i) = forward_.col(i) - eliminated_[i] * x.col(i + 1);
    return x.allFinite();
  }

 private:
  int n_ = 0;
  std::vector<Block, Eigen::aligned_allocator<Block>> lower_, diagonal_, upper_, eliminated_;
  std::vector<Eigen::PartialPivLU<Block>, Eigen::aligned_allocator<Eigen::PartialPivLU<Block>>> factors_;
  Eigen::Matrix<double, B, Eigen::Dynamic> forward_;
};

}  // namespace cable_dynamics
