"""Render a results directory of ArchDam in ParaView and save a PNG.

    xvfb-run -a pvpython scripts/paraview-screenshot.py RESULTS_DIR OUT.png \
        [--time T] [--field major_principal_stress|displacement] \
        [--title TEXT] [--size 1400x900] [--rock-opacity A]

Loads RESULTS_DIR/solution.pvd and RESULTS_DIR/joints_dynamic.pvd with
ParaView's PVD readers, goes to the field output time closest to the largest
joint opening of the dynamic stage (summary.json, "dynamic/joints/joint k/peak
opening"; without summary.json the output time with the largest opening in
the joint series), and draws the dam seen from downstream: the dam blocks
(material id >= 10) coloured by the major principal stress in MPa (tension
positive; the displacement magnitude in mm if the stress is absent), the
joint node pairs coloured by their opening in mm, and the rock around the
dam, cut at the downstream end of the dam so that the canyon's section frames
it. The water is left out.

pvpython and pvbatch of Debian's ParaView render through X: run them under
xvfb-run on a machine without a display. Only Debian's paraview,
python3-paraview (pvpython) and xvfb packages are needed; the project itself
does not depend on them.
"""

import argparse
import json
import math
import os
import sys

from paraview.simple import (AppendDatasets, Calculator, CleantoGrid, Clip, ColorBy,
                             Delaunay2D, ExtractSurface, FeatureEdges,
                             GetActiveViewOrCreate, GetAnimationScene,
                             GetColorTransferFunction, GetScalarBar, Hide, PVDReader,
                             Render, SaveScreenshot, Show, Text, Threshold, Tube)

DAM_MATERIAL_MIN = 10  # dam block k has material id 10 + k, rock 1, water 2
ROCK_MATERIAL = 1


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("results", help="results directory of a run (Output/Directory)")
    p.add_argument("png", help="PNG file to write")
    p.add_argument("--time", type=float, default=None,
                   help="time to show [s] (default: the largest joint opening)")
    p.add_argument("--field", default=None,
                   help="dam field: major_principal_stress (default) or displacement")
    p.add_argument("--title", default=None, help="first title line (default: the case name)")
    p.add_argument("--size", default="1400x900", help="image size WIDTHxHEIGHT in pixels")
    p.add_argument("--rock-opacity", type=float, default=1.0,
                   help="opacity of the rock, 0 hides it (default 1)")
    return p.parse_args()


def threshold(source, array, lower, upper):
    t = Threshold(Input=source)
    t.Scalars = ["POINTS", array]
    # ParaView 5.10 and later: LowerThreshold/UpperThreshold; before: ThresholdRange.
    if hasattr(t, "LowerThreshold"):
        t.LowerThreshold = lower
        t.UpperThreshold = upper
        t.ThresholdMethod = "Between"
    else:
        t.ThresholdRange = [lower, upper]
    return t


def colour_bar(lut, view, title, position, label_format):
    """A vertical colour bar at position (view fractions), dark text."""
    bar = GetScalarBar(lut, view)
    bar.Title = title
    bar.HorizontalTitle = 1
    bar.ComponentTitle = ""
    bar.Orientation = "Vertical"
    bar.WindowLocation = "Any Location"
    bar.Position = position
    bar.ScalarBarLength = 0.5
    bar.TitleFontSize = 18
    bar.LabelFontSize = 16
    bar.TitleColor = [0.1, 0.1, 0.1]
    bar.LabelColor = [0.1, 0.1, 0.1]
    bar.RangeLabelFormat = label_format
    bar.Visibility = 1
    return bar


def nearest(values, t):
    return min(values, key=lambda v: abs(v - t))


def peak_opening_from_summary(results):
    """(value [m], time [s], joint name) of the largest dynamic joint opening, or None."""
    path = os.path.join(results, "summary.json")
    if not os.path.isfile(path):
        return None
    with open(path) as f:
        summary = json.load(f)
    joints = summary.get("dynamic", {}).get("joints", {})
    best = None
    for name, j in joints.items():
        v = j.get("peak opening [m]")
        t = j.get("peak opening time [s]")
        if v is not None and t is not None and (best is None or v > best[0]):
            best = (v, t, name)
    return best


def summary_case(results):
    path = os.path.join(results, "summary.json")
    if os.path.isfile(path):
        with open(path) as f:
            return json.load(f).get("case")
    return None


def main():
    args = parse_args()
    results = os.path.abspath(args.results)
    width, height = (int(v) for v in args.size.lower().split("x"))

    solution_pvd = os.path.join(results, "solution.pvd")
    joints_pvd = os.path.join(results, "joints_dynamic.pvd")
    if not os.path.isfile(solution_pvd):
        sys.exit("no solution.pvd in " + results)
    solution = PVDReader(FileName=solution_pvd)
    joints = PVDReader(FileName=joints_pvd) if os.path.isfile(joints_pvd) else None

    point_arrays = solution.PointData.keys()
    print("solution.pvd point arrays:", ", ".join(point_arrays))
    if joints is not None:
        print("joints_dynamic.pvd point arrays:", ", ".join(joints.PointData.keys()))
    times = list(solution.TimestepValues) or [0.0]

    # --- the time to show ---------------------------------------------------
    peak = peak_opening_from_summary(results)
    note = ""
    if args.time is not None:
        time = nearest(times, args.time)
    elif peak is not None:
        time = nearest(times, peak[1])
        note = "largest joint opening %.2f mm (%s) at t = %.3f s" % (
            peak[0] * 1e3, peak[2], peak[1])
    elif joints is not None and "opening" in joints.PointData.keys():
        best = None
        for t in joints.TimestepValues:
            joints.UpdatePipeline(t)
            v = joints.PointData["opening"].GetRange()[1]
            if best is None or v > best[0]:
                best = (v, t)
        time = nearest(times, best[1])
        note = "largest joint opening at the output times: %.2f mm" % (best[0] * 1e3)
    else:
        time = times[int(0.75 * (len(times) - 1))]
    print("showing t = %g s %s" % (time, ("(" + note + ")") if note else ""))

    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = time

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [width, height]
    view.ViewTime = time
    view.OrientationAxesVisibility = 1
    view.OrientationAxesLabelColor = [0.1, 0.1, 0.1]
    view.Background = [1.0, 1.0, 1.0]
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    if hasattr(view, "BackgroundColorMode"):
        view.BackgroundColorMode = "Single Color"
    view.EnableRenderOnInteraction = 0
    if hasattr(view, "OrientationAxesInteractivity"):
        view.OrientationAxesInteractivity = 0

    # --- the dam ------------------------------------------------------------
    dam = threshold(solution, "material_id", DAM_MATERIAL_MIN, 1e6)
    field = args.field
    if field is None:
        field = ("major_principal_stress" if "major_principal_stress" in point_arrays
                 else "displacement")
    if field == "major_principal_stress":
        dam_field = Calculator(Input=dam, ResultArrayName="s1 [MPa]",
                               Function="major_principal_stress*1e-6")
        label, unit_name = "s1 [MPa]", "Major principal\nstress [MPa]\n(tension +)"
    elif field == "displacement":
        dam_field = Calculator(Input=dam, ResultArrayName="|u| [mm]",
                               Function="mag(displacement)*1e3")
        label, unit_name = "|u| [mm]", "Displacement\nmagnitude [mm]"
    else:
        sys.exit("unknown --field " + field)
    dam_surface = ExtractSurface(Input=dam_field)
    dam_display = Show(dam_surface, view)
    dam_display.SetRepresentationType("Surface With Edges")
    dam_display.EdgeColor = [0.25, 0.25, 0.25]
    dam_display.Ambient = 0.25
    dam_display.Diffuse = 0.85
    if hasattr(dam_display, "LineWidth"):
        dam_display.LineWidth = 1.0
    ColorBy(dam_display, ("POINTS", label))
    dam_surface.UpdatePipeline(time)
    lo, hi = dam_surface.PointData[label].GetRange()
    lut = GetColorTransferFunction(label)
    if field == "major_principal_stress":
        lut.ApplyPreset("Cool to Warm", True)
        bound = max(abs(lo), abs(hi))
        bound = math.ceil(bound * 2.0) / 2.0  # to 0.5 MPa
        lut.RescaleTransferFunction(-bound, bound)
    else:
        lut.ApplyPreset("Inferno (matplotlib)", True)
        lut.RescaleTransferFunction(lo, hi)
    lut.AutomaticRescaleRangeMode = "Never"
    dam_bar = colour_bar(lut, view, unit_name, [0.87, 0.25], "%-#.2f")
    dam_bar.AddRangeLabels = 1

    # --- the rock as context ------------------------------------------------
    # The VTU cells do not share points (every cell carries its own), so merge
    # them before taking the surface; cut the rock downstream of the dam so
    # that the canyon's section frames the dam.
    dam.UpdatePipeline(time)
    db = dam.GetDataInformation().GetBounds()
    rock = CleantoGrid(Input=threshold(solution, "material_id", ROCK_MATERIAL, ROCK_MATERIAL))
    rock_cut = Clip(Input=rock)
    rock_cut.ClipType = "Box"
    rock_cut.ClipType.UseReferenceBounds = 0
    margin = 0.2 * (db[5] - db[4])
    rock_cut.ClipType.Position = [db[0] - 2.0 * margin, db[2] - margin, db[4] - 0.35 * margin]
    rock_cut.ClipType.Length = [db[1] + 1.0 - (db[0] - 2.0 * margin), db[3] - db[2] + 2.0 * margin,
                                db[5] - db[4] + 2.0 * margin]
    if hasattr(rock_cut, "Exact"):
        rock_cut.Exact = 1
    rock_cut.Invert = 1
    rock_surface = ExtractSurface(Input=rock_cut)
    rock_display = Show(rock_surface, view)
    rock_display.ColorArrayName = ["POINTS", ""]
    rock_display.AmbientColor = rock_display.DiffuseColor = [0.80, 0.78, 0.74]
    rock_display.Opacity = args.rock_opacity
    if args.rock_opacity <= 0.0:
        Hide(rock_surface, view)
    rock_display.Specular = 0.0

    # --- the joints -----------------------------------------------------------
    shown_opening = 0.0
    if joints is not None:
        opening = Calculator(Input=joints, ResultArrayName="opening [mm]", Function="opening*1e3")
        # The joint output holds one vertex per node pair. Join the pairs of each
        # joint into a surface (the joint plane) and draw its outline, which runs
        # along the dam faces, coloured by the opening.
        joints.UpdatePipeline(time)
        n_joints = int(round(joints.PointData["joint"].GetRange()[1])) + 1 \
            if "joint" in joints.PointData.keys() else 0
        strips = []
        for k in range(n_joints):
            one = threshold(opening, "joint", k - 0.25, k + 0.25)
            strips.append(Delaunay2D(Input=one, ProjectionPlaneMode="Best-Fitting Plane"))
        outline_display = None
        if strips:
            outlines = FeatureEdges(Input=ExtractSurface(Input=AppendDatasets(Input=strips)))
            outlines.BoundaryEdges = 1
            outlines.FeatureEdges = 0
            outlines.NonManifoldEdges = 0
            outlines.ManifoldEdges = 0
            tubes = Tube(Input=outlines)
            tubes.Radius = 1.5
            tubes.NumberofSides = 12
            outline_display = Show(tubes, view)
            ColorBy(outline_display, ("POINTS", "opening [mm]"))
        pairs_display = Show(opening, view)
        pairs_display.SetRepresentationType("Points")
        pairs_display.PointSize = 9
        pairs_display.RenderPointsAsSpheres = 1
        ColorBy(pairs_display, ("POINTS", "opening [mm]"))
        olut = GetColorTransferFunction("opening [mm]")
        opening.UpdatePipeline(time)
        omax = opening.PointData["opening [mm]"].GetRange()[1]
        shown_opening = omax
        omax = max(0.5, math.ceil(omax * 2.0) / 2.0)
        # closed pairs light grey, open ones from yellow-green to dark green:
        # distinct from the blue-red of the dam's stress.
        olut.ColorSpace = "RGB"
        olut.RGBPoints = [0.0, 0.80, 0.80, 0.80,
                          0.02 * omax, 0.85, 0.90, 0.35,
                          0.5 * omax, 0.20, 0.65, 0.25,
                          omax, 0.00, 0.27, 0.10]
        olut.RescaleTransferFunction(0.0, omax)
        olut.AutomaticRescaleRangeMode = "Never"
        colour_bar(olut, view, "Joint opening\n[mm]", [0.04, 0.25], "%-#.1f")

    # --- titles -------------------------------------------------------------
    case = args.title or summary_case(results) or os.path.basename(results.rstrip("/"))
    title = Text(Text="%s, t = %.2f s" % (case, time))
    title_display = Show(title, view)
    title_display.WindowLocation = "Upper Center"
    title_display.FontSize = 24
    title_display.Color = [0.05, 0.05, 0.05]
    subtitle_lines = ["View from downstream; %s; water hidden." % (
        "rock hidden" if args.rock_opacity <= 0.0 else "rock cut at the downstream end of the dam")]
    if joints is not None:
        subtitle_lines.append("Joints: node pairs and joint edges; largest opening shown %.2f mm."
                              % shown_opening)
    if note:
        subtitle_lines.append(note[0].upper() + note[1:] + "; field output every %.3g s." % (
            times[1] - times[0] if len(times) > 1 else 0.0))
    subtitle = Text(Text="\n".join(subtitle_lines))
    subtitle_display = Show(subtitle, view)
    subtitle_display.WindowLocation = "Lower Left Corner"
    subtitle_display.FontSize = 15
    subtitle_display.Justification = "Left"
    subtitle_display.Color = [0.2, 0.2, 0.2]

    # --- camera: from downstream (+x), a little above the crest -------------
    Render(view)  # the first render resets the camera: set it afterwards
    dam_surface.UpdatePipeline(time)
    b = dam_surface.GetDataInformation().GetBounds()
    centre = [0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), b[4] + 0.40 * (b[5] - b[4])]
    span = max(b[3] - b[2], b[5] - b[4])
    view.CameraFocalPoint = centre
    direction = [1.0, -0.33, 0.38]  # downstream, a little to the left bank, above
    norm = math.sqrt(sum(c * c for c in direction))
    distance = 3.6 * span  # the dam fills about half the width at a 22 degree view angle
    view.CameraPosition = [c + distance * d / norm for c, d in zip(centre, direction)]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraParallelProjection = 0
    view.CameraViewAngle = 22

    Render(view)
    SaveScreenshot(os.path.abspath(args.png), view, ImageResolution=[width, height],
                   TransparentBackground=0)
    print("wrote", args.png)


if __name__ == "__main__":
    main()
