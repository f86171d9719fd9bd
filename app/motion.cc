// The `archdam-motion` command: generate, convert, scale and inspect ground
// motions (see include/archdam/application/motion_command.h and `--help`).
// MPI set-up here; errors are reported there (exit code 1 for bad input).
#include <archdam/application/motion_command.h>

#include <deal.II/base/mpi.h>

#include <iostream>

int
main(int argc, char **argv)
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      return archdam::run_motion_command(argc, argv, std::cout, std::cerr);
    }
  catch (const std::exception &e)
    {
      std::cerr << "archdam-motion: fatal error: " << e.what() << std::endl;
      return 2;
    }
}
