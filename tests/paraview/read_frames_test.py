#!/usr/bin/env python3
"""ParaView's reader on tridem's frames: VTK's own vtkXMLUnstructuredGridReader and
vtkXMLPolyDataReader (Debian's python3-vtk9, the library ParaView is built on) read the
frames and contact networks a run writes in the default format (binary, Float32, zlib),
in the former one (Float64, uncompressed), in VTK's raw appended data and compressed by
vtkLZMADataCompressor, and with only some arrays (`frame_arrays`, `contact_arrays`); point and cell counts are those of the
run, and the last frame's cell data and vertices are final.csv's state within float32
rounding (exactly, in Float64).

usage: read_frames_test.py TRIDEM SOURCE_DIR WORK_DIR
Exits 77 (CTest's skip) with the reason when python3-vtk9 is missing.
"""
import csv
import os
import shutil
import subprocess
import sys

SKIP = 77
try:
    import numpy as np
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError:
    print("SKIP: python3-vtk9 is not installed (apt-get install python3-vtk9)")
    sys.exit(SKIP)

tridem, source, work = sys.argv[1], sys.argv[2], sys.argv[3]
sys.path.insert(0, os.path.join(source, "scripts"))
import tridem_experiments as tx  # noqa: E402  (found through the source folder, above)
scene = os.path.join(source, "tests", "paraview", "frames_scene.toml")
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL:", what)


def read(reader_type, path):
    reader = reader_type()
    reader.SetFileName(path)
    reader.Update()
    check(reader.GetErrorCode() == 0, f"{path}: VTK reports error {reader.GetErrorCode()}")
    return reader.GetOutput()


def run(out, extra):
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    text = open(scene).read().replace("[output]\n", "[output]\n" + extra)
    path = os.path.join(out, "scene.toml")
    open(path, "w").write(text)
    subprocess.run([tridem, "run", path, "--out", out, "--quiet"], check=True,
                   stdout=subprocess.DEVNULL)


def verify(out, tolerance, type_name):
    with open(os.path.join(out, "final.csv")) as f:
        final = list(csv.DictReader(f))
    n = len(final)
    frames = sorted(os.listdir(os.path.join(out, "frames")))
    check(frames == [f"frame_{s:09d}.vtu" for s in (0, 1000, 2000, 3000)], f"{out}: frames {frames}")
    grid = read(vtkXMLUnstructuredGridReader, os.path.join(out, "frames", frames[-1]))
    check(grid.GetNumberOfCells() == n, f"{out}: {grid.GetNumberOfCells()} cells, {n} particles")
    check(grid.GetNumberOfPoints() == 3 * n, f"{out}: {grid.GetNumberOfPoints()} points")
    cells = grid.GetCellData()
    velocity = cells.GetArray("velocity")
    check(velocity is not None and velocity.GetDataTypeAsString() == type_name,
          f"{out}: velocity is {velocity and velocity.GetDataTypeAsString()}, not {type_name}")
    v = vtk_to_numpy(velocity)
    ids = vtk_to_numpy(cells.GetArray("id"))
    points = vtk_to_numpy(grid.GetPoints().GetData())
    worst = 0.0
    for cell, k in enumerate(ids):
        row = final[int(k)]
        pairs = [(v[cell][0], row["vx"]), (v[cell][1], row["vy"])]
        for vertex in range(3):
            pairs.append((points[3 * cell + vertex][0], row[f"x{vertex + 1}"]))
            pairs.append((points[3 * cell + vertex][1], row[f"y{vertex + 1}"]))
        for got, want in pairs:
            want = float(want)
            worst = max(worst, abs(float(got) - want) / max(abs(want), 1e-300))
    check(worst <= tolerance, f"{out}: the last frame differs from final.csv by {worst:g} (relative)")
    network = read(vtkXMLPolyDataReader, os.path.join(out, "contacts", "contacts_000003000.vtp"))
    with open(os.path.join(out, "contacts", "contacts_000003000.csv")) as f:
        contacts = list(csv.DictReader(f))
    check(len(contacts) > 0, f"{out}: the pile has no contacts")
    check(network.GetNumberOfLines() == len(contacts),
          f"{out}: {network.GetNumberOfLines()} lines, {len(contacts)} contacts")
    # The network's points are the particles' centroids, in id order.
    check(network.GetNumberOfPoints() == n, f"{out}: {network.GetNumberOfPoints()} points")
    fn = vtk_to_numpy(network.GetCellData().GetArray("normal_force"))
    off = max((abs(float(got) - float(row["fn"])) / max(abs(float(row["fn"])), 1e-300)
               for got, row in zip(fn, contacts)), default=0.0)
    check(off <= max(tolerance, 1e-12) * 4, f"{out}: normal_force differs from the CSV by {off:g}")
    print(f"{out}: {n} cells, {len(contacts)} contacts read by VTK; worst relative difference {worst:g}")


def verify_lean(out):
    """`frame_arrays` and `contact_arrays`: VTK reads the frame and network, which hold the
    arrays chosen (besides the frame's identity) and no others, with final.csv's values."""
    with open(os.path.join(out, "final.csv")) as f:
        final = list(csv.DictReader(f))
    grid = read(vtkXMLUnstructuredGridReader, os.path.join(out, "frames", "frame_000003000.vtu"))
    cells = grid.GetCellData()
    names = [cells.GetArrayName(k) for k in range(cells.GetNumberOfArrays())]
    check(names == ["id", "velocity", "material", "motion", "body"], f"{out}: frame arrays {names}")
    ids = vtk_to_numpy(cells.GetArray("id"))
    v = vtk_to_numpy(cells.GetArray("velocity"))
    worst = max(abs(float(v[cell][0]) - float(final[int(k)]["vx"])) /
                max(abs(float(final[int(k)]["vx"])), 1e-300) for cell, k in enumerate(ids))
    check(worst <= 2.0 ** -23, f"{out}: velocity differs from final.csv by {worst:g}")
    network = read(vtkXMLPolyDataReader, os.path.join(out, "contacts", "contacts_000003000.vtp"))
    data = network.GetCellData()
    names = [data.GetArrayName(k) for k in range(data.GetNumberOfArrays())]
    check(names == ["force"], f"{out}: network arrays {names}")
    with open(os.path.join(out, "contacts", "contacts_000003000.csv")) as f:
        contacts = list(csv.DictReader(f))
    check(network.GetNumberOfLines() == len(contacts) > 0,
          f"{out}: {network.GetNumberOfLines()} lines, {len(contacts)} contacts")
    force = vtk_to_numpy(data.GetArray("force"))
    off = max((abs(float(got[1]) - float(row["fy"])) / max(abs(float(row["fy"])), 1e-300)
               for got, row in zip(force, contacts)), default=0.0)
    check(off <= 2.0 ** -23, f"{out}: force differs from the CSV by {off:g}")
    print(f"{out}: the lean frame and network read by VTK; {len(contacts)} contacts")


def same_as_experiments_reader(out):
    """scripts/tridem_experiments.py's read_frame (what the experiment scripts read frames
    with) gives VTK's arrays, in every encoding: inline, appended, lzma."""
    path = os.path.join(out, "frames", "frame_000003000.vtu")
    grid = read(vtkXMLUnstructuredGridReader, path)
    frame = tx.read_frame(path)
    cells = grid.GetCellData()
    for k in range(cells.GetNumberOfArrays()):
        name = cells.GetArrayName(k)
        check(name in frame and np.array_equal(frame[name], vtk_to_numpy(cells.GetArray(k))),
              f"{path}: read_frame's {name} is not VTK's")
    points = vtk_to_numpy(grid.GetPoints().GetData())
    check(np.array_equal(frame["vertices"], points[:, :2].reshape(-1, 3, 2)),
          f"{path}: read_frame's vertices are not VTK's")


out = os.path.join(work, "lean")
run(out, 'vtk_encoding = "appended"\nframe_arrays = ["velocity"]\ncontact_arrays = ["force"]\n')
verify_lean(out)
same_as_experiments_reader(out)

verify_cases = [
    ("default", "", 2.0 ** -23, "float"),
    ("former", 'vtk_precision = "double"\nvtk_compression = "none"\n', 0.0, "double"),
    # VTK's raw appended data, compressed and not.
    ("appended", 'vtk_encoding = "appended"\n', 2.0 ** -23, "float"),
    ("appended_double", 'vtk_encoding = "appended"\nvtk_precision = "double"\n'
     'vtk_compression = "none"\n', 0.0, "double"),
    # vtkLZMADataCompressor's blocks, inline and appended (the doubles exactly).
    ("lzma", 'vtk_compression = "lzma"\n', 2.0 ** -23, "float"),
    ("lzma_appended_double", 'vtk_encoding = "appended"\nvtk_precision = "double"\n'
     'vtk_compression = "lzma"\n', 0.0, "double"),
]
for name, extra, tolerance, type_name in verify_cases:
    out = os.path.join(work, name)
    run(out, extra)
    verify(out, tolerance, type_name)
    same_as_experiments_reader(out)
sys.exit(1 if failures else 0)
