#include <deal.II/base/exceptions.h>

#include <bilayer/cholesky.h>

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


  bool
  SparseCholesky::try_initialize(const SparseMatrix<double> &matrix)
  {
    if (data->factor)
      cholmod_free_factor(&data->factor, &data->common);
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

    data->factor = cholmod_analyze(a, &data->common);
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
} // namespace bilayer
