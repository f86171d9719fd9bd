// The contact problem joint by joint (doc/theory/joints.md §12).
#include <archdam/joints/joint_solver.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace archdam::joints
{
  using namespace dealii;

  bool
  MixedJointSolver::joint_by_joint(ContactStep &step)
  {
    // doc/theory/joints.md §12: each joint's pairs solved together by the
    // active set with the other joints' forces held (their effect on it
    // added to its s); a joint's change moves the w of its own and its
    // neighbouring joints' pairs, where W has not yet decayed. Red-black:
    // the even joints, then the odd ones; the joints of one colour do not
    // see each other within the sweep, so they are solved on the processes
    // in turn and shared, and the sweep is the same on any number of them.
    // Once a sweep leaves every pair settled, w is computed with the exact
    // C, and the law checked again at every pair. The sweeps are counted in
    // the step's iterations, with the joints' own active-set iterations.
    const unsigned int  m  = dim * pairs.size();
    const double        hc = contact_h();
    MPI_Comm            comm    = pairs.communicator();
    const unsigned int  n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int  rank    = Utilities::MPI::this_mpi_process(comm);
    std::vector<double> before, w_start(m), f_start(m), shared;
    s_joint.resize(m);
    std::vector<unsigned int> all(pairs.size());
    std::iota(all.begin(), all.end(), 0u);
    // what a process that solved a joint gives the others, per pair
    constexpr unsigned int per_pair = dim + 5;
    const auto             pack     = [&](const unsigned int i, double *v) {
      std::copy(&force[dim * i], &force[dim * i] + dim, v);
      v[dim]     = static_cast<double>(state[i]);
      v[dim + 1] = direction[i][1];
      v[dim + 2] = direction[i][2];
      v[dim + 3] = slip_ratio[i];
      v[dim + 4] = damaged[i] ? 1. : 0.;
    };
    const auto unpack = [&](const unsigned int i, const double *v) {
      std::copy(v, v + dim, &force[dim * i]);
      state[i]        = static_cast<PairState>(std::lround(v[dim]));
      direction[i][1] = v[dim + 1];
      direction[i][2] = v[dim + 2];
      slip_ratio[i]   = v[dim + 3];
      damaged[i]      = v[dim + 4] != 0.;
    };
    // The sweeps hold the law to a thousandth of Gap tolerance, so that the
    // answer is as near the exact problem's as the all-pairs solve's (which
    // is exact to round-off for the states it finds): a law held only to the
    // tolerance at every pair of a joint moves the whole joint by it.
    const double tolerance = 1e-3 * p.gap_tolerance;
    for (unsigned int sweep = 0; sweep < sweep_limit && step.iterations < p.max_iterations;
         ++sweep)
      {
        before = force;
        for (const unsigned int colour : {0u, 1u})
          {
            f_start                      = force;
            const unsigned int iterations = step.iterations;
            bool               failed     = false;
            for (unsigned int b = colour; b < by_joint.size() && !failed; b += 2)
              {
                if ((b / 2) % n_ranks != rank)
                  continue;
                const auto &own = by_joint[b].pairs();
                for (const unsigned int i : own)
                  for (unsigned int k = 0; k < dim; ++k)
                    {
                      const unsigned int r   = dim * i + k;
                      const double      *row = &C_rows[static_cast<std::size_t>(r) * m];
                      double             v   = w[r];
                      for (const unsigned int j : own)
                        for (unsigned int l = 0; l < dim; ++l)
                          v += hc * row[dim * j + l] * force[dim * j + l];
                      s_joint[r] = v;
                      w_start[r] = w[r];
                    }
                failed = !active_set_iteration(step, std::min(p.max_iterations, active_set_limit),
                                               by_joint[b], s_joint);
                for (const unsigned int i : own)
                  for (unsigned int k = 0; k < dim; ++k)
                    w[dim * i + k] = w_start[dim * i + k];
              }
            if (n_ranks > 1)
              {
                shared.assign(per_pair * pairs.size() + 2, 0.);
                for (unsigned int b = colour; b < by_joint.size(); b += 2)
                  if ((b / 2) % n_ranks == rank)
                    for (const unsigned int i : by_joint[b].pairs())
                      pack(i, &shared[per_pair * i]);
                shared[per_pair * pairs.size()]     = failed ? 1. : 0.;
                shared[per_pair * pairs.size() + 1] = step.iterations - iterations;
                Utilities::MPI::sum(shared, comm, shared);
                for (unsigned int b = colour; b < by_joint.size(); b += 2)
                  if ((b / 2) % n_ranks != rank)
                    for (const unsigned int i : by_joint[b].pairs())
                      unpack(i, &shared[per_pair * i]);
                failed          = shared[per_pair * pairs.size()] != 0.;
                step.iterations = iterations + std::lround(shared[per_pair * pairs.size() + 1]);
              }
            if (failed)
              return false;
            // the colour's force changes move the pairs within their reach,
            // in the joints' order on every process
            for (unsigned int b = colour; b < by_joint.size(); b += 2)
              for (const unsigned int j : by_joint[b].pairs())
                for (unsigned int l = 0; l < dim; ++l)
                  if (const double df = force[dim * j + l] - f_start[dim * j + l]; df != 0.)
                    {
                      const double *column = &C[static_cast<std::size_t>(dim * j + l) * m];
                      for (const unsigned int c : reach[b])
                        for (const unsigned int i : by_joint[c].pairs())
                          for (unsigned int k = 0; k < dim; ++k)
                            w[dim * i + k] -= hc * column[dim * i + k] * df;
                    }
          }
        ++step.iterations;
        step.force_change = relative_change(before);
        if (!settle(all) || gap_residual(step.worst_pair) > tolerance)
          continue;
        set_relative_displacement(); // the exact C: the far joints too
        const bool settled = settle(all);
        step.gap_residual  = gap_residual(step.worst_pair);
        if (settled && step.gap_residual <= tolerance)
          return step.converged = true;
      }
    return false;
  }
} // namespace archdam::joints
