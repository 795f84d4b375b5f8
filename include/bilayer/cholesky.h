#ifndef bilayer_cholesky_h
#define bilayer_cholesky_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>

namespace bilayer
{
  /**
   * Sparse Cholesky factorisation A = L L^T of a symmetric positive
   * definite matrix by CHOLMOD (SuiteSparse, supernodal, with its fill-
   * reducing ordering). The subproblem matrices are symmetric positive
   * definite (the constrained rows keep a positive diagonal), and a
   * Cholesky solve costs about half of an LU solve with the same ordering.
   * Factorise once, solve many times; solve() may run concurrently on
   * different objects, not on the same one.
   */
  class SparseCholesky
  {
  public:
    SparseCholesky();
    ~SparseCholesky();
    SparseCholesky(const SparseCholesky &) = delete;
    SparseCholesky &
    operator=(const SparseCholesky &) = delete;

    /// Analyse and factorise; throws a message naming @p what if the
    /// matrix is not positive definite, std::bad_alloc if CHOLMOD runs out
    /// of memory.
    void
    initialize(const dealii::SparseMatrix<double> &matrix,
               const std::string &what = "a subproblem matrix");

    /// As initialize(), but returns false instead of throwing when the
    /// matrix is not (numerically) positive definite.
    bool
    try_initialize(const dealii::SparseMatrix<double> &matrix);

    /// Overwrite @p rhs_and_solution with A^{-1} rhs.
    void
    solve(dealii::Vector<double> &rhs_and_solution) const;

  private:
    struct Data;
    std::unique_ptr<Data> data;
  };
} // namespace bilayer

#endif
