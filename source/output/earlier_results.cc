#include <archdam/base/input_error.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/output/earlier_results.h>

#include <algorithm>
#include <filesystem>
#include <regex>

namespace archdam::output
{
  std::vector<std::string>
  earlier_results(const std::string &directory)
  {
    // What the writers of output/ name (summary.cc, histories.cc,
    // joint_output.cc, monitor_histories.cc, pressure_recorder.cc,
    // stress_envelope.cc, field_writer.cc, mesh_writer.cc, checkpoint.cc).
    static const std::regex ours(
      R"((summary\.json|report\.html|suite\.(csv|json)|histories\.(csv|h5)|checkpoint(\.old)?)"
      R"(|(solution|modes|mesh|joints?|stress|pressure)(_.*)?\.(vtu|pvtu|pvd|h5|xdmf|csv)))");
    std::vector<std::string> names;
    std::error_code          ec;
    for (const auto &entry : std::filesystem::directory_iterator(directory, ec))
      if (const std::string name = entry.path().filename().string();
          std::regex_match(name, ours))
        names.push_back(name);
    std::sort(names.begin(), names.end());
    return names;
  }

  void
  handle_earlier_results(const std::string &directory, const EarlierResults policy,
                         const MPI_Comm comm)
  {
    if (policy == EarlierResults::keep)
      return;
    on_rank_zero(comm, [&] {
      const auto names = earlier_results(directory);
      if (names.empty())
        return;
      if (policy == EarlierResults::refuse)
        {
          std::string list;
          for (unsigned int k = 0; k < std::min<std::size_t>(names.size(), 5); ++k)
            list += (k ? ", " : "") + names[k];
          if (names.size() > 5)
            list += " and " + std::to_string(names.size() - 5) + " more";
          throw InputError("Output/Directory '" + directory + "' holds the results of an "
                           "earlier run (" + list + "): choose another directory, or set "
                           "Output/Earlier results = replace to remove them (or keep, to "
                           "write over them and leave the rest).");
        }
      for (const auto &name : names)
        {
          std::error_code ec;
          std::filesystem::remove_all(directory + "/" + name, ec);
          if (ec)
            throw InputError("Output/Directory: cannot remove the earlier run's '" + directory +
                             "/" + name + "': " + ec.message() + ".");
        }
    });
  }
} // namespace archdam::output
