#!/usr/bin/python3
"""What the rock's damping does to the free field (doc/theory/foundation.md §4).

The massed foundation takes the free field of the undamped half-space on its
outer boundary, and inside the rock the waves travel through the model's
damping D = alpha M + beta K (doc/theory/solid.md §4). For vertically
propagating SV waves in a rock column of height H (bottom to free surface)
damped with (alpha, beta), over the undamped half-space from which the
incident wave comes, the motion at depth s below the free surface is, for
exp(i w t),
    u(s) = U(s) / (2 A) * g^(w),
with U(s) the motion at depth s of the layer solution that is 1 at the
surface with zero traction there, and A the upgoing amplitude it implies in
the half-space (the layer matrices of the test foundation_column, part C,
which checks this closed form against the finite element column). The
undamped free field at depth s is g^(w) exp(-i w H/c) cos(w s / c).

usage: free-field-damping.py MOTION.csv [MOTION.csv ...] --rock E NU RHO
       --height H --depth S [--case NAME ALPHA BETA]...
MOTION.csv: two columns, time [s] and acceleration (as `archdam-motion ...
--csv` writes it). Prints, for each damping case, the ratio of the damped to
the undamped free field at depth S: of the transfer function's modulus at
1, 2, 5, 10 and 20 Hz, and of the peak acceleration of each motion.
"""
import argparse
import numpy as np


def layer_transfer(w, G, rho, c, H, s, alpha, beta):
    """U(s) / (2 A): the damped column's response at depth s per control motion
    of the undamped half-space's incident wave (w > 0)."""
    Gs = G * (1 + 1j * w * beta)
    k = np.sqrt(rho * (w * w - 1j * w * alpha) / Gs)
    # from (u, tau) = (1, 0) at the surface down to depth h
    u_s = np.cos(k * s)
    u_b = np.cos(k * H)
    tau_b = Gs * k * np.sin(k * H)
    A = 0.5 * (u_b + 1j * tau_b / (w / c * G))
    return u_s / (2 * A)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("motions", nargs="+")
    ap.add_argument("--rock", nargs=3, type=float, required=True, metavar=("E", "NU", "RHO"))
    ap.add_argument("--height", type=float, required=True)
    ap.add_argument("--depth", type=float, required=True)
    ap.add_argument("--case", nargs=3, action="append", default=[],
                    metavar=("NAME", "ALPHA", "BETA"))
    a = ap.parse_args()
    E, nu, rho = a.rock
    G = E / (2 * (1 + nu))
    c = np.sqrt(G / rho)
    H, s = a.height, a.depth

    def undamped(w):
        return np.exp(-1j * w * H / c) * np.cos(w * s / c)

    print(f"rock: c_s = {c:.0f} m/s; column {H:g} m, depth {s:g} m below the free surface")
    freqs = [1., 2., 5., 10., 20.]
    head = " | ".join(f"{f:g} Hz" for f in freqs)
    names = [m.split("/")[-1] for m in a.motions]
    print(f"| damping (alpha [1/s], beta [s]) | {head} | " +
          " | ".join(f"peak acc. {n}" for n in names) + " |")
    print("|---" * (1 + len(freqs) + len(names)) + "|")
    records = []
    for m in a.motions:
        d = np.loadtxt(m, delimiter=",", comments="#")
        t, acc = d[:, 0], d[:, 1]
        dt = t[1] - t[0]
        n = 1
        while n < 4 * len(acc):
            n *= 2
        records.append((acc, dt, n))
    for name, alpha, beta in a.case:
        alpha, beta = float(alpha), float(beta)
        ratios = [abs(layer_transfer(2 * np.pi * f, G, rho, c, H, s, alpha, beta) /
                      undamped(2 * np.pi * f)) for f in freqs]
        peaks = []
        for acc, dt, n in records:
            spec = np.fft.rfft(acc, n)
            w = 2 * np.pi * np.fft.rfftfreq(n, dt)
            w[0] = 1e-9
            damped = np.fft.irfft(spec * layer_transfer(w, G, rho, c, H, s, alpha, beta), n)
            ref = np.fft.irfft(spec * undamped(w), n)
            peaks.append(np.max(np.abs(damped)) / np.max(np.abs(ref)))
        print(f"| {name} ({alpha:g}, {beta:g}) | " + " | ".join(f"{r:.3f}" for r in ratios) +
              " | " + " | ".join(f"{p:.3f}" for p in peaks) + " |")


if __name__ == "__main__":
    main()
