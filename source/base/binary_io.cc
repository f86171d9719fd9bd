#include <archdam/base/binary_io.h>

#include <petscvec.h>

namespace archdam::binary
{
  namespace
  {
    [[noreturn]] void
    ends_early()
    {
      throw InputError("Checkpoint: the saved state ends early (written by a different "
                       "version of the program?).");
    }
  } // namespace

  void
  write(std::ostream &out, const std::string &s)
  {
    write(out, static_cast<std::uint64_t>(s.size()));
    out.write(s.data(), s.size());
  }

  void
  read(std::istream &in, std::string &s)
  {
    std::uint64_t n = 0;
    read(in, n);
    s.resize(n);
    if (!in.read(s.data(), n))
      ends_early();
  }

  void
  write(std::ostream &out, const std::vector<bool> &v)
  {
    write(out, std::vector<char>(v.begin(), v.end()));
  }

  void
  read(std::istream &in, std::vector<bool> &v)
  {
    std::vector<char> c;
    read(in, c);
    v.assign(c.begin(), c.end());
  }

  void
  write(std::ostream &out, const Vector &v)
  {
    const PetscScalar *x = nullptr;
    PetscInt           n = 0;
    VecGetLocalSize(v, &n);
    VecGetArrayRead(v, &x);
    write(out, static_cast<std::uint64_t>(n));
    out.write(reinterpret_cast<const char *>(x), n * sizeof(PetscScalar));
    VecRestoreArrayRead(v, &x);
  }

  void
  read(std::istream &in, Vector &v)
  {
    std::uint64_t n = 0;
    read(in, n);
    PetscInt local = 0;
    VecGetLocalSize(v, &local);
    if (n != static_cast<std::uint64_t>(local))
      throw InputError("Checkpoint: a saved field has " + std::to_string(n) +
                       " entries on this process, the model has " + std::to_string(local) +
                       " (a different mesh or partition).");
    PetscScalar *x  = nullptr;
    VecGetArray(v, &x);
    const bool ok = static_cast<bool>(
      in.read(reinterpret_cast<char *>(x), n * sizeof(PetscScalar)));
    VecRestoreArray(v, &x);
    if (!ok)
      ends_early();
  }
} // namespace archdam::binary
