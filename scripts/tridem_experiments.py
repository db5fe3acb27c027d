"""What the experiment scripts share (scripts/biaxial_*.py, shear_flow_*.py, drum_angle.py,
hopper_gate_plot.py): finding and running tridem, reading its CSV logs, and the box of four
flat walls that consolidates a packing. Reading only needs numpy; plots need matplotlib
(Debian: python3-numpy, python3-matplotlib; scripts/install-deps.sh tools)."""
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
IMAGES = os.path.join(ROOT, "docs", "images")


def tridem_binary():
    """$TRIDEM, else the build tree's program."""
    path = os.environ.get("TRIDEM", os.path.join(ROOT, "build", "app", "tridem"))
    if not os.access(path, os.X_OK):
        sys.exit(f"no tridem program at {path}: build it (README) or set TRIDEM")
    return path


def run(scene, out, *extra):
    """Runs a scene into `out` without a progress bar (extra: more options, such as
    --backend cpu) and returns what tridem printed; a failed run stops the script with
    tridem's message."""
    cmd = [tridem_binary(), "run", scene, "--out", out, "--quiet", *extra]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed ({done.returncode}):\n{done.stdout}\n{done.stderr}")
    return done.stdout


def read_csv(path):
    """A tridem CSV as a dict of column name -> float array (rows in file order)."""
    with open(path) as f:
        names = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {name: data[:, k] for k, name in enumerate(names)}


def wall_series(walls, wall_id):
    """walls.csv's rows of one wall id, as a dict of arrays in time order."""
    keep = walls["id"] == wall_id
    return {name: column[keep] for name, column in walls.items()}


# The box: four thick triangles whose inner faces are the sample's sides. Each face is an
# edge of its triangle, so the face's position is the centroid's plus a third of the
# triangle's thickness T: walls.csv's x, y give the box's size at every logged step.
# Ids 0..3 in this order (they are the scene's first triangles).
LEFT, RIGHT, BOTTOM, TOP = 0, 1, 2, 3
WALL_THICKNESS = 0.05  # m


def box_walls(width, height, material, programs):
    """The four [[triangle]] walls of a box [0, width] x [0, height]. programs maps a wall
    (LEFT, RIGHT, TOP, BOTTOM) to its motion lines; the others are fixed. Faces reach past
    the corners by half the box, so that the walls still close the box as they move."""
    reach_x, reach_y = 0.5 * width, 0.5 * height
    thick = WALL_THICKNESS
    tri = {
        LEFT: [(0, -reach_y), (0, height + reach_y), (-thick, 0.5 * height)],
        RIGHT: [(width, height + reach_y), (width, -reach_y), (width + thick, 0.5 * height)],
        BOTTOM: [(width + reach_x, 0), (-reach_x, 0), (0.5 * width, -thick)],
        TOP: [(-reach_x, height), (width + reach_x, height), (0.5 * width, height + thick)],
    }
    names = {LEFT: "left", RIGHT: "right", BOTTOM: "bottom", TOP: "top"}
    blocks = []
    for wall in (LEFT, RIGHT, BOTTOM, TOP):
        v = ", ".join(f"[{x:.9g}, {y:.9g}]" for x, y in tri[wall])
        motion = programs.get(wall, "fixed = true")
        blocks.append(f"[[triangle]]   # {names[wall]} wall (id {wall})\n"
                      f'material = "{material}"\nvertices = [{v}]\n{motion}\n')
    return "\n".join(blocks)


def face_positions(walls):
    """The box's inner faces over time from walls.csv: x_left, x_right, y_bottom, y_top."""
    third = WALL_THICKNESS / 3
    left, right = wall_series(walls, LEFT), wall_series(walls, RIGHT)
    bottom, top = wall_series(walls, BOTTOM), wall_series(walls, TOP)
    return (left["x"] + third, right["x"] - third, bottom["y"] + third, top["y"] - third)


def packing_at_origin(final, first_grain=4):
    """final.csv's free grains (ids from first_grain on: a consolidation's walls come first)
    moved so that their outline (the extreme vertices, 1e-7 m out) is the box [0, w] x [0, h]:
    a box of walls there touches no grain, so the scene is read without an overlap. Returns
    (the rows of an [[import]] CSV as dicts: x1..y3, body), w, h."""
    keep = final["id"] >= first_grain
    corners = ("x1", "y1", "x2", "y2", "x3", "y3")
    v = np.stack([final[c][keep] for c in corners], axis=1)
    x0, y0 = v[:, 0::2].min() - 1e-7, v[:, 1::2].min() - 1e-7
    v[:, 0::2] -= x0
    v[:, 1::2] -= y0
    w, h = v[:, 0::2].max() + 1e-7, v[:, 1::2].max() + 1e-7
    rows = [dict(zip(corners, r), body=int(b)) for r, b in zip(v, final["body"][keep])]
    return rows, w, h


def triangle_area(r):
    """The area of an [[import]] CSV row's triangle (a dict with x1..y3)."""
    return 0.5 * abs((r["x2"] - r["x1"]) * (r["y3"] - r["y1"])
                     - (r["x3"] - r["x1"]) * (r["y2"] - r["y1"]))


def write_grains_csv(path, rows, extra=()):
    """An [[import]] CSV of rows (dicts with x1..y3, body and the extra columns' keys)."""
    columns = ["x1", "y1", "x2", "y2", "x3", "y3", *extra, "body"]
    with open(path, "w") as f:
        f.write(",".join(columns) + "\n")
        for r in rows:
            f.write(",".join(f"{r[c]:.12g}" if c != "body" else str(r[c]) for c in columns)
                    + "\n")


_VTK_TYPES = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "Int64": "<i8",
              "UInt8": "u1", "UInt32": "<u4", "UInt64": "<u8"}


def _vtk_array(text, dtype, decompress, header):
    """One DataArray's text: ascii numbers, or VTK's base64 binary (UInt64 or UInt32
    header), its blocks compressed (decompress: zlib's or lzma's) or not (None)."""
    import base64
    text = "".join(text.split())
    if not text:
        return np.zeros(0, dtype)
    word = np.dtype(header)
    if decompress is None:
        raw = base64.b64decode(text)
        return np.frombuffer(raw[word.itemsize:], dtype=dtype)
    # The header (blocks, block size, last block's size, each block's compressed size) is
    # encoded on its own, then the compressed blocks.
    first = base64.b64decode(text[:4 * ((3 * word.itemsize + 2) // 3)])
    blocks = int(np.frombuffer(first[:3 * word.itemsize], dtype=word)[0])
    chars = 4 * (((3 + blocks) * word.itemsize + 2) // 3)
    sizes = np.frombuffer(base64.b64decode(text[:chars]), dtype=word)[3:3 + blocks]
    data = base64.b64decode(text[chars:])
    out, at = [], 0
    for size in sizes:
        out.append(decompress(data[at:at + int(size)]))
        at += int(size)
    return np.frombuffer(b"".join(out), dtype=dtype)


def _appended_array(raw, offset, dtype, decompress, header):
    """One array of VTK's raw appended data, from `offset` (its DataArray's attribute):
    the byte count and the values, or the blocks' header and the compressed blocks."""
    word = np.dtype(header)
    first = np.frombuffer(raw[offset:offset + word.itemsize], dtype=word)
    if decompress is None:
        start = offset + word.itemsize
        return np.frombuffer(raw[start:start + int(first[0])], dtype=dtype)
    blocks = int(first[0])
    at = offset + (3 + blocks) * word.itemsize
    sizes = np.frombuffer(raw[offset:at], dtype=word)[3:]
    out = []
    for size in sizes:
        out.append(decompress(raw[at:at + int(size)]))
        at += int(size)
    return np.frombuffer(b"".join(out), dtype=dtype)


def read_frame(path):
    """A frame (frames/frame_STEP.vtu) as a dict: 'time', 'vertices' (n x 3 x 2) and each
    cell array by name (velocity as n x 3, motion, body, material, ...; those a run's
    [output] frame_arrays left out are absent). Reads every encoding tridem writes:
    inline base64 or text, and VTK's raw appended data (vtk_encoding = "appended")."""
    import lzma
    import xml.etree.ElementTree as ET
    import zlib
    with open(path, "rb") as f:
        data = f.read()
    # Appended raw data is not XML: the tags before it are parsed, its bytes taken as they
    # are (from the underscore after its tag to its closing tag, the file's last).
    raw = b""
    marker = data.find(b"<AppendedData")
    if marker >= 0:
        start = data.index(b"_", data.index(b">", marker)) + 1
        raw = data[start:data.rindex(b"</AppendedData>")]
        data = data[:marker] + b"</VTKFile>"
    root = ET.fromstring(data)
    decompress = {"vtkZLibDataCompressor": zlib.decompress,
                  "vtkLZMADataCompressor": lzma.decompress}.get(root.get("compressor"))
    header = _VTK_TYPES[root.get("header_type", "UInt32")]
    frame = {}
    for a in root.iter("DataArray"):
        dtype = _VTK_TYPES[a.get("type")]
        if a.get("format") == "ascii":
            values = np.array((a.text or "").split(), dtype=dtype)
        elif a.get("format") == "appended":
            values = _appended_array(raw, int(a.get("offset")), dtype, decompress, header)
        else:
            values = _vtk_array(a.text or "", dtype, decompress, header)
        comps = int(a.get("NumberOfComponents", "1"))
        name = a.get("Name", "")
        frame[name] = values.reshape(-1, comps) if comps > 1 else values
        if name == "TimeValue":
            frame["time"] = float(values[0])
    points = frame["Points"]
    frame["vertices"] = points[:, :2].reshape(-1, 3, 2)
    return frame
