// Whole run with compressible water (regression of the chain, serial and
// mpirun -np 2): the coarse arch dam with its reservoir on massless rock,
// gravity and hydrostatic pressure, then 0.2 s of El Centro in x; the
// hydrodynamic pressure recorded at five points along the crown's upstream
// face. Checks that can fail:
//  - the static stage leaves the hydrodynamic pressure at zero (the water
//    rows carry no static load);
//  - pressure_histories.csv has one row per step plus the initial one, and
//    its values are those the run kept in memory;
//  - pressure_profile.csv holds, for every point, the values of the
//    histories at the profile time and their envelope (max and min);
//  - the pressure at the heel is the largest of the five in magnitude at the
//    end of the run (the water deepest there), and the one at the surface
//    point (z = 200 m, 2 m below the level) the smallest.

#include <archdam/analysis/simulation.h>
#include <archdam/geometry/arch_dam_shape.h>
#include <archdam/parameters/parameters.h>

#include <deal.II/base/utilities.h>

#include <fstream>

#include "archdam_tests.h"
#include "case_text.h"

using namespace archdam;
using archdam::testing::log;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const geometry::ArchDamGeometry          dam{geometry::ArchDamParameters{}};
  std::ostringstream                       points;
  const std::vector<double>                z = {0., 50., 100., 150., 200.};
  for (unsigned int i = 0; i < z.size(); ++i)
    points << (i ? "; " : "") << "p" << i << ": " << dam.crown_upstream_face(z[i]) - 0.5
           << ", 0, " << z[i];
  namespace case_text = testing::case_text;
  const std::string prm =
    case_text::coarse_arch_dam_mesh(4, "    set Number of blocks = 4\n    set Rock cell size = 120\n"
                                       "    set Water cell size = 100\n") +
    case_text::compressible_reservoir("  set Bottom reflection coefficient = 0.8\n"
                                      "  set Pressure points = " + points.str() +
                                      "\n  set Profile times = 0.1\n") +
    case_text::time_integration(0.01, 0.2) + case_text::el_centro_x() +
    case_text::quiet_output("run", 0);
  const Parameters p = parameters_from_string(prm);
  std::ostringstream   screen;
  analysis::Simulation sim(p, MPI_COMM_WORLD, screen);
  sim.run();
  bool ok = true;

  const auto &rows = sim.recorder<archdam::output::PressureRecorder>()->rows();
  ok &= testing::check_below("static stage: largest |p| at t = 0 [Pa]",
                             std::abs(*std::max_element(rows[0].begin() + 1, rows[0].end(),
                                                        [](double a, double b) {
                                                          return std::abs(a) < std::abs(b);
                                                        })),
                             1e-6);
  MPI_Barrier(MPI_COMM_WORLD);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::ifstream            csv("run/pressure_histories.csv");
      std::string              line;
      std::vector<std::string> lines;
      while (std::getline(csv, line))
        lines.push_back(line);
      log() << "pressure_histories.csv: " << lines.size() - 1 << " rows for "
            << rows.size() << " recorded steps: " << (lines.size() - 1 == rows.size() ? "yes" : "NO")
            << std::endl;
      double diff = 0.;
      for (unsigned int r = 0; r + 1 < lines.size(); ++r)
        {
          const auto v = dealii::Utilities::split_string_list(lines[r + 1], ',');
          for (unsigned int c = 0; c < v.size(); ++c)
            diff = std::max(diff, std::abs(std::stod(v[c]) - rows[r][c]) /
                                    std::max(1., std::abs(rows[r][c])));
        }
      ok &= testing::check_below("  largest relative difference to the values in memory", diff,
                                 1e-8);

      std::ifstream profile("run/pressure_profile.csv");
      std::getline(profile, line);
      log() << "pressure_profile.csv header: " << line << std::endl;
      unsigned int at = 0;
      for (unsigned int r = 0; r < rows.size(); ++r)
        if (std::abs(rows[r][0] - 0.1) < std::abs(rows[at][0] - 0.1))
          at = r;
      double profile_diff = 0.;
      for (unsigned int k = 0; k < z.size(); ++k)
        {
          std::getline(profile, line);
          const auto v  = dealii::Utilities::split_string_list(line, ',');
          double     hi = -1e300, lo = 1e300;
          for (const auto &row : rows)
            hi = std::max(hi, row[k + 1]), lo = std::min(lo, row[k + 1]);
          for (const auto &[column, value] :
               std::vector<std::pair<unsigned int, double>>{{4, rows[at][k + 1]}, {5, hi}, {6, lo}})
            profile_diff = std::max(profile_diff, std::abs(std::stod(v[column]) - value) /
                                                    std::max(1., std::abs(value)));
        }
      ok &= testing::check_below("  profile and envelope against the histories", profile_diff,
                                 1e-8);
    }
  const auto  &last = rows.back();
  std::vector<double> magnitude;
  for (unsigned int k = 1; k < last.size(); ++k)
    magnitude.push_back(std::abs(last[k]));
  const auto largest  = std::max_element(magnitude.begin(), magnitude.end()) - magnitude.begin();
  const auto smallest = std::min_element(magnitude.begin(), magnitude.end()) - magnitude.begin();
  log() << "largest |p| at the end at p" << largest << ", smallest at p" << smallest << ": "
        << (largest == 0 && smallest == 4 ? "yes" : "NO") << std::endl;
  log() << (ok ? "OK" : "FAILED") << std::endl;
}
