#include <archdam/base/interrupt.h>

#include <csignal>

#include <unistd.h>

namespace archdam::interrupt
{
  namespace
  {
    volatile std::sig_atomic_t armed = 0, asked = 0;

    extern "C" void
    on_signal(const int sig)
    {
      // the next signal ends the program at once
      std::signal(sig, SIG_DFL);
      if (!armed)
        {
          std::raise(sig);
          return;
        }
      asked = 1;
      static const char text[] =
        "\narchdam: interrupted: the step under way ends, then the results and a checkpoint are "
        "written (interrupt again to quit at once)\n";
      [[maybe_unused]] const auto written = ::write(2, text, sizeof(text) - 1);
    }
  } // namespace

  void
  catch_signals()
  {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
  }

  bool
  requested()
  {
    return asked != 0;
  }

  Armed::Armed()
  {
    asked = 0;
    armed = 1;
  }

  Armed::~Armed()
  {
    armed = 0;
  }
} // namespace archdam::interrupt
