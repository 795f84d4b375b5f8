#include <deal.II/base/exceptions.h>

#include <bilayer/subproblem/cholesky.h>

#include <algorithm>
#include <cholmod.h>
#include <new>

namespace bilayer
{
  using namespace dealii;

  struct SparseCholesky::Data
  {
    cholmod_common  common;
    cholmod_factor *factor = nullptr;
    std::size_t     n      = 0;
  };


  SparseCholesky::SparseCholesky()
    : data(std::make_unique<Data>())
  {
    cholmod_start(&data->common);
    data->common.print = 0;
  }


  SparseCholesky::~SparseCholesky()
  {
    if (data->factor)
      cholmod_free_factor(&data->factor, &data->common);
    cholmod_finish(&data->common);
  }


  void
  SparseCholesky::initialize(const SparseMatrix<double> &matrix,
                             const std::string          &what)
  {
    AssertThrow(try_initialize(matrix),
                ExcMessage("the Cholesky factorisation of " + what +
                           " failed: it is not positive definite"));
  }


  void *
  SparseCholesky::copy_matrix(const SparseMatrix<double> &matrix)
  {
    if (data->factor)
      cholmod_free_factor(&data->factor, &data->common);
    schur.reset();
    const std::size_t n = matrix.m();
    data->n             = n;

    // The rows of the symmetric matrix are the columns of CHOLMOD's
    // compressed-column format; stype = 1 uses the upper triangle.
    cholmod_sparse *a = cholmod_allocate_sparse(
      n, n, matrix.n_nonzero_elements(), 0, 1, 1, CHOLMOD_REAL, &data->common);
    if (a == nullptr)
      throw std::bad_alloc();
    auto *p = static_cast<int *>(a->p);
    auto *i = static_cast<int *>(a->i);
    auto *x = static_cast<double *>(a->x);
    int   k = 0;
    for (std::size_t row = 0; row < n; ++row)
      {
        p[row] = k;
        for (auto entry = matrix.begin(row); entry != matrix.end(row); ++entry)
          {
            i[k] = entry->column();
            x[k] = entry->value();
            ++k;
          }
      }
    p[n] = k;
    return a;
  }


  bool
  SparseCholesky::factorise(void *matrix)
  {
    auto *a = static_cast<cholmod_sparse *>(matrix);
    if (data->factor == nullptr)
      {
        cholmod_free_sparse(&a, &data->common);
        throw std::bad_alloc();
      }
    cholmod_factorize(a, data->factor, &data->common);
    const int status = data->common.status;
    cholmod_free_sparse(&a, &data->common);
    if (status == CHOLMOD_OUT_OF_MEMORY)
      throw std::bad_alloc();
    return status == CHOLMOD_OK;
  }


  bool
  SparseCholesky::try_initialize(const SparseMatrix<double> &matrix)
  {
    void *a = copy_matrix(matrix);
    data->factor =
      cholmod_analyze(static_cast<cholmod_sparse *>(a), &data->common);
    return factorise(a);
  }


  bool
  SparseCholesky::try_initialize(const SparseMatrix<double>      &matrix,
                                 const std::vector<unsigned int> &last)
  {
    auto             *a = static_cast<cholmod_sparse *>(copy_matrix(matrix));
    const std::size_t n = data->n, m = last.size();
    if (m == 0 || m >= n)
      {
        data->factor = cholmod_analyze(a, &data->common);
        return factorise(a);
      }
    // CAMD with the indices of T in the second constraint set: they come
    // after all others. The elimination tree's postorder keeps them there
    // (they are the ancestors of every other node that couples to them);
    // checked below on the factor's permutation.
    std::vector<int> member(n, 0), permutation(n);
    for (const unsigned int i : last)
      member[i] = 1;
    const bool ordered = cholmod_camd(
      a, nullptr, 0, member.data(), permutation.data(), &data->common);
    if (!ordered)
      {
        data->factor = cholmod_analyze(a, &data->common);
        return factorise(a);
      }
    // The factor as L L^T (a simplicial one is LDL^T otherwise), supernodal
    // or simplicial as CHOLMOD chooses (simplicial for small matrices).
    const int nmethods              = data->common.nmethods,
              ordering              = data->common.method[0].ordering,
              final_ll              = data->common.final_ll;
    data->common.nmethods           = 1;
    data->common.method[0].ordering = CHOLMOD_GIVEN;
    data->common.final_ll           = 1;
    data->factor =
      cholmod_analyze_p(a, permutation.data(), nullptr, 0, &data->common);
    data->common.nmethods           = nmethods;
    data->common.method[0].ordering = ordering;
    if (data->factor == nullptr)
      {
        cholmod_free_sparse(&a, &data->common);
        throw std::bad_alloc();
      }
    // The dense block of |T|^2 entries must not outgrow the sparse factor.
    const double sparse_entries = data->common.lnz;
    if (static_cast<double>(m) * m > sparse_entries)
      {
        cholmod_free_factor(&data->factor, &data->common);
        data->factor = cholmod_analyze(a, &data->common);
        return factorise(a);
      }
    const bool factorised = factorise(a);
    data->common.final_ll = final_ll;
    if (!factorised)
      return false;

    const cholmod_factor *f     = data->factor;
    const int            *perm  = static_cast<const int *>(f->Perm);
    const std::size_t     first = n - m;
    for (std::size_t k = first; k < n; ++k)
      if (member[perm[k]] != 1)
        return true; // T not last after all: no Schur factor
    if (!f->is_ll)
      return true;
    schur = std::make_unique<SchurComplementFactor>();
    schur->index.assign(perm + first, perm + n);
    schur->factor.assign(m * m, 0.);
    const auto *x = static_cast<const double *>(f->x);
    if (!f->is_super)
      {
        // Compressed columns: rows i[p[c] .. p[c] + nz[c]), diagonal first.
        const auto *p  = static_cast<const int *>(f->p);
        const auto *i  = static_cast<const int *>(f->i);
        const auto *nz = static_cast<const int *>(f->nz);
        for (std::size_t c = first; c < n; ++c)
          for (int k = p[c]; k < p[c] + nz[c]; ++k)
            schur->factor[(c - first) * m + (i[k] - first)] = x[k];
        return true;
      }
    const auto *super = static_cast<const int *>(f->super);
    const auto *pi    = static_cast<const int *>(f->pi);
    const auto *px    = static_cast<const int *>(f->px);
    const auto *rows  = static_cast<const int *>(f->s);
    for (std::size_t s = 0; s < f->nsuper; ++s)
      {
        const std::size_t c0 = super[s], c1 = super[s + 1];
        if (c1 <= first)
          continue;
        const std::size_t n_rows = pi[s + 1] - pi[s];
        for (std::size_t c = std::max(c0, first); c < c1; ++c)
          for (std::size_t r = c - c0; r < n_rows; ++r)
            schur->factor[(c - first) * m + (rows[pi[s] + r] - first)] =
              x[px[s] + (c - c0) * n_rows + r];
      }
    return true;
  }


  // The dense triangular products below are plain loops, not BLAS calls:
  // their order of summation, and so their bits, do not depend on the BLAS
  // or its threads (a threaded dtrsv sums in blocks per thread), and at the
  // sizes of a Sigma (|T| of the order of 10^3) they cost about a
  // millisecond.

  void
  SchurComplementFactor::solve(std::vector<double> &x) const
  {
    AssertDimension(x.size(), size());
    const std::size_t n = size();
    const double     *l = factor.data();
    forward_solve(x);
    // L^T z = y, by rows of L^T (columns of L).
    for (std::size_t j = n; j-- > 0;)
      {
        const double *column = l + j * n;
        double        sum    = x[j];
        for (std::size_t i = j + 1; i < n; ++i)
          sum -= column[i] * x[i];
        x[j] = sum / column[j];
      }
  }


  void
  SchurComplementFactor::forward_solve(std::vector<double> &x) const
  {
    AssertDimension(x.size(), size());
    const std::size_t n = size();
    const double     *l = factor.data();
    // L y = x, by columns.
    for (std::size_t j = 0; j < n; ++j)
      {
        const double *column = l + j * n;
        const double  y      = x[j] / column[j];
        x[j]                 = y;
        for (std::size_t i = j + 1; i < n; ++i)
          x[i] -= column[i] * y;
      }
  }


  void
  SchurComplementFactor::multiply(std::vector<double> &x) const
  {
    AssertDimension(x.size(), size());
    const std::size_t n = size();
    const double     *l = factor.data();
    // z = L^T x ...
    std::vector<double> z(n);
    for (std::size_t j = 0; j < n; ++j)
      {
        const double *column = l + j * n;
        double        sum    = 0;
        for (std::size_t i = j; i < n; ++i)
          sum += column[i] * x[i];
        z[j] = sum;
      }
    // ... then L z.
    std::fill(x.begin(), x.end(), 0.);
    for (std::size_t j = 0; j < n; ++j)
      {
        const double *column = l + j * n;
        for (std::size_t i = j; i < n; ++i)
          x[i] += column[i] * z[j];
      }
  }

  void
  SparseCholesky::solve(Vector<double> &rhs_and_solution) const
  {
    AssertDimension(rhs_and_solution.size(), data->n);
    cholmod_dense b;
    b.nrow  = data->n;
    b.ncol  = 1;
    b.nzmax = data->n;
    b.d     = data->n;
    b.x     = rhs_and_solution.data();
    b.z     = nullptr;
    b.xtype = CHOLMOD_REAL;
    b.dtype = CHOLMOD_DOUBLE;
    cholmod_dense *x =
      cholmod_solve(CHOLMOD_A, data->factor, &b, &data->common);
    AssertThrow(x != nullptr, ExcMessage("CHOLMOD solve failed"));
    const double *values = static_cast<const double *>(x->x);
    std::copy(values, values + data->n, rhs_and_solution.begin());
    cholmod_free_dense(&x, &data->common);
  }


  void
  SparseCholesky::solve_from_trailing(std::vector<double> &load,
                                      Vector<double>      &solution) const
  {
    Assert(schur != nullptr, ExcInternalError());
    const std::size_t n = data->n, m = schur->size(), first = n - m;
    schur->forward_solve(load);
    cholmod_dense *y = cholmod_zeros(n, 1, CHOLMOD_REAL, &data->common);
    if (y == nullptr)
      throw std::bad_alloc();
    std::copy(load.begin(), load.end(), static_cast<double *>(y->x) + first);
    // L^T z = y, then x = P^T z.
    cholmod_dense *z =
      cholmod_solve(CHOLMOD_Lt, data->factor, y, &data->common);
    cholmod_free_dense(&y, &data->common);
    AssertThrow(z != nullptr, ExcMessage("CHOLMOD solve failed"));
    const double *values = static_cast<const double *>(z->x);
    const int    *perm   = static_cast<const int *>(data->factor->Perm);
    solution.reinit(n, true);
    for (std::size_t k = 0; k < n; ++k)
      solution(perm[k]) = values[k];
    cholmod_free_dense(&z, &data->common);
  }
} // namespace bilayer
