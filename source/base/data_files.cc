#include <archdam/base/data_files.h>
#include <archdam/base/input_error.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>

// The data/ folder of the source tree, set by CMakeLists.txt for this file
// only (every other object file stays the same in any checkout).
#ifndef ARCHDAM_DEFAULT_DATA_DIR
#  error "ARCHDAM_DEFAULT_DATA_DIR (the default data folder) must be defined."
#endif

namespace archdam
{
  namespace
  {
    /// ARCHDAM_DATA_DIR, or "" if it is not set or empty.
    std::string
    data_directory_from_environment()
    {
      const char *value = std::getenv("ARCHDAM_DATA_DIR");
      return value == nullptr ? std::string() : std::string(value);
    }
  } // namespace



  std::string
  data_directory()
  {
    const std::string from_environment = data_directory_from_environment();
    return from_environment.empty() ? std::string(ARCHDAM_DEFAULT_DATA_DIR) : from_environment;
  }



  std::string
  find_input_file(const std::string &name,
                  const std::string &case_directory,
                  const std::string &what,
                  const std::string &first_folder)
  {
    namespace fs = std::filesystem;
    if (name.empty())
      throw InputError(what + ": no file given.");
    if (fs::path(name).is_absolute())
      return name;

    // A directory counts as found: its reader says that it is not a file.
    const auto exists = [](const std::string &file) {
      std::error_code ignored; // the non-throwing overload: false on error
      return fs::exists(file, ignored);
    };

    const std::string in_case = case_directory.empty() ?
                                  name :
                                  (fs::path(case_directory) / name).string();
    if (exists(in_case))
      return in_case;

    const std::string data    = data_directory();
    const std::string in_data = (fs::path(data) / name).string();
    if (exists(in_data))
      return in_data;

    const std::string data_origin = data_directory_from_environment().empty() ?
                                      "the data folder; ARCHDAM_DATA_DIR sets another" :
                                      "the data folder, from ARCHDAM_DATA_DIR";
    throw InputError(what + ": cannot find '" + name + "': it is neither in '" +
                     (case_directory.empty() ? std::string(".") : case_directory) + "' (" +
                     first_folder + ") nor in '" + data + "' (" + data_origin + ").");
  }
} // namespace archdam
