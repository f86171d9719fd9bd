#include <archdam/joints/pair_system.h>

#include <algorithm>

namespace archdam::joints
{
  PairSystem::PairSystem(std::vector<unsigned int> pairs)
    : pair_indices(std::move(pairs))
  {
    for (const unsigned int i : pair_indices)
      for (unsigned int k = 0; k < dim; ++k)
        unknowns.push_back(dim * i + k);
  }

  void
  PairSystem::forget()
  {
    base.reinit(0, 0);
    update_columns.clear();
    last_b.reinit(0);
    last_y.reinit(0);
  }

  std::size_t
  PairSystem::memory() const
  {
    std::size_t bytes = sizeof(double) * base.m() * base.n();
    for (const auto &column : update_columns)
      bytes += sizeof(double) * column.size();
    return bytes + sizeof(double) * (last_b.size() + last_y.size() + base_product.size());
  }

  PairSystem::Solve
  PairSystem::solve(const std::vector<double> &C_rows, const unsigned int m, const double hc,
                    const std::function<SystemRow(unsigned int, unsigned int)> &row_of,
                    dealii::Vector<double>                                     &x)
  {
    // Local unknowns a = dim p + k of the system's pair p (pair_indices[p]).
    const unsigned int n_row = unknowns.size();
    Solve              how   = Solve::kept;
    if (base.m() != n_row || base_hc != hc)
      {
        // the base: every pair in stick, (h C) restricted to the system's
        // unknowns
        base.reinit(n_row, n_row);
        for (unsigned int a = 0; a < n_row; ++a)
          {
            const double *row = &C_rows[static_cast<std::size_t>(unknowns[a]) * m];
            for (unsigned int j = 0; j < n_row; ++j)
              base(a, j) = hc * row[unknowns[j]];
          }
        base.compute_lu_factorization();
        base_hc = hc;
        update_columns.assign(n_row, {});
        last_b.reinit(0);
        last_y.reinit(0);
        how = Solve::factorized;
      }

    // The rows that differ from the base's (a flexibility row with nothing
    // on the pair's own unknowns), ascending.
    std::vector<SystemRow>    parts(n_row);
    std::vector<unsigned int> changed;
    dealii::Vector<double>    b(n_row);
    for (unsigned int a = 0; a < n_row; ++a)
      {
        parts[a] = row_of(pair_indices[a / dim], a % dim);
        b(a)     = parts[a].rhs;
        for (unsigned int l = 0; l < dim; ++l)
          if (parts[a].own[l] != 0. || parts[a].flex[l] != (l == a % dim ? 1. : 0.))
            {
              changed.push_back(a);
              break;
            }
      }
    if (!changed.empty() && how == Solve::kept)
      how = Solve::updated;

    // Z's missing columns, in one multi-column solve.
    std::vector<unsigned int> missing;
    for (const unsigned int j : changed)
      if (update_columns[j].size() == 0)
        missing.push_back(j);
    if (!missing.empty())
      {
        dealii::LAPACKFullMatrix<double> Z(n_row, missing.size());
        for (unsigned int c = 0; c < missing.size(); ++c)
          Z(missing[c], c) = 1.;
        base.solve(Z);
        for (unsigned int c = 0; c < missing.size(); ++c)
          {
            update_columns[missing[c]].reinit(n_row);
            for (unsigned int j = 0; j < n_row; ++j)
              update_columns[missing[c]](j) = Z(j, c);
          }
      }
    // y = A0^{-1} b, from the last y when b differs from the last b in a
    // few rows that have their column of Z, else by the LU (a pass over
    // all of it).
    std::vector<unsigned int> differing;
    bool                      follows = last_y.size() == n_row;
    for (unsigned int a = 0; a < n_row && follows; ++a)
      if (b(a) != last_b(a))
        {
          follows = update_columns[a].size() == n_row && 4 * differing.size() < n_row;
          differing.push_back(a);
        }
    if (follows)
      {
        x = last_y;
        for (const unsigned int a : differing)
          x.add(b(a) - last_b(a), update_columns[a]);
      }
    else
      {
        x = b;
        base.solve(x);
      }
    last_b       = b;
    last_y       = x;
    base_product = b; // A0 x = b - E_R t
    if (changed.empty())
      return how;

    // T = A_R Z and t = A_R y - b_R. A new row is sum_l flex[l] (row r_l of
    // the base) + sum_l own[l] e_{r_l}, r_l = dim p + l, and the base's rows
    // give A0_r Z = (E_R)_r and A0_r y = b_r: a row of T is the unit entries
    // of its rows r_l among R plus its own entries times three rows of Z, a
    // row of t the same with b and y.
    const unsigned int n_changed = changed.size();
    std::vector<int>   position(n_row, -1);
    for (unsigned int c = 0; c < n_changed; ++c)
      position[changed[c]] = c;
    dealii::LAPACKFullMatrix<double> T(n_changed, n_changed);
    dealii::Vector<double>           t(n_changed);
    for (unsigned int a = 0; a < n_changed; ++a)
      {
        const SystemRow   &row   = parts[changed[a]];
        const unsigned int first = changed[a] - changed[a] % dim;
        t(a)                     = -b(changed[a]);
        for (unsigned int l = 0; l < dim; ++l)
          {
            const unsigned int r_l = first + l;
            if (row.flex[l] != 0.)
              {
                t(a) += row.flex[l] * b(r_l);
                if (position[r_l] >= 0)
                  T(a, position[r_l]) += row.flex[l];
              }
            if (row.own[l] != 0.)
              {
                t(a) += row.own[l] * x(r_l);
                for (unsigned int c = 0; c < n_changed; ++c)
                  T(a, c) += row.own[l] * update_columns[changed[c]](r_l);
              }
          }
      }
    T.compute_lu_factorization();
    T.solve(t);
    for (unsigned int c = 0; c < n_changed; ++c)
      {
        x.add(-t(c), update_columns[changed[c]]);
        base_product(changed[c]) -= t(c);
      }
    return how;
  }
} // namespace archdam::joints
