// The Newton method of a cohesive step: its Jacobian's kept factorisation
// and the Sherman-Morrison-Woodbury updates of the rows that differ
// (docs/cohesive.md, "The Newton method").

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/lapack_templates.h>

#include <bilayer/solvers/cohesive_newton.h>

#include <algorithm>

namespace bilayer
{
  using namespace dealii;

  void
  CohesiveNewton::multiply(const Vector<double> &x, Vector<double> &y) const
  {
    // (A is stored by rows: the column-major A^T of the BLAS.)
    const types::blas_int n = size(), one = 1;
    const double          unit = 1, zero = 0;
    y.reinit(size());
    if (n > 0)
      gemv("T",
           &n,
           &n,
           &unit,
           &A(0, 0),
           &n,
           x.begin(),
           &one,
           &zero,
           y.begin(),
           &one);
  }


  void
  CohesiveNewton::materialise(const unsigned int    r,
                              const Row            &row,
                              const Vector<double> &g_fixed,
                              Vector<double>       &values) const
  {
    const unsigned int n = size();
    values.reinit(n + (g_fixed.size() > 0 ? 1 : 0));
    values(r) += row.unit;
    for (unsigned int k = 0; k < row.n_terms; ++k)
      {
        const double f = row.factor[k];
        const auto  *a = &A(row.q[k], 0);
        for (unsigned int j = 0; j < n; ++j)
          values(j) -= f * a[j];
        if (g_fixed.size() > 0)
          values(n) += f * g_fixed(row.q[k]);
      }
  }


  void
  CohesiveNewton::factorise(const std::vector<Row> &rows,
                            const Vector<double>   &control_row,
                            const Vector<double>   &load) const
  {
    const unsigned int n     = size();
    const unsigned int total = n + (load.size() > 0 ? 1 : 0);
    const bool         path  = total > n;
    // A new factorisation of the Jacobian.
    // (Factorised in place: a copy of a LAPACKFullMatrix is no
    // factorisation.)
    kept.lu = std::make_unique<LAPACKFullMatrix<double>>(total);
    LAPACKFullMatrix<double> &J = *kept.lu;
    Vector<double>            values;
    for (unsigned int k = 0; k < n; ++k)
      {
        materialise(k, rows[k], load, values);
        for (unsigned int j = 0; j < total; ++j)
          J(k, j) = values(j);
      }
    if (path)
      for (unsigned int j = 0; j < total; ++j)
        J(n, j) = control_row(j);
    J.compute_lu_factorization();
    kept.rows        = rows;
    kept.control_row = control_row;
    kept.columns.clear();
    ++kept.factorisations;
  }


  void
  CohesiveNewton::add_columns(const std::vector<unsigned int> &differ) const
  {
    const unsigned int        total = kept.lu->m();
    std::vector<unsigned int> missing;
    for (const unsigned int k : differ)
      if (kept.columns.find(k) == kept.columns.end())
        missing.push_back(k);
    if (!missing.empty())
      {
        LAPACKFullMatrix<double> units(total, missing.size());
        for (unsigned int c = 0; c < missing.size(); ++c)
          units(missing[c], c) = 1;
        kept.lu->solve(units);
        for (unsigned int c = 0; c < missing.size(); ++c)
          {
            Vector<double> &column = kept.columns[missing[c]];
            column.reinit(total);
            for (unsigned int j = 0; j < total; ++j)
              column(j) = units(j, c);
          }
      }
  }


  Vector<double>
  CohesiveNewton::direction(const std::vector<Row> &rows,
                            const Vector<double>   &control_row,
                            const Vector<double>   &r) const
  {
    const unsigned int    n     = size();
    const unsigned int    total = r.size();
    const bool            path  = total > n;
    const Vector<double>  no_load;
    const Vector<double> &load = path ? g_unit : no_load;
    // The rows that differ from the kept Jacobian's.
    std::vector<unsigned int> differ;
    if (kept.lu)
      {
        for (unsigned int k = 0; k < n; ++k)
          if (!(rows[k] == kept.rows[k]))
            differ.push_back(k);
        if (path)
          differ.push_back(n);
      }
    if (!kept.lu || differ.size() > std::max(40u, total / 8))
      {
        factorise(rows, control_row, load);
        differ.clear();
      }
    Vector<double> y = r;
    kept.lu->solve(y);
    if (differ.empty())
      return y;
    // Sherman-Morrison-Woodbury: J = J_kept + P^T D with P the rows that
    // differ, D their differences: J^{-1} r = y - W (I + D W)^{-1} D y,
    // W = J_kept^{-1} P^T (columns kept while the factorisation is).
    add_columns(differ);
    const unsigned int          m = differ.size();
    std::vector<Vector<double>> D(m);
    Vector<double>              now, before;
    for (unsigned int a = 0; a < m; ++a)
      {
        const unsigned int k = differ[a];
        if (k == n)
          {
            D[a] = control_row;
            D[a] -= kept.control_row;
            continue;
          }
        materialise(k, rows[k], load, now);
        materialise(k, kept.rows[k], load, before);
        D[a] = now;
        D[a] -= before;
      }
    // C = I + D W (BLAS 3: D by rows is the column-major D^T).
    std::vector<double> Dt(std::size_t(total) * m), W(Dt.size()),
      DW(std::size_t(m) * m);
    Vector<double> Dy(m);
    for (unsigned int a = 0; a < m; ++a)
      {
        Dy(a) = D[a] * y;
        std::copy(D[a].begin(),
                  D[a].end(),
                  Dt.begin() + std::size_t(a) * total);
        const Vector<double> &w = kept.columns[differ[a]];
        std::copy(w.begin(), w.end(), W.begin() + std::size_t(a) * total);
      }
    {
      const types::blas_int mm = m, nn = total;
      const double          unit = 1, zero = 0;
      gemm("T",
           "N",
           &mm,
           &mm,
           &nn,
           &unit,
           Dt.data(),
           &nn,
           W.data(),
           &nn,
           &zero,
           DW.data(),
           &mm);
    }
    LAPACKFullMatrix<double> C(m);
    for (unsigned int a = 0; a < m; ++a)
      for (unsigned int b = 0; b < m; ++b)
        C(a, b) = (a == b ? 1. : 0.) + DW[std::size_t(b) * m + a];
    C.compute_lu_factorization();
    C.solve(Dy);
    for (unsigned int b = 0; b < m; ++b)
      y.add(-Dy(b), kept.columns[differ[b]]);
    return y;
  }
} // namespace bilayer
