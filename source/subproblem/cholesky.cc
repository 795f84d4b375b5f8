#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include <bilayer/core/huge_pages.h>
#include <bilayer/subproblem/cholesky.h>

#include <algorithm>
#include <cholmod.h>
#include <cstdlib>
#include <mutex>
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
    huge_pages::use_for_cholmod();
    cholmod_start(&data->common);
    data->common.print = 0;
  }


  SparseCholesky::~SparseCholesky()
  {
    if (data->factor)
      cholmod_free_factor(&data->factor, &data->common);
    cholmod_finish(&data->common);
  }


  std::string
  SparseCholesky::name(const Ordering ordering)
  {
    switch (ordering)
      {
        case Ordering::minimum_degree:
          return "minimum degree";
        case Ordering::nested_dissection:
          return "nested dissection";
        default:
          return "CHOLMOD's choice";
      }
  }


  std::vector<SparseCholesky::Ordering>
  SparseCholesky::orderings(const std::size_t n) const
  {
    switch (ordering_choice)
      {
        case OrderingChoice::nested_dissection:
          return {Ordering::nested_dissection};
        case OrderingChoice::fewest_flops:
          // Below a few thousand unknowns the bisections cost more than
          // any difference in the factorisation.
          if (n >= 4000)
            return {Ordering::minimum_degree, Ordering::nested_dissection};
          return {Ordering::minimum_degree};
        default:
          return {Ordering::minimum_degree};
      }
  }


  void
  SparseCholesky::record_cholmod_choice()
  {
    report.chosen  = Ordering::cholmod_default;
    report.flops   = data->common.fl;
    report.entries = data->common.lnz;
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
    report  = OrderingReport();
    data->factor =
      cholmod_analyze(static_cast<cholmod_sparse *>(a), &data->common);
    record_cholmod_choice();
    return factorise(a);
  }


  namespace
  {
    /**
     * The graph of @p matrix (its full symmetric pattern) on the indices
     * with @p member 0, compressed: runs of consecutive indices with equal
     * rows (the components of one vertex) are one node. Returns the
     * pattern (CHOLMOD, upper triangle) over the nodes; @p first and
     * @p size hold each node's first index and its number of indices.
     */
    cholmod_sparse *
    compressed_interior(const SparseMatrix<double> &matrix,
                        const std::vector<int>     &member,
                        std::vector<int>           &first,
                        std::vector<int>           &size,
                        cholmod_common             *common)
    {
      const SparsityPattern &pattern = matrix.get_sparsity_pattern();
      const std::size_t      n       = matrix.m();
      const auto equal_rows = [&](const std::size_t i, const std::size_t j) {
        if (pattern.row_length(i) != pattern.row_length(j))
          return false;
        // deal.II stores the diagonal first, then the row sorted.
        std::vector<std::size_t> ci, cj;
        for (auto e = pattern.begin(i); e != pattern.end(i); ++e)
          ci.push_back(e->column());
        for (auto e = pattern.begin(j); e != pattern.end(j); ++e)
          cj.push_back(e->column());
        std::sort(ci.begin(), ci.end());
        std::sort(cj.begin(), cj.end());
        return ci == cj;
      };
      std::vector<int> node(n, -1);
      first.clear();
      size.clear();
      for (std::size_t i = 0; i < n; ++i)
        if (member[i] == 0)
          {
            if (i > 0 && node[i - 1] >= 0 && equal_rows(i - 1, i))
              {
                node[i] = node[i - 1];
                ++size.back();
              }
            else
              {
                node[i] = first.size();
                first.push_back(i);
                size.push_back(1);
              }
          }
      const std::size_t             n_nodes = first.size();
      std::vector<std::vector<int>> adjacent(n_nodes);
      for (std::size_t c = 0; c < n_nodes; ++c)
        {
          for (auto e = pattern.begin(first[c]); e != pattern.end(first[c]);
               ++e)
            {
              const int d = node[e->column()];
              if (d >= 0 && d <= static_cast<int>(c))
                adjacent[c].push_back(d);
            }
          std::sort(adjacent[c].begin(), adjacent[c].end());
          adjacent[c].erase(std::unique(adjacent[c].begin(), adjacent[c].end()),
                            adjacent[c].end());
        }
      std::size_t nz = 0;
      for (const auto &a : adjacent)
        nz += a.size();
      cholmod_sparse *b = cholmod_allocate_sparse(
        n_nodes, n_nodes, nz, 1, 1, 1, CHOLMOD_PATTERN, common);
      if (b == nullptr)
        throw std::bad_alloc();
      auto *bp = static_cast<int *>(b->p);
      auto *bi = static_cast<int *>(b->i);
      int   k  = 0;
      for (std::size_t c = 0; c < n_nodes; ++c)
        {
          bp[c] = k;
          for (const int d : adjacent[c])
            bi[k++] = d;
        }
      bp[n_nodes] = k;
      return b;
    }
  } // namespace


  bool
  SparseCholesky::ordering_with_last(void                       *matrix_copy,
                                     const SparseMatrix<double> &matrix,
                                     const std::vector<int>     &member,
                                     const Ordering              ordering,
                                     std::vector<int>           &permutation)
  {
    auto             *a = static_cast<cholmod_sparse *>(matrix_copy);
    const std::size_t n = data->n;
    permutation.assign(n, 0);
    if (ordering == Ordering::minimum_degree)
      // CAMD with the indices of T in the second constraint set: they come
      // after all others.
      return cholmod_camd(a,
                          nullptr,
                          0,
                          const_cast<int *>(member.data()),
                          permutation.data(),
                          &data->common);
    // Nested dissection of the interior (CHOLMOD's: METIS node bisections,
    // constrained minimum degree on the separator tree) on the graph of
    // its vertices, T appended: T is the last separator.
    std::vector<int> first, size;
    cholmod_sparse  *b =
      compressed_interior(matrix, member, first, size, &data->common);
    const std::size_t n_nodes = b->ncol;
    std::vector<int>  order(n_nodes), parent(n_nodes), component(n_nodes);
    // METIS draws from one random-number state per process, seeded at
    // each call: calls from concurrent subproblem set-ups would interleave
    // their draws and make the ordering depend on the timing.
    static std::mutex                 metis;
    const std::lock_guard<std::mutex> lock(metis);
    const auto                        components = cholmod_nested_dissection(b,
                                                      nullptr,
                                                      0,
                                                      order.data(),
                                                      parent.data(),
                                                      component.data(),
                                                      &data->common);
    cholmod_free_sparse(&b, &data->common);
    if (components < 0)
      return false;
    std::size_t k = 0;
    for (const int c : order)
      for (int j = first[c]; j < first[c] + size[c]; ++j)
        permutation[k++] = j;
    for (std::size_t j = 0; j < n; ++j)
      if (member[j] != 0)
        permutation[k++] = j;
    return true;
  }


  bool
  SparseCholesky::try_initialize(const SparseMatrix<double>      &matrix,
                                 const std::vector<unsigned int> &last)
  {
    auto             *a = static_cast<cholmod_sparse *>(copy_matrix(matrix));
    const std::size_t n = data->n, m = last.size();
    report = OrderingReport();
    if (m == 0 || m >= n)
      {
        data->factor = cholmod_analyze(a, &data->common);
        record_cholmod_choice();
        return factorise(a);
      }
    // T after all other indices, by each ordering Solver/Ordering names;
    // of several, the one with fewer flops is factorised. The
    // elimination tree's postorder keeps T last (T holds the ancestors of
    // every other node that couples to it); checked below on the factor's
    // permutation.
    std::vector<int> member(n, 0);
    for (const unsigned int i : last)
      member[i] = 1;
    // The factor as L L^T (a simplicial one is LDL^T otherwise), supernodal
    // or simplicial as CHOLMOD chooses (simplicial for small matrices).
    const int nmethods              = data->common.nmethods,
              ordering              = data->common.method[0].ordering,
              final_ll              = data->common.final_ll;
    data->common.nmethods           = 1;
    data->common.method[0].ordering = CHOLMOD_GIVEN;
    data->common.final_ll           = 1;
    for (const Ordering candidate : orderings(n))
      {
        std::vector<int> permutation;
        if (!ordering_with_last(a, matrix, member, candidate, permutation))
          continue;
        cholmod_factor *f =
          cholmod_analyze_p(a, permutation.data(), nullptr, 0, &data->common);
        if (f == nullptr)
          continue;
        const double flops = data->common.fl, entries = data->common.lnz;
        if (data->factor == nullptr || flops < report.flops)
          {
            if (data->factor)
              cholmod_free_factor(&data->factor, &data->common);
            data->factor   = f;
            report.chosen  = candidate;
            report.flops   = flops;
            report.entries = entries;
          }
        else
          cholmod_free_factor(&f, &data->common);
      }
    data->common.nmethods           = nmethods;
    data->common.method[0].ordering = ordering;
    if (data->factor == nullptr)
      {
        data->common.final_ll = final_ll;
        data->factor          = cholmod_analyze(a, &data->common);
        record_cholmod_choice();
        return factorise(a);
      }
    // The dense block of |T|^2 entries must not outgrow the sparse factor.
    const double sparse_entries = report.entries;
    if (static_cast<double>(m) * m > sparse_entries)
      {
        // CHOLMOD's own ordering, the factor still as L L^T (and so for
        // this object's later analyses: the bits of every earlier version).
        cholmod_free_factor(&data->factor, &data->common);
        data->factor = cholmod_analyze(a, &data->common);
        record_cholmod_choice();
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
  SchurComplementFactor::solve_many(std::vector<double> &X,
                                    const unsigned int   n_columns) const
  {
    AssertDimension(X.size(), std::size_t(size()) * n_columns);
    if (n_columns == 0 || size() == 0)
      return;
    const types::blas_int n = size(), m = n_columns;
    types::blas_int       info = 0;
    potrs("L", &n, &m, factor.data(), &n, X.data(), &n, &info);
    AssertThrow(info == 0,
                ExcMessage("SchurComplementFactor::solve_many: dpotrs "
                           "returned " +
                           std::to_string(info)));
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
