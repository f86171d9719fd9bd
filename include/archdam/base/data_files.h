#pragma once

#include <string>

namespace archdam
{
  /**
   * The program's data folder, where input files named by a relative path
   * are looked for after the case file's own folder (the ground-motion
   * records shipped in data/ground_motions/, for instance): the environment
   * variable ARCHDAM_DATA_DIR if it is set and not empty, else the data/
   * folder of the source tree the program was built from.
   */
  std::string
  data_directory();

  /**
   * The file to read for the input file @p name given by the parameter
   * @p what (e.g. "Ground motion/Component x/File"). The one search path of
   * every input file a case names (doc/user-guide.md, "Where input files are
   * found"):
   *
   * - an absolute @p name is returned as it is (whoever reads it reports a
   *   file that is not there);
   * - a relative @p name is looked for in @p case_directory ("" is the
   *   working directory), then in data_directory(); the first place where it
   *   exists is returned, as `case_directory/name` or `data/name`.
   *
   * @p first_folder says what @p case_directory is, for the message.
   * Throws InputError naming @p what, @p name and every folder searched if
   * the file is in none of them.
   */
  std::string
  find_input_file(const std::string &name,
                  const std::string &case_directory,
                  const std::string &what,
                  const std::string &first_folder = "the case file's folder");
} // namespace archdam
