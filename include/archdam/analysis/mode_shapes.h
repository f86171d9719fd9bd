#pragma once

#include <archdam/analysis/modal_analysis.h>
#include <archdam/fe/fe_space.h>

#include <string>

namespace archdam::analysis
{
  /**
   * The mode shapes of a modal stage for ParaView: one VTU piece set per mode
   * (`modes_NNNNN.pvtu`, the mass-normalized displacement field `mode_shape`
   * and the material id) and `modes.pvd`, whose "time" is the mode number, so
   * that ParaView's time control steps through the modes. The shapes must be
   * complete (constraints distributed).
   */
  void
  write_mode_shapes(const std::string &directory, const fe::FESpace &space,
                    const NaturalModes &modes);
} // namespace archdam::analysis
