#!/usr/bin/python3
"""Read a PVD time series written by ArchDam with Debian's VTK (python3-vtk9)
and check it against what the caller expects (tests/vtk_output.cc).

The PVD itself is XML: it is parsed here with the standard library, and every
dataset it names is read by VTK's own XML readers, vtkXMLPUnstructuredGridReader
for a .pvtu record (which reads its .vtu pieces) and vtkXMLUnstructuredGridReader
for a .vtu file, exactly as ParaView opens them. Checks:
  - the datasets' times are the expected ones (the output interval times dt);
  - every dataset loads without a VTK error, with the expected number of
    pieces, cells and points, and every expected point-data array with its
    number of components and one tuple per point;
  - optional: the set of material ids over all points (--materials), and
    value checks against closed forms (--column, --joint-plane, --water),
    described at each function below.
Prints one verdict per check ("...: yes" or "...: NO") and nothing that
depends on the number of MPI processes; exits 1 if VTK is missing.

usage: vtk_output.py SERIES.pvd --cells N --points N --pieces N
                     --times T0,T1,... --arrays NAME:COMPONENTS,...
                     [--materials ID,...] [--column H,RHO,G,E,DT]
                     [--joint-plane Y,RHO,G,H] [--water]
"""

import argparse
import math
import os
import sys
import xml.etree.ElementTree as ElementTree

try:
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkIOXML import (vtkXMLPUnstructuredGridReader,
                                     vtkXMLUnstructuredGridReader)
    from vtkmodules.util.numpy_support import vtk_to_numpy
    import numpy
except ImportError as error:
    print("VTK for Python is missing (" + str(error) + "): install python3-vtk9, "
          "e.g. with scripts/install-dependencies.sh")
    sys.exit(1)


def verdict(text, ok):
    print(text + ": " + ("yes" if ok else "NO"))
    return ok


class ErrorObserver:
    """Collects the error events of a VTK reader (VTK reports them there, not
    through an exception)."""

    def __init__(self):
        self.messages = []

    def __call__(self, caller, event):
        self.messages.append(event)


def read_dataset(path):
    """The unstructured grid in @p path (.vtu or .pvtu), its number of pieces
    and VTK's error events while reading it."""
    if path.endswith(".pvtu"):
        reader = vtkXMLPUnstructuredGridReader()
    else:
        reader = vtkXMLUnstructuredGridReader()
    errors = ErrorObserver()
    reader.AddObserver(vtkCommand.ErrorEvent, errors)
    reader.GetExecutive().AddObserver(vtkCommand.ErrorEvent, errors)
    reader.SetFileName(path)
    reader.Update()
    pieces = reader.GetNumberOfPieces() if path.endswith(".pvtu") else 1
    return reader.GetOutput(), pieces, errors.messages


def point_array(grid, name):
    return vtk_to_numpy(grid.GetPointData().GetArray(name))


def check_column(grid, H, rho, g, E, dt):
    """Self-weight of a laterally free column with Poisson's ratio 0 fixed at
    z = 0 (tests/gravity_column.cc): u = (0, 0, -(rho g / E)(H z - z^2 / 2)),
    sigma_zz = -rho g (H - z), all other stresses 0, exact for quadratic
    elements; the dynamic stage starts from this equilibrium at rest without
    ground motion, so it stays (velocity and acceleration 0). Returns the
    largest relative errors."""
    z = vtk_to_numpy(grid.GetPoints().GetData())[:, 2]
    u = point_array(grid, "displacement")
    stress = point_array(grid, "stress")
    u_scale = rho * g * H * H / (2 * E)
    s_scale = rho * g * H
    u_z = -(rho * g / E) * (H * z - z * z / 2)
    s_zz = -rho * g * (H - z)
    other = numpy.delete(stress, 8, axis=1)
    return {
        "u_z": numpy.max(numpy.abs(u[:, 2] - u_z)) / u_scale,
        "u_x, u_y": numpy.max(numpy.abs(u[:, :2])) / u_scale,
        "sigma_zz": numpy.max(numpy.abs(stress[:, 8] - s_zz)) / s_scale,
        "other stress components": numpy.max(numpy.abs(other)) / s_scale,
        "velocity (of u_z(H) / dt)":
            numpy.max(numpy.abs(point_array(grid, "velocity"))) * dt / u_scale,
        "acceleration (of u_z(H) / dt^2)":
            numpy.max(numpy.abs(point_array(grid, "acceleration"))) * dt * dt / u_scale,
    }


def check_joint_plane(grid, y, rho, g, H):
    """Node pairs of a vertical joint y = Y between two laterally free columns
    (Poisson's ratio 0, self-weight): every pair lies on the plane, within
    0 <= z <= H, and the joint carries nothing (sigma_yy = 0 in both columns):
    no opening, no slip, no normal or shear stress. Returns the largest
    deviations relative to H and rho g H."""
    points = vtk_to_numpy(grid.GetPoints().GetData())
    scale = rho * g * H
    return {
        "distance from the joint plane (of H)": numpy.max(numpy.abs(points[:, 1] - y)) / H,
        "height outside 0...H (of H)": max(0., -numpy.min(points[:, 2]),
                                           numpy.max(points[:, 2]) - H) / H,
        "opening and slip (of H)": max(numpy.max(numpy.abs(point_array(grid, "opening"))),
                                       numpy.max(numpy.abs(point_array(grid, "slip")))) / H,
        "normal and shear stress (of rho g H)":
            max(numpy.max(numpy.abs(point_array(grid, "normal_stress"))),
                numpy.max(numpy.abs(point_array(grid, "shear_stress")))) / scale,
    }


def water_layout(grid):
    """The water carries the pressure and the solid the displacement: the
    largest |p| on water points (material id 2) and on the others, and the
    largest |u| on water points."""
    material = point_array(grid, "material_id")
    water = material == 2
    p = numpy.abs(point_array(grid, "pressure"))
    u = numpy.abs(point_array(grid, "displacement"))
    return (numpy.max(p[water]) if water.any() else 0.,
            numpy.max(p[~water]) if (~water).any() else 0.,
            numpy.max(u[water]) if water.any() else 0.,
            int(numpy.count_nonzero(water)))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("pvd")
    parser.add_argument("--cells", type=int, required=True)
    parser.add_argument("--points", type=int, required=True)
    parser.add_argument("--pieces", type=int, required=True)
    parser.add_argument("--times", required=True)
    parser.add_argument("--arrays", required=True)
    parser.add_argument("--materials", default="")
    parser.add_argument("--column", default="")
    parser.add_argument("--joint-plane", default="")
    parser.add_argument("--water", action="store_true")
    args = parser.parse_args()

    name = os.path.basename(args.pvd)
    directory = os.path.dirname(args.pvd)
    datasets = [(float(d.get("timestep")), d.get("file"))
                for d in ElementTree.parse(args.pvd).getroot().iter("DataSet")]
    times = [float(t) for t in args.times.split(",")]
    ok = verdict(name + ": " + str(len(datasets)) + " datasets at the expected times "
                 + " ".join("%g" % t for t in times),
                 len(datasets) == len(times) and
                 all(abs(d[0] - t) <= 1e-12 * max(1., abs(t)) for d, t in zip(datasets, times)))

    expected_arrays = [(a.split(":")[0], int(a.split(":")[1])) for a in args.arrays.split(",")]
    worst = {}
    pressure = [0., 0., 0.]
    pressure_first = None
    water_everywhere = True
    all_load = all_counts = all_arrays = True
    materials = set()
    for index, (time, file) in enumerate(datasets):
        grid, pieces, errors = read_dataset(os.path.join(directory, file))
        all_load = all_load and not errors and grid is not None
        if grid is None:
            continue
        all_counts = all_counts and pieces == args.pieces and \
            grid.GetNumberOfCells() == args.cells and grid.GetNumberOfPoints() == args.points
        data = grid.GetPointData()
        for array, components in expected_arrays:
            a = data.GetArray(array)
            all_arrays = all_arrays and a is not None and \
                a.GetNumberOfComponents() == components and \
                a.GetNumberOfTuples() == grid.GetNumberOfPoints()
        if not all_arrays or grid.GetNumberOfPoints() == 0:
            continue
        if data.GetArray("material_id") is not None:
            materials |= set(int(round(m)) for m in point_array(grid, "material_id"))
        checks = {}
        if args.column:
            checks = check_column(grid, *[float(v) for v in args.column.split(",")])
        if args.joint_plane:
            checks = check_joint_plane(grid, *[float(v) for v in args.joint_plane.split(",")])
        for what, value in checks.items():
            worst[what] = max(worst.get(what, 0.), value)
        if args.water:
            p_water, p_solid, u_water, n_water = water_layout(grid)
            if pressure_first is None:
                pressure_first = p_water
            pressure = [max(pressure[0], p_water), max(pressure[1], p_solid),
                        max(pressure[2], u_water)]
            water_everywhere = water_everywhere and n_water > 0

    ok = verdict("  every dataset loads without a VTK error", all_load) and ok
    ok = verdict("  every dataset has %d cells and %d points, in as many pieces as "
                 "written" % (args.cells, args.points), all_counts) and ok
    ok = verdict("  point data " + ", ".join("%s (%d)" % a for a in expected_arrays)
                 + " present with one tuple per point", all_arrays) and ok
    if args.materials:
        expected = set(int(m) for m in args.materials.split(","))
        ok = verdict("  material ids " + args.materials, materials == expected) and ok
    # deal.II's VTU writer stores Float32: each value and coordinate carries a
    # relative rounding error up to 2^-24 = 6e-8 (measured 7e-8 of u_z(H) for
    # the column's u_z, whose reference is evaluated at rounded heights);
    # 1e-6 keeps a margin above that while a field 0.1 % off (density,
    # modulus, gravity) is off by 1e-3.
    tolerance = 1e-6
    for what, value in worst.items():
        ok = verdict("  largest error of " + what + " over every dataset below %g" % tolerance,
                     value < tolerance) and ok
    if args.water:
        ok = verdict("  every dataset has water points (material id 2)", water_everywhere) and ok
        ok = verdict("  pressure 0 in the first dataset (static stage: the hydrostatic "
                     "pressure is a load, the field is the hydrodynamic part)",
                     pressure_first == 0.) and ok
        ok = verdict("  pressure nonzero in the water later", pressure[0] > 0.) and ok
        ok = verdict("  pressure exactly 0 on dam and rock points", pressure[1] == 0.) and ok
        ok = verdict("  displacement exactly 0 on water points", pressure[2] == 0.) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
