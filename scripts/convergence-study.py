#!/usr/bin/python3
"""Mesh convergence study of the reference case (doc/convergence.md).

The reference case prm/paper_235m_dam.prm on a sequence of meshes, the same
motion and time step on each:

  coarse      Q1, 1 cell across each block, 1 through the thickness, 4 over the height
  q2-113      Q2, 1 x 1 x 3
  q2-224      Q2, 2 x 2 x 4 (the production mesh with fewer cells over the height:
              that direction measured from below)
  production  Q2, 2 x 2 x 6 (the case file as written)
  q2-236      Q2, 2 x 3 x 6 (the production mesh with three cells through the thickness)
  q2-326      Q2, 3 x 2 x 6 (the production mesh with three cells across each block)
  q2-229      Q2, 2 x 2 x 9 (the production mesh with more cells over the height)
  q2-2212     Q2, 2 x 2 x 12 (and twice the production mesh's cells over the height:
              the height direction's series 6, 9, 12 for the earthquake peaks)
  q2-239      Q2, 2 x 3 x 9 (the case's mesh with three cells through the thickness)
  q2-329      Q2, 3 x 2 x 9 (the case's mesh with three cells across each block;
              both on the short rock, MESH-extent050 below, against q2-229 there)
  q2-2215     Q2, 2 x 2 x 15 and
  q2-2218     Q2, 2 x 2 x 18: the height series continued on the short rock
              (MESH-extent050 below)
  fine        Q2, 3 x 3 x 9
  (rock and water cell sizes as in the case file: the rock and water meshes
  follow the dam's cells at the interfaces and grade to 45 m and 35 m away
  from it)
  rockNN      the q2-113 dam with the rock's cell size NN m instead of 45 m
              (the rock's own sensitivity: rock60, rock35; 30 m cells put
              a point of the MTF outside the rock at 5 ms)
  extentNN    the production mesh with the rock reaching NN/100 of the dam's
              height below the base, downstream and to the sides instead of
              one height (extent050, extent075); upstream it keeps one height,
              where a shorter rock puts a point of the MTF into the canyon's
              water at 5 ms
  MESH-extentNN  any mesh above with the rock reaching NN/100 of the dam's
              height as extentNN (q2-2218-extent050: the finest meshes of the
              height series on a rock that fits in memory; doc/convergence.md,
              "The height series on the short rock")

For each mesh up to six runs (each kept when its summary.json exists):

  dynamic         the case as it first shipped (static stage, then the motion;
                  the rock damped like the dam) up to --end-time, the static
                  field written (stresses at the crown)
  modal_massed    the first five modes of the grouted dam (joints glued) with
                  the compressible water on the massed rock
  modal_massless  the same on the massless rock (the dam-water modes alone)
  static          the static stage alone (the study's recorded static runs
                  used contact tolerances loosened to 1e-7 m and 1e-6, made
                  before the slip law's convergence test was corrected; the
                  defaults now give the same static openings to 4e-10 m,
                  doc/convergence.md)
  dynamic_relaxed the dynamic run from the static state by dynamic relaxation
  dynamic_rock_beta the same with the rock damped by its strain rate only (the
                  dam's Rayleigh beta, no mass term: doc/convergence.md, "The
                  earthquake peaks over the height with the rock's own damping")
                  (these dynamic runs with the joints' step impulse alone, as
                  they were made before the position correction)
  corrected_rock_beta dynamic_rock_beta with the position correction, the
                  joints' default scheme (doc/theory/joints.md §11): the case
                  as it now ships, from the relaxed static state
  relaxed         the static stage alone by dynamic relaxation (the load
                  ramped over 1 s in a damped transient, steps of 10 ms,
                  damping critical at 1.5 Hz, out of balance 1e-6): the one
                  static series that reaches every mesh (the one solve's
                  active set cycles on meshes with more cells over the height)

then the tables (Markdown) and one figure per quantity against the DOFs.

Usage (from the project root):
  /usr/bin/python3 scripts/convergence-study.py run MESH[,MESH...] [--what dynamic,modal_massed,modal_massless]
  /usr/bin/python3 scripts/convergence-study.py report [--figures doc/figures/convergence] [--window S]
options: --results DIR (default results/convergence), --archdam build/archdam,
         --end-time S (default 8: the window of every peak, doc/convergence.md),
"""
import argparse
import os
import subprocess
import sys
import time

MESHES = {
    # name: (degree, across each block, through thickness, over height)
    "coarse": (1, 1, 1, 4),
    "q2-113": (2, 1, 1, 3),
    "q2-224": (2, 2, 2, 4),
    "production": (2, 2, 2, 6),
    "q2-236": (2, 2, 3, 6),
    "q2-326": (2, 3, 2, 6),
    "q2-229": (2, 2, 2, 9),
    "q2-239": (2, 2, 3, 9),
    "q2-329": (2, 3, 2, 9),
    "q2-2212": (2, 2, 2, 12),
    "q2-2215": (2, 2, 2, 15),
    "q2-2218": (2, 2, 2, 18),
    "fine": (2, 3, 3, 9),
}
# uniformly refined Q2 meshes: observed orders and Richardson estimates
SERIES = ["q2-113", "production", "fine"]
# the height direction (6, 9 and 12 cells over the height): the earthquake
# peaks from the relaxed static state ("relaxed: " rows)
HEIGHT_SERIES = ["production", "q2-229", "q2-2212"]
RUNS = ["dynamic", "modal_massed", "modal_massless"]
# the height series on the rock reaching half the dam's height (memory: the
# 18-cell mesh on the whole rock would not fit), run as corrected_rock_beta
SHORT_ROCK_SERIES = [f"{m}-extent050" for m in ["production", "q2-229", "q2-2212", "q2-2215", "q2-2218"]]
# the two other directions on the case's mesh, on the same short rock: a third
# cell through the thickness and across each block
SHORT_ROCK_DIRECTIONS = ["q2-229-extent050", "q2-239-extent050", "q2-329-extent050"]


def extent_settings(percent):
    e = int(percent) / 100
    return [f"Mesh/Arch dam/Foundation {where}={e}"
            for where in ["depth", "extent downstream", "extent to the sides"]]


def mesh_settings(mesh):
    extra = []
    if "-extent" in mesh:
        mesh, percent = mesh.split("-extent")
        extra = extent_settings(percent)
    if mesh.startswith("rock"):
        # rockNN: the q2-113 dam with a rock cell size of NN m
        degree, nb, nt, nz = MESHES["q2-113"]
        extra.append(f"Mesh/Arch dam/Rock cell size={mesh[4:]}")
    elif mesh.startswith("extent"):
        degree, nb, nt, nz = MESHES["production"]
        extra = extent_settings(mesh[6:])
    else:
        degree, nb, nt, nz = MESHES[mesh]
    return [
        f"Finite element/Degree={degree}",
        f"Mesh/Arch dam/Cells across each block={nb}",
        f"Mesh/Arch dam/Cells through thickness={nt}",
        f"Mesh/Arch dam/Cells over height={nz}",
    ] + extra


def run_settings(what, end_time):
    # the study's first series solved the static stage in one solve, the
    # case's default until 2026-11-29
    one_solve = ["Contraction joints/Static solution=one solve"]
    if what == "static":
        return ["Analysis/Stages=static"] + one_solve
    r = "Contraction joints/Dynamic relaxation/"
    relaxation = [
        "Contraction joints/Static solution=dynamic relaxation",
        r + "Time step=0.01",
        r + "Frequency=1.5",
        r + "Loading time=1",
        r + "Tolerance=1e-6",
    ]
    if what == "relaxed":
        return ["Analysis/Stages=static"] + relaxation
    if what.startswith("dynamic") or what == "corrected_rock_beta":
        # the static state is written as the dynamic stage's first field
        dynamic = [f"Time integration/End time={end_time}", "Output/Field output interval=1000000"]
        # the study's first runs: the rock damped like the dam, as the case
        # was then
        rock_like_dam = ["Damping/Rock/Mode=same as the dam"]
        if what == "dynamic":
            return dynamic + one_solve + rock_like_dam
        # the rock without the mass term, which damps the incoming free
        # field (doc/theory/foundation.md §4); beta = 2 zeta / (w1 + w2) of
        # the case's damping (5 % at 2 and 15 Hz)
        rock_beta = [
            "Damping/Rock/Mode=coefficients",
            "Damping/Rock/Mass proportional coefficient=0",
            "Damping/Rock/Stiffness proportional coefficient=0.0009362",
        ]
        # the closures of the runs recorded then (doc/theory/joints.md §11)
        corrected = ["Contraction joints/Closure=velocities"]
        step_impulse_alone = corrected + ["Contraction joints/Position correction=false"]
        if what == "dynamic_relaxed":
            return dynamic + relaxation + rock_like_dam + step_impulse_alone
        if what == "dynamic_rock_beta":
            return dynamic + relaxation + rock_beta + step_impulse_alone
        if what == "corrected_rock_beta":
            return dynamic + relaxation + rock_beta + corrected
        sys.exit(f"unknown run {what}")
    foundation = "massed" if what == "modal_massed" else "massless"
    return [
        "Analysis/Stages=modal",
        "Contraction joints/Model=glued",
        f"Foundation/Model={foundation}",
        "Modal analysis/Number of modes=5",
        "Modal analysis/Write mode shapes=false",
    ]


def run(args, mesh, what):
    out = os.path.join(args.results, mesh, what)
    if os.path.exists(os.path.join(out, "summary.json")):
        print(f"{mesh}/{what}: kept ({out}/summary.json exists)")
        return
    os.makedirs(out, exist_ok=True)
    command = [args.archdam, "prm/paper_235m_dam.prm", "--set", f"Output/Directory={out}"]
    for s in mesh_settings(mesh) + run_settings(what, args.end_time):
        command += ["--set", s]
    # /usr/bin/time -v: the peak resident memory of the run
    command = ["/usr/bin/time", "-v", "-o", os.path.join(out, "time.txt")] + command
    print(f"{mesh}/{what}: running", flush=True)
    start = time.time()
    with open(os.path.join(out, "run.log"), "w") as log:
        status = subprocess.call(command, stdout=log, stderr=subprocess.STDOUT)
    print(f"{mesh}/{what}: exit {status} after {time.time() - start:.0f} s", flush=True)
    if status != 0:
        sys.exit(f"{mesh}/{what}: archdam failed; see {out}/run.log")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("command", choices=["run", "report"])
    p.add_argument("meshes", nargs="?", default=",".join(MESHES))
    p.add_argument("--what", default=",".join(RUNS))
    p.add_argument("--results", default="results/convergence")
    p.add_argument("--archdam", default="build/archdam")
    p.add_argument("--end-time", default="8")
    p.add_argument("--figures", default=None, help="report: write the figures here")
    p.add_argument("--window", default="8", help="report: the dynamic peaks over 0 to this time [s]")
    args = p.parse_args()
    if args.command == "run":
        for mesh in args.meshes.split(","):
            for what in args.what.split(","):
                run(args, mesh, what)
    else:
        import convergence_report

        convergence_report.report(args, MESHES, SERIES, HEIGHT_SERIES)
        convergence_report.short_rock_report(args, MESHES, SHORT_ROCK_SERIES)
        convergence_report.directions_report(args, MESHES, SHORT_ROCK_DIRECTIONS)


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    main()
