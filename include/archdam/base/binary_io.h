#pragma once

#include <archdam/base/input_error.h>
#include <archdam/base/types.h>

#include <deal.II/base/tensor.h>

#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace archdam::binary
{
  /**
   * The state a class saves into a checkpoint (output/checkpoint.h): plain
   * values, strings, vectors of them and the locally owned part of a
   * distributed Vector, in the machine's byte order, each container preceded
   * by its size. The checkpoint file carries a checksum over all of it, so a
   * short read here means a program that saves and loads different things,
   * not a damaged file; it is still an InputError, never garbage.
   */
  // Declared first so that each overload sees the others (a vector of pairs).
  template <typename T>
  void
  write(std::ostream &out, const std::vector<T> &v);
  template <typename T>
  void
  read(std::istream &in, std::vector<T> &v);
  template <typename A, typename B>
  void
  write(std::ostream &out, const std::pair<A, B> &x);
  template <typename A, typename B>
  void
  read(std::istream &in, std::pair<A, B> &x);

  template <typename T>
  void
  write(std::ostream &out, const T &value)
  {
    static_assert(std::is_trivially_copyable_v<T>);
    out.write(reinterpret_cast<const char *>(&value), sizeof(T));
  }

  template <typename T>
  void
  read(std::istream &in, T &value)
  {
    static_assert(std::is_trivially_copyable_v<T>);
    if (!in.read(reinterpret_cast<char *>(&value), sizeof(T)))
      throw InputError("Checkpoint: the saved state ends early (written by a different "
                       "version of the program?).");
  }

  void
  write(std::ostream &out, const std::string &s);
  void
  read(std::istream &in, std::string &s);

  void
  write(std::ostream &out, const std::vector<bool> &v);
  void
  read(std::istream &in, std::vector<bool> &v);

  /// The locally owned entries of @p v; load() requires the same layout.
  void
  write(std::ostream &out, const Vector &v);
  void
  read(std::istream &in, Vector &v);

  template <typename T>
  void
  write(std::ostream &out, const std::vector<T> &v)
  {
    write(out, static_cast<std::uint64_t>(v.size()));
    for (const auto &x : v)
      write(out, x);
  }

  template <typename T>
  void
  read(std::istream &in, std::vector<T> &v)
  {
    std::uint64_t n = 0;
    read(in, n);
    v.resize(n);
    for (auto &x : v)
      read(in, x);
  }

  template <typename A, typename B>
  void
  write(std::ostream &out, const std::pair<A, B> &x)
  {
    write(out, x.first);
    write(out, x.second);
  }

  template <typename A, typename B>
  void
  read(std::istream &in, std::pair<A, B> &x)
  {
    read(in, x.first);
    read(in, x.second);
  }

  /// Several values in order.
  template <typename... T>
  void
  write_all(std::ostream &out, const T &...values)
  {
    (write(out, values), ...);
  }

  template <typename... T>
  void
  read_all(std::istream &in, T &...values)
  {
    (read(in, values), ...);
  }
} // namespace archdam::binary
