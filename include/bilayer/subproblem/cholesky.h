#ifndef bilayer_cholesky_h
#define bilayer_cholesky_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace bilayer
{
  /**
   * The dense Cholesky factor S = L_T L_T^T of the Schur complement S of a
   * symmetric positive definite matrix A on an index set T: the trailing
   * block of the sparse factor of A when T is eliminated last. Its order of
   * T (indices()) is the factor's. With A = [A_RR A_RT; A_TR A_TT],
   *   S = A_TT - A_TR A_RR^{-1} A_RT   and   (A^{-1})_TT = S^{-1},
   * so the T part of A^{-1} b for b supported on T costs two dense
   * triangular solves with L_T instead of a sparse forward and back
   * substitution with the whole factor.
   */
  class SchurComplementFactor
  {
  public:
    /// |T|.
    unsigned int
    size() const
    {
      return index.size();
    }

    /// The indices of T, in the order of the factor's rows.
    const std::vector<unsigned int> &
    indices() const
    {
      return index;
    }

    /// x := S^{-1} x (x in the order of indices()).
    void
    solve(std::vector<double> &x) const;

    /// X := S^{-1} X for the @p n_columns columns of X (column-major, each
    /// of size()): LAPACK's dpotrs, blocked (BLAS 3) where solve() is a
    /// plain loop: many right-hand sides at once.
    void
    solve_many(std::vector<double> &X, const unsigned int n_columns) const;

    /// x := L_T^{-1} x, the first of the two triangular solves of solve().
    void
    forward_solve(std::vector<double> &x) const;

    /// x := S x (x in the order of indices()).
    void
    multiply(std::vector<double> &x) const;

  private:
    friend class SparseCholesky;
    std::vector<unsigned int> index;
    /// L_T, column-major, lower triangle.
    std::vector<double> factor;
  };


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
    /// The fill-reducing orderings with the trace indices last.
    enum class Ordering
    {
      /// Constrained approximate minimum degree (CAMD).
      minimum_degree,
      /// CHOLMOD's nested dissection (METIS node bisections, constrained
      /// minimum degree on the separator tree) of the other indices, the
      /// trace indices appended as the last separator.
      nested_dissection,
      /// CHOLMOD's own choice (no indices to keep last).
      cholmod_default
    };

    /// What an analysis found: the ordering kept, the flops and the
    /// entries of its factor (CHOLMOD's fl and lnz).
    struct OrderingReport
    {
      Ordering chosen = Ordering::cholmod_default;
      double   flops = 0, entries = 0;
    };

    /// Which orderings the analysis with trace indices last tries.
    enum class OrderingChoice
    {
      minimum_degree,
      nested_dissection,
      fewest_flops
    };

    /// Set which orderings try_initialize() with trace indices tries.
    void
    set_ordering(const OrderingChoice choice)
    {
      ordering_choice = choice;
    }

    /// The name of @p ordering in the outputs.
    static std::string
    name(Ordering ordering);

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

    /**
     * As try_initialize(), with the indices @p last ordered after all
     * others (CAMD with two constraint sets) and the factor of the Schur
     * complement on them kept (schur_complement()), provided that its
     * dense block of |last|^2 entries is no larger than the sparse factor
     * (else the order is CHOLMOD's usual one and there is no Schur factor).
     */
    bool
    try_initialize(const dealii::SparseMatrix<double> &matrix,
                   const std::vector<unsigned int>    &last);

    /// The orderings tried by the last analysis and the one kept.
    const OrderingReport &
    ordering_report() const
    {
      return report;
    }

    /// The factor of the Schur complement on the indices given to
    /// try_initialize() (nullptr if none was kept).
    const SchurComplementFactor *
    schur_complement() const
    {
      return schur.get();
    }


    /// Overwrite @p rhs_and_solution with A^{-1} rhs.
    void
    solve(dealii::Vector<double> &rhs_and_solution) const;

    /**
     * With schur_complement(): @p solution = A^{-1} b for a right-hand side
     * b that is zero off T, given by its entries on T in the order of
     * schur_complement()->indices() (@p load, overwritten). With
     * P A P^T = L L^T and T last in P, L^{-1} P b is zero on the other
     * indices and L_T^{-1} b_T on T: the forward substitution is the dense
     * one on T alone, and only the backward substitution runs through the
     * sparse factor (about half of solve()).
     */
    void
    solve_from_trailing(std::vector<double>    &load,
                        dealii::Vector<double> &solution) const;

  private:
    struct Data;
    std::unique_ptr<Data>                  data;
    std::unique_ptr<SchurComplementFactor> schur;
    OrderingReport                         report;
    OrderingChoice ordering_choice = OrderingChoice::minimum_degree;

    /// The orderings try_initialize() compares for a matrix of size @p n.
    std::vector<Ordering>
    orderings(std::size_t n) const;
    /// The permutation of @p ordering with the indices of @p member 1
    /// last; false if CHOLMOD failed.
    bool
    ordering_with_last(void                               *matrix_copy,
                       const dealii::SparseMatrix<double> &matrix,
                       const std::vector<int>             &member,
                       Ordering                            ordering,
                       std::vector<int>                   &permutation);
    /// Record CHOLMOD's own choice of ordering and its factor's size.
    void
    record_cholmod_choice();

    /// The CHOLMOD copy of @p matrix's upper triangle (rows as columns).
    void *
    copy_matrix(const dealii::SparseMatrix<double> &matrix);
    /// Factorise the copy @p a (freed) with the analysis done.
    bool
    factorise(void *a);
  };
} // namespace bilayer

#endif
