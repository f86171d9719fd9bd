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
    base_rows.clear();
    update_columns.clear();
  }

  std::size_t
  PairSystem::memory() const
  {
    std::size_t bytes = sizeof(double) * base.m() * base.n();
    for (const auto &column : update_columns)
      bytes += sizeof(double) * column.size();
    return bytes;
  }

  PairSystem::Solve
  PairSystem::solve(const std::vector<double> &C_rows, const unsigned int m, const double hc,
                    const std::function<SystemRow(unsigned int, unsigned int)> &row_of,
                    const std::function<RowsOfPair(unsigned int)>               &rows_of,
                    dealii::Vector<double>                                     &x)
  {
    // Local unknowns a = dim p + k of the system's pair p (pair_indices[p]).
    const unsigned int n     = pair_indices.size();
    const unsigned int n_row = dim * n;
    // (h C)(row, j) of local unknowns, from C by rows.
    const auto flexibility = [&](const unsigned int j, const unsigned int row) {
      return hc * C_rows[static_cast<std::size_t>(unknowns[row]) * m + unknowns[j]];
    };
    const auto system_row = [&](const unsigned int p, const SystemRow &parts, double *row) {
      std::fill(row, row + n_row, 0.);
      for (unsigned int l = 0; l < dim; ++l)
        if (parts.flex[l] != 0.)
          for (unsigned int j = 0; j < n_row; ++j)
            row[j] += parts.flex[l] * flexibility(j, dim * p + l);
      for (unsigned int l = 0; l < dim; ++l)
        row[dim * p + l] += parts.own[l];
    };

    // The rows that changed, ascending: the normal row is the flexibility
    // row in stick and slip alike, and changes only with a separation.
    std::vector<RowsOfPair> rows(n);
    for (unsigned int p = 0; p < n; ++p)
      rows[p] = rows_of(pair_indices[p]);
    std::vector<unsigned int> changed;
    if (base_rows.size() == n)
      for (unsigned int p = 0; p < n; ++p)
        if (!(rows[p] == base_rows[p]))
          for (unsigned int k = 0; k < dim; ++k)
            if (k > 0 || (rows[p].state == PairState::separation) !=
                           (base_rows[p].state == PairState::separation))
              changed.push_back(dim * p + k);
    Solve how = changed.empty() ? Solve::kept : Solve::updated;
    if (base_rows.size() != n || changed.size() > std::max(8u, n_row / 4))
      {
        base.reinit(n_row, n_row);
        std::vector<double> row(n_row);
        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int k = 0; k < dim; ++k)
            {
              system_row(p, row_of(pair_indices[p], k), row.data());
              for (unsigned int j = 0; j < n_row; ++j)
                base(dim * p + k, j) = row[j];
            }
        base_rows = rows;
        base.compute_lu_factorization();
        update_columns.assign(n_row, {});
        changed.clear();
        how = Solve::factorized;
      }

    const unsigned int     n_changed = changed.size();
    dealii::Vector<double> b(n_row);
    std::vector<SystemRow> changed_parts(n_changed);
    for (unsigned int p = 0, a = 0; p < n; ++p)
      for (unsigned int k = 0; k < dim; ++k)
        {
          const SystemRow parts = row_of(pair_indices[p], k);
          b(dim * p + k)        = parts.rhs;
          if (a < n_changed && changed[a] == dim * p + k)
            changed_parts[a++] = parts;
        }
    x = b;
    base.solve(x); // y
    if (n_changed == 0)
      return how;

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
    // T = A_R Z and t = A_R y - b_R. Where a new row's rows of h C are rows
    // of the base (a pair that the base has in stick, or a normal row),
    // A0_r Z = (E_R)_r and A0_r y = b_r give those parts without a product:
    // such a row (a slipping pair that the base has stuck, a separated pair,
    // a pair slipping with kappa = 0) costs its own few entries of Z and y;
    // the other rows are built and multiplied by Z.
    const auto base_row_is_flexibility = [&](const unsigned int p, const unsigned int l) {
      return base_rows[p].state == PairState::stick ||
             (base_rows[p].state == PairState::slip && l == 0);
    };
    std::vector<int> position(n_row, -1);
    for (unsigned int a = 0; a < n_changed; ++a)
      position[changed[a]] = a;
    const auto Z_entry = [&](const unsigned int j, const unsigned int c) {
      return update_columns[changed[c]](j);
    };
    dealii::LAPACKFullMatrix<double> T(n_changed, n_changed);
    dealii::Vector<double>           t(n_changed);
    std::vector<unsigned int>        products; // rows of R multiplied by Z
    for (unsigned int a = 0; a < n_changed; ++a)
      {
        const unsigned int p     = changed[a] / dim;
        const SystemRow   &parts = changed_parts[a];
        bool               cheap = true;
        for (unsigned int l = 0; l < dim; ++l)
          cheap = cheap && (parts.flex[l] == 0. || base_row_is_flexibility(p, l));
        if (!cheap)
          {
            products.push_back(a);
            continue;
          }
        t(a) = -b(changed[a]);
        for (unsigned int l = 0; l < dim; ++l)
          {
            const unsigned int r_pl = dim * p + l;
            if (parts.flex[l] != 0.)
              {
                t(a) += parts.flex[l] * b(r_pl);
                if (position[r_pl] >= 0)
                  T(a, position[r_pl]) += parts.flex[l];
              }
            if (parts.own[l] != 0.)
              {
                t(a) += parts.own[l] * x(r_pl);
                for (unsigned int c = 0; c < n_changed; ++c)
                  T(a, c) += parts.own[l] * Z_entry(r_pl, c);
              }
          }
      }
    if (!products.empty())
      {
        const unsigned int               n_products = products.size();
        dealii::LAPACKFullMatrix<double> A_P(n_products, n_row), Z(n_row, n_changed),
          T_P(n_products, n_changed);
        std::vector<double> row(n_row);
        for (unsigned int q = 0; q < n_products; ++q)
          {
            const unsigned int a = products[q];
            system_row(changed[a] / dim, changed_parts[a], row.data());
            double y_a = 0.;
            for (unsigned int j = 0; j < n_row; ++j)
              {
                A_P(q, j) = row[j];
                y_a += row[j] * x(j);
              }
            t(a) = y_a - b(changed[a]);
          }
        for (unsigned int c = 0; c < n_changed; ++c)
          for (unsigned int j = 0; j < n_row; ++j)
            Z(j, c) = Z_entry(j, c);
        A_P.mmult(T_P, Z);
        for (unsigned int q = 0; q < n_products; ++q)
          for (unsigned int c = 0; c < n_changed; ++c)
            T(products[q], c) = T_P(q, c);
      }
    T.compute_lu_factorization();
    T.solve(t);
    for (unsigned int a = 0; a < n_changed; ++a)
      x.add(-t(a), update_columns[changed[a]]);
    return how;
  }
} // namespace archdam::joints
