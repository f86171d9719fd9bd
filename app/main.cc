// The `archdam` command: MPI set-up and the command line (see
// include/archdam/application/command_line.h). Errors are reported there.
#include <archdam/application/command_line.h>

#include <deal.II/base/mpi.h>

#include <iostream>

int
main(int argc, char **argv)
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      return archdam::run_command_line(argc, argv, std::cout, std::cerr);
    }
  catch (const std::exception &e)
    {
      std::cerr << "archdam: fatal error: " << e.what() << std::endl;
      return 2;
    }
}
