#pragma once

namespace archdam
{
  /// ArchDam's version: `git describe` of the checkout it was built from
  /// (generated at configure time, cmake/version.cc.in).
  const char *
  version();
} // namespace archdam
