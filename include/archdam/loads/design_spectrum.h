#pragma once

#include <string>
#include <utility>
#include <vector>

/**
 * Target (design) acceleration spectra at 5 % damping, the input of the
 * artificial-motion generator and the reference drawn on response-spectrum
 * plots.
 */
namespace archdam::loads
{
  /**
   * S_a(T) = PGA * beta(T), with the amplification beta(T) either
   *
   *  - the design spectrum of the Chinese standard for the seismic design of
   *    hydraulic structures of hydropower projects, NB 35047-2015:
   *      beta = 1 + 10 (beta_max - 1) T         0    <= T <= 0.1 s (rising)
   *      beta = beta_max                         0.1 s < T <= T_g  (plateau)
   *      beta = beta_max (T_g / T)^0.6           T > T_g           (descent)
   *    and never below the floor 0.2 beta_max; beta_max = 2.50 for arch dams
   *    (2.00 gravity dams, 2.25 other hydraulic structures), T_g the
   *    characteristic period of the site (0.20 ... 0.90 s); or
   *  - a user table of (T, beta) points, linear between them and constant
   *    beyond the first and last points.
   */
  class TargetSpectrum
  {
  public:
    /**
     * The NB 35047-2015 spectrum for peak ground acceleration @p pga (m/s^2,
     * > 0), characteristic period @p characteristic_period (s, >= 0.1) and
     * plateau @p beta_max (>= 1). InputError for values outside these ranges.
     */
    static TargetSpectrum
    nb35047(const double pga,
            const double characteristic_period,
            const double beta_max = 2.5);

    /**
     * A table of (T in s, beta) points, T >= 0 strictly increasing, beta > 0,
     * at least 2 points; S_a = @p pga * beta. InputError otherwise.
     */
    static TargetSpectrum
    table(const double pga, const std::vector<std::pair<double, double>> &points);

    /// beta(T), the amplification over the PGA.
    double
    amplification(const double period) const;

    /// S_a(T) = PGA beta(T) in m/s^2.
    double
    acceleration(const double period) const;

    /// The PGA (S_a at T = 0 for the NB 35047 spectrum), in m/s^2.
    double
    pga() const;

    /// The same shape with the PGA multiplied by @p factor.
    TargetSpectrum
    scaled(const double factor) const;

    /// One line: "NB 35047-2015, PGA 0.300 g, T_g 0.40 s, beta_max 2.50".
    std::string
    description() const;

  private:
    TargetSpectrum() = default;

    bool                                   is_table     = false;
    double                                 peak         = 0.;
    double                                 t_g          = 0.;
    double                                 plateau      = 0.;
    std::vector<std::pair<double, double>> table_points = {};
  };

  /**
   * Parse a spectrum table written "T1: beta1; T2: beta2; ...", e.g.
   * "0: 1; 0.1: 2.5; 0.4: 2.5; 3: 0.6". InputError starting with @p context
   * for malformed text (the checks of TargetSpectrum::table come on top).
   */
  std::vector<std::pair<double, double>>
  parse_spectrum_table(const std::string &text, const std::string &context);
} // namespace archdam::loads
