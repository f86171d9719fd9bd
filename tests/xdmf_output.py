#!/usr/bin/python3
"""Compare the HDF5/XDMF field output of an ArchDam run with its VTU output of
the same run, array by array and value by value (tests/vtk_output.cc).

The two formats are written from the same solution at the same times, so each
must hold the same points and the same values. The XDMF file is XML, parsed
with the standard library; the arrays it names are read from the .h5 files
with h5py; the VTU records (solution.pvd) with VTK's own readers, as ParaView
opens them. Checks, for every output time:
  - the XDMF file lists the same times as solution.pvd;
  - every XDMF attribute's declared dimensions equal those of its HDF5
    dataset (a tensor declared as a 3-vector loses six components);
  - every point array of the VTU output is in the HDF5 output with all its
    components (the stress tensor's nine as stress_xx, stress_xy, ...,
    stress_zz, row by row) and every HDF5 array is in the VTU output;
  - the points' coordinates and every value agree to 1e-6 of the array's
    largest magnitude (the VTU files hold Float32: 6e-8 relative per value).
Prints one verdict per check ("...: yes" or "...: NO"), nothing that depends
on the number of MPI processes; exits 1 if a check fails or h5py or VTK is
missing.

usage: xdmf_output.py DIRECTORY
"""

import os
import sys
import xml.etree.ElementTree as ElementTree

try:
    import h5py
    import numpy
    from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError as error:
    print("h5py or VTK for Python is missing (" + str(error) + "): install python3-h5py "
          "and python3-vtk9, e.g. with scripts/install-dependencies.sh")
    sys.exit(1)

TOLERANCE = 1e-6
TENSOR = ["stress_" + a + b for a in "xyz" for b in "xyz"]


def verdict(text, ok):
    print(text + ": " + ("yes" if ok else "NO"))
    return ok


def vtu_series(directory):
    """(time, point coordinates, {name: array (points x components)}) of each
    record of solution.pvd."""
    series = []
    for dataset in ElementTree.parse(os.path.join(directory, "solution.pvd")).iter("DataSet"):
        reader = vtkXMLPUnstructuredGridReader()
        reader.SetFileName(os.path.join(directory, dataset.get("file")))
        reader.Update()
        grid = reader.GetOutput()
        data = grid.GetPointData()
        arrays = {}
        for k in range(data.GetNumberOfArrays()):
            values = vtk_to_numpy(data.GetArray(k)).astype(float)
            arrays[data.GetArrayName(k)] = values.reshape(len(values), -1)
        points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
        series.append((float(dataset.get("timestep")), points, arrays))
    return series


def hdf5_item(directory, item):
    """The dataset a DataItem names ("file.h5:/name"), as points x components,
    and the dimensions the XDMF file declares for it."""
    name, path = item.text.strip().split(":")
    with h5py.File(os.path.join(directory, name), "r") as f:
        values = numpy.array(f[path], dtype=float)
    declared = [int(n) for n in item.get("Dimensions").split()]
    return values.reshape(values.shape[0], -1), declared, list(values.shape)


def xdmf_series(directory):
    """(time, points, {name: array}, [dimension mismatches]) of each grid of
    solution.xdmf."""
    series = []
    root = ElementTree.parse(os.path.join(directory, "solution.xdmf")).getroot()
    for grid in root.iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        time = float(grid.find("Time").get("Value"))
        points, declared, stored = hdf5_item(directory, grid.find("Geometry/DataItem"))
        mismatches = [] if declared == stored else ["nodes"]
        arrays = {}
        for attribute in grid.findall("Attribute"):
            values, declared, stored = hdf5_item(directory, attribute.find("DataItem"))
            if declared[0] != stored[0] or numpy.prod(declared) != numpy.prod(stored):
                mismatches.append(attribute.get("Name"))
            arrays[attribute.get("Name")] = values
        series.append((time, points, arrays, mismatches))
    return series


def as_hdf5_names(vtu_arrays):
    """The VTU arrays under the names the HDF5 output gives them: the stress
    tensor split into its nine components."""
    arrays = dict(vtu_arrays)
    if "stress" in arrays:
        stress = arrays.pop("stress")
        for k, name in enumerate(TENSOR):
            arrays[name] = stress[:, k:k + 1]
    return arrays


def main():
    directory = sys.argv[1]
    vtu = vtu_series(directory)
    xdmf = xdmf_series(directory)
    ok = verdict("solution.xdmf: %d grids at the times of solution.pvd" % len(xdmf),
                 [t for t, *_ in vtu] == [t for t, *_ in xdmf] and len(vtu) > 0)
    if not ok:
        return 1
    mismatched = sorted({name for *_, m in xdmf for name in m})
    ok &= verdict("  every XDMF attribute declares the dimensions of its HDF5 dataset"
                  + ("" if not mismatched else " (not: " + ", ".join(mismatched) + ")"),
                  not mismatched)
    names_ok, shapes_ok, worst, worst_name = True, True, 0., ""
    for (_, vtu_points, vtu_arrays), (_, h5_points, h5_arrays, _) in zip(vtu, xdmf):
        expected = as_hdf5_names(vtu_arrays)
        expected["coordinates"] = vtu_points
        h5_arrays = dict(h5_arrays)
        h5_arrays["coordinates"] = h5_points
        names_ok &= set(expected) == set(h5_arrays)
        for name in set(expected) & set(h5_arrays):
            a, b = expected[name], h5_arrays[name]
            if a.shape != b.shape:
                shapes_ok = False
                continue
            scale = max(numpy.max(numpy.abs(a)), numpy.max(numpy.abs(b)))
            error = numpy.max(numpy.abs(a - b)) / scale if scale > 0 else 0.
            if error >= worst:
                worst, worst_name = error, name
    ok &= verdict("  the same arrays in both (the stress tensor as its nine components)",
                  names_ok)
    ok &= verdict("  every array with as many points and components in both", shapes_ok)
    ok &= verdict("  every value, and every point's coordinates, equal to %g of the array's "
                  "largest magnitude" % TOLERANCE, worst < TOLERANCE)
    if worst >= TOLERANCE:
        print("    largest difference %.3g in %s" % (worst, worst_name))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
