// Fuzz target (libFuzzer) for the ground-motion readers (loads/record_io):
// every input, however malformed, must either give a valid record or end in
// InputError with a message. A valid record has at least two samples, as
// many times as values, strictly increasing finite times and finite
// accelerations. Anything else (another exception, a crash, a sanitizer
// report, a record breaking these rules) is a finding.
#include <archdam/loads/record_io.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

namespace
{
  void
  check(const archdam::loads::AccelerationRecord &r)
  {
    bool ok = r.times.size() >= 2 && r.times.size() == r.values.size();
    for (std::size_t k = 0; ok && k < r.times.size(); ++k)
      ok = std::isfinite(r.times[k]) && std::isfinite(r.values[k]) &&
           (k == 0 || r.times[k] > r.times[k - 1]);
    if (!ok)
      std::abort();
  }

  template <typename Read>
  void
  try_reader(const std::string &text, const Read &read)
  {
    std::istringstream in(text);
    try
      {
        check(read(in));
      }
    catch (const archdam::InputError &e)
      {
        if (std::string(e.what()).empty())
          std::abort();
      }
  }
} // namespace

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  using namespace archdam::loads;
  const std::string text(reinterpret_cast<const char *>(data), size);
  try_reader(text, [](std::istream &in) { return read_at2(in, "fuzz.AT2", 1.); });
  try_reader(text, [](std::istream &in) { return read_two_column(in, "fuzz.csv", 0.01, 2.); });
  try_reader(text,
             [](std::istream &in) { return read_single_column(in, "fuzz.txt", 0.01, 9.81, 1.); });
  return 0;
}
