// The table of bad input (doc/bad-input.md, issue "reliability", must show 3)
// is what the error tests check today: regenerating it from their expected
// outputs (scripts/make-bad-input-table.py) gives the shipped file, so every
// row names a case a test runs and the message it checks, and no case of
// those tests is missing from the table.

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

int
main()
{
  std::string generated;
  if (FILE *pipe = popen("/usr/bin/python3 " SOURCE_DIR "/../scripts/make-bad-input-table.py "
                         "--print",
                         "r"))
    {
      char   buffer[4096];
      size_t n;
      while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0)
        generated.append(buffer, n);
      pclose(pipe);
    }
  std::ifstream     file(SOURCE_DIR "/../doc/bad-input.md");
  std::stringstream shipped;
  shipped << file.rdbuf();

  unsigned int       rows = 0;
  std::istringstream lines(shipped.str());
  for (std::string line; std::getline(lines, line);)
    rows += line.rfind("| ", 0) == 0 && line.rfind("| input |", 0) != 0;
  std::cout << "doc/bad-input.md has more than 100 rows: " << (rows > 100 ? "yes" : "NO")
            << "\ndoc/bad-input.md matches the error tests' outputs: "
            << (!generated.empty() && generated == shipped.str() ?
                  "yes" :
                  "NO (run scripts/make-bad-input-table.py)")
            << std::endl;
}
