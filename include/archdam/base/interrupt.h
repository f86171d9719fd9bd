#pragma once

namespace archdam
{
  /**
   * Ctrl-C (SIGINT) and SIGTERM during the dynamic stage end the run after
   * the step under way, with its results and a checkpoint written and a
   * message saying where they are and how to continue
   * (doc/user-guide.md, "When a run stops"). Outside the dynamic stage the
   * signals end the program at once, as without this handler; a second
   * signal always does.
   */
  namespace interrupt
  {
    /// Install the handler for SIGINT and SIGTERM (once, at the start of a run).
    void
    catch_signals();

    /// Whether a signal came while armed (and has not been cleared since).
    bool
    requested();

    /// Arms the handler for its lifetime: a signal then asks the run to stop
    /// after its step instead of ending the program.
    class Armed
    {
    public:
      Armed();
      ~Armed();
      Armed(const Armed &) = delete;
      Armed &
      operator=(const Armed &) = delete;
    };
  } // namespace interrupt
} // namespace archdam
