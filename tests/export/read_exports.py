#!/usr/bin/env python3
"""Reads tidepool's exports back with real readers: each scene is rendered twice,
`--export vtk` and `--export ply`, and
  - the .pvd is parsed as XML: one DataSet per exported frame (frame 0 and every K-th), in order,
    at the simulated time the scene's step gives;
  - each .vtp is read with VTK's own vtkXMLPolyDataReader (Debian's python3-vtk9): point and
    vertex counts, the fields and their components per model, z = 0 for the 2D models;
  - each .ply is read by the small reader below (not VTK's) and must hold, value for value, what
    the .vtp of the same frame holds (the runs are reproducible);
  - the obstacles' mesh (.vtp, .ply) and the ripples' heightfield (.vti, vtkXMLImageDataReader);
  - the water surface (`--export surface`): each surface_*.vtp read by VTK and the surface_*.ply of
    the same frame by the small mesh reader below hold the same closed, consistently wound mesh.
Usage: read_exports.py TIDEPOOL_EXE TEST_DATA_DIR WORK_DIR. Exits 77 (skipped) only when VTK's
Python module is not installed."""
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET

try:
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataReader
except ImportError as e:
    print(f"SKIP: VTK's Python module is not installed ({e}); install python3-vtk9 (scripts/install-deps.sh)")
    sys.exit(77)

EXE, DATA, WORK = sys.argv[1], sys.argv[2], sys.argv[3]
FRAMES, EVERY = 5, 2

# scene -> fields (name: components) and the simulated seconds of one frame (None: not checked)
def frame_seconds(scene, model):
    p = scene["params"]
    if model in ("balls", "fluid"):
        return p["engine"]["dt"] * p["engine"].get("substeps", 1)
    if model == "life":
        return p["model"]["max_dt"]  # one step of max_dt a frame
    return None

CASES = {
    "balls": {"velocity": 3, "foam": 1},
    "fluid": {"velocity": 3, "foam": 1, "density": 1},
    "life": {"velocity": 3, "species": 1},
    "swarm": {"velocity": 3},
}
PLY_TYPES = {"float": ("f", 4), "int": ("i", 4), "uchar": ("B", 1)}
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def render(scene_file, fmt, out):
    shutil.rmtree(out, ignore_errors=True)
    cmd = [EXE, "render", scene_file, "--frames", str(FRAMES), "--size", "32x18", "--export", fmt, "--every",
           str(EVERY), "--no-frames", "--quiet", "--out", out]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed ({r.returncode}): {r.stderr}")


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    out = reader.GetOutput()
    pd = out.GetPointData()
    arrays = {pd.GetArrayName(i): pd.GetArray(i) for i in range(pd.GetNumberOfArrays())}
    points = [out.GetPoint(i) for i in range(out.GetNumberOfPoints())]
    return out, points, arrays


def read_ply(path):
    """A plain binary_little_endian PLY reader: header lines, then packed vertex rows."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    lines = data[:end].decode("ascii").splitlines()
    if lines[0] != "ply" or lines[1] != "format binary_little_endian 1.0":
        raise ValueError(f"{path}: not a binary little-endian PLY: {lines[:2]}")
    count, props, comments = None, [], []
    for line in lines[2:]:
        words = line.split()
        if words[0] == "element":
            if words[1] != "vertex":
                raise ValueError(f"{path}: unexpected element {words[1]}")
            count = int(words[2])
        elif words[0] == "property":
            props.append((words[2], words[1]))
        elif words[0] == "comment":
            comments.append(line)
    fmt = "<" + "".join(PLY_TYPES[t][0] for _, t in props)
    stride = struct.calcsize(fmt)
    if len(data) - end != count * stride:
        raise ValueError(f"{path}: {len(data) - end} body bytes for {count} rows of {stride}")
    rows = [struct.unpack_from(fmt, data, end + i * stride) for i in range(count)]
    return [name for name, _ in props], rows, comments


def same(a, b):
    return (math.isnan(a) and math.isnan(b)) or a == b


for model, fields in CASES.items():
    scene_file = os.path.join(DATA, "soak", model + ".json")
    with open(scene_file) as f:
        scene = json.load(f)
    step = frame_seconds(scene, model)
    vtk_dir, ply_dir = os.path.join(WORK, model, "vtk"), os.path.join(WORK, model, "ply")
    render(scene_file, "vtk", vtk_dir)
    render(scene_file, "ply", ply_dir)

    # The collection: frame 0 and every EVERY-th, at their simulated times.
    root = ET.parse(os.path.join(vtk_dir, "particles.pvd")).getroot()
    check(root.get("type") == "Collection", f"{model}: pvd type {root.get('type')}")
    sets = root.find("Collection").findall("DataSet")
    expected_frames = list(range(0, FRAMES, EVERY))
    check([d.get("file") for d in sets] == [f"frame_{i:05d}.vtp" for i in expected_frames],
          f"{model}: pvd files {[d.get('file') for d in sets]}")
    times = [float(d.get("timestep")) for d in sets]
    check(times[0] == 0.0 and all(b > a for a, b in zip(times, times[1:])), f"{model}: times {times}")
    if step is not None:
        for frame, t in zip(expected_frames, times):
            check(math.isclose(t, frame * step, rel_tol=1e-6), f"{model}: frame {frame} at t = {t}, not {frame * step}")
    check(sorted(f for f in os.listdir(vtk_dir) if f.endswith(".vtp")) == [d.get("file") for d in sets],
          f"{model}: vtp files on disk {os.listdir(vtk_dir)}")

    for frame, d in zip(expected_frames, sets):
        where = f"{model} frame {frame}"
        poly, points, arrays = read_vtp(os.path.join(vtk_dir, d.get("file")))
        n = poly.GetNumberOfPoints()
        check(n > 100, f"{where}: {n} points")
        check(poly.GetNumberOfVerts() == n, f"{where}: {poly.GetNumberOfVerts()} vertex cells for {n} points")
        check({k: a.GetNumberOfComponents() for k, a in arrays.items()} == fields,
              f"{where}: arrays {[(k, a.GetNumberOfComponents()) for k, a in arrays.items()]}")
        check(all(a.GetNumberOfTuples() == n for a in arrays.values()), f"{where}: array lengths")
        if model in ("life", "swarm"):
            check(all(p[2] == 0.0 for p in points), f"{where}: 2D points with z != 0")
        if model == "life":
            species = arrays["species"].GetRange()
            check(species[0] >= 0 and species[1] < scene["params"]["species"] and species[1] > species[0],
                  f"{where}: species range {species}")
        if model == "fluid":
            rho = sorted(arrays["density"].GetValue(i) for i in range(n))
            if frame == 0:
                check(all(math.isnan(r) for r in rho), f"{where}: density before any step should be NaN")
            else:
                median = rho[n // 2]
                check(500 < median < 1500, f"{where}: median density {median} kg/m^3")

        # The PLY of the same frame holds the same values.
        names, rows, comments = read_ply(os.path.join(ply_dir, f"frame_{frame:05d}.ply"))
        check(len(rows) == n, f"{where}: ply has {len(rows)} vertices, vtp {n}")
        expected_names = ["x", "y", "z", "vx", "vy", "vz"] + [k for k in fields if k != "velocity"]
        check(names == expected_names, f"{where}: ply properties {names}")
        check(any(math.isclose(float(c.split()[-1]), times[expected_frames.index(frame)], rel_tol=1e-6)
                  for c in comments if c.startswith("comment tidepool time")), f"{where}: ply time comment {comments}")
        velocity = arrays["velocity"]
        mismatches = 0
        for i, row in enumerate(rows[:n]):
            want = list(points[i]) + list(velocity.GetTuple3(i)) + \
                [arrays[k].GetValue(i) for k in fields if k != "velocity"]
            mismatches += not all(same(float(a), float(b)) for a, b in zip(row, want))
        check(mismatches == 0, f"{where}: {mismatches} of {n} ply rows differ from the vtp")
    print(f"{model}: {len(sets)} frames of {n} points, fields {sorted(fields)}: vtp (VTK reader) and ply agree")


# Obstacles: written once, as a closed triangle mesh around where the obstacle stands.
OBSTACLE_SCENE = {
    "name": "export obstacle", "model": "balls",
    "params": {
        "particles": {"radius": 0.02, "domain_min": [0, 0, 0], "domain_max": [0.4, 0.4, 0.4],
                      "fill": "block", "fill_min": [0, 0, 0], "fill_max": [0.4, 0.4, 0.1]},
        "engine": {"dt": 0.0005, "substeps": 1},
        "obstacles": [{"shape": "box", "centre": [0.2, 0.2, 0.25], "size": [0.12, 0.08, 0.1]}]},
    "clip": {"frames": 2, "fps": 30, "width": 32, "height": 18}}
os.makedirs(os.path.join(WORK, "obstacle"), exist_ok=True)
obstacle_file = os.path.join(WORK, "obstacle", "scene.json")
with open(obstacle_file, "w") as f:
    json.dump(OBSTACLE_SCENE, f)
for fmt in ("vtk", "ply"):
    render(obstacle_file, fmt, os.path.join(WORK, "obstacle", fmt))
reader = vtkXMLPolyDataReader()
reader.SetFileName(os.path.join(WORK, "obstacle", "vtk", "obstacles.vtp"))
reader.Update()
mesh = reader.GetOutput()
bounds = mesh.GetBounds()
check(mesh.GetNumberOfPolys() > 100 and mesh.GetNumberOfVerts() == 0, f"obstacles.vtp: {mesh.GetNumberOfPolys()} polys")
# Around the box (size is its half extents: 0.08..0.32, 0.12..0.28, 0.15..0.35), within a ball or so.
for axis, (lo, hi) in enumerate([(0.08, 0.32), (0.12, 0.28), (0.15, 0.35)]):
    check(abs(bounds[2 * axis] - lo) < 0.03 and abs(bounds[2 * axis + 1] - hi) < 0.03,
          f"obstacles.vtp: bounds {bounds} around the box")
# Closed and consistently wound: each directed edge as often as its reverse (surface nets may give
# an edge four triangles where two parts of the surface touch).
edges = {}
ids = mesh.GetPolys().GetData()
triangles = [tuple(int(ids.GetValue(4 * t + 1 + k)) for k in range(3)) for t in range(mesh.GetNumberOfPolys())]
for a, b, c in triangles:
    for e in ((a, b), (b, c), (c, a)):
        edges[e] = edges.get(e, 0) + 1
check(all(edges.get((b, a), 0) == n for (a, b), n in edges.items()), "obstacles.vtp: not closed or not consistently wound")
with open(os.path.join(WORK, "obstacle", "ply", "obstacles.ply"), "rb") as f:
    ply = f.read()
header = ply[:ply.index(b"end_header\n")].decode("ascii")
check(f"element vertex {mesh.GetNumberOfPoints()}" in header and f"element face {len(triangles)}" in header and
      "property list uchar int vertex_indices" in header, f"obstacles.ply header: {header}")
print(f"obstacles: {len(triangles)} triangles, closed, in both formats")

# Ripples: no particles, its heightfield as VTK ImageData (.vti) in the same kind of collection.
ripples_file = os.path.join(DATA, "soak", "ripples.json")
with open(ripples_file) as f:
    ripples = json.load(f)["params"]
ripples_dir = os.path.join(WORK, "ripples", "vtk")
render(ripples_file, "vtk", ripples_dir)
sets = ET.parse(os.path.join(ripples_dir, "particles.pvd")).getroot().find("Collection").findall("DataSet")
check([d.get("file") for d in sets] == [f"frame_{i:05d}.vti" for i in range(0, FRAMES, EVERY)],
      f"ripples: pvd files {[d.get('file') for d in sets]}")
dx = ripples["cell_size"]
for d in sets:
    reader = vtkXMLImageDataReader()
    reader.SetFileName(os.path.join(ripples_dir, d.get("file")))
    reader.Update()
    image = reader.GetOutput()
    where = f"ripples {d.get('file')}"
    check(image.GetDimensions() == (ripples["width"], ripples["height"], 1), f"{where}: dimensions {image.GetDimensions()}")
    check(all(math.isclose(a, b, rel_tol=1e-6) for a, b in zip(image.GetSpacing(), (dx, dx, dx))),
          f"{where}: spacing {image.GetSpacing()}")
    check(all(math.isclose(a, b, rel_tol=1e-6) for a, b in zip(image.GetOrigin(), (dx / 2, dx / 2, 0))),
          f"{where}: origin {image.GetOrigin()}")
    pd = image.GetPointData()
    names = [pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())]
    check(names == ["height", "vertical_velocity"], f"{where}: arrays {names}")
    lo, hi = pd.GetArray("height").GetRange()
    # Flat water at frame 0; the scene's first drop (depth -0.06 m) goes in at the first step.
    if d.get("file") == "frame_00000.vti":
        check(lo == 0.0 and hi == 0.0, f"{where}: height range {lo}..{hi} of flat water")
    else:
        check(lo < -0.01 and hi <= 0.06, f"{where}: height range {lo}..{hi}")
print(f"ripples: {len(sets)} heightfields of {ripples['width']} x {ripples['height']} cells")


def read_ply_mesh(path):
    """A plain binary_little_endian PLY mesh reader: float vertex rows, then uchar-counted int faces."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    counts, props = {}, []
    for line in data[:end].decode("ascii").splitlines()[2:]:
        words = line.split()
        if words[0] == "element":
            counts[words[1]] = int(words[2])
        elif words[0] == "property" and words[1] == "float":
            props.append(words[2])
    stride = 4 * len(props)
    rows = [struct.unpack_from("<" + "f" * len(props), data, end + i * stride) for i in range(counts["vertex"])]
    at, faces = end + counts["vertex"] * stride, []
    for _ in range(counts["face"]):
        n = data[at]
        faces.append(struct.unpack_from(f"<{n}i", data, at + 1))
        at += 1 + 4 * n
    if at != len(data):
        raise ValueError(f"{path}: {len(data) - at} bytes after the faces")
    return props, rows, faces


surface_dir = os.path.join(WORK, "surface")
balls_file = os.path.join(DATA, "soak", "balls.json")
for fmt in ("vtk", "ply"):
    out = os.path.join(surface_dir, fmt)
    shutil.rmtree(out, ignore_errors=True)
    cmd = [EXE, "render", balls_file, "--frames", "3", "--size", "32x18", "--export", "surface", "--surface-format",
           fmt, "--surface-resolution", "32", "--every", "2", "--no-frames", "--quiet", "--out", out]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed ({r.returncode}): {r.stderr}")
sets = ET.parse(os.path.join(surface_dir, "vtk", "surface.pvd")).getroot().find("Collection").findall("DataSet")
check([d.get("file") for d in sets] == ["surface_00000.vtp", "surface_00002.vtp"], f"surface.pvd files {sets}")
for frame in (0, 2):
    where = f"surface frame {frame}"
    poly, points, _ = read_vtp(os.path.join(surface_dir, "vtk", f"surface_{frame:05d}.vtp"))
    props, rows, faces = read_ply_mesh(os.path.join(surface_dir, "ply", f"surface_{frame:05d}.ply"))
    check(props == ["x", "y", "z", "nx", "ny", "nz"], f"{where}: ply properties {props}")
    check(len(rows) == len(points) and all(tuple(row[:3]) == tuple(p) for row, p in zip(rows, points)),
          f"{where}: ply and vtp vertices differ ({len(rows)}, {len(points)})")
    ids = poly.GetPolys().GetData()
    vtp_faces = [tuple(int(ids.GetValue(4 * t + 1 + k)) for k in range(3)) for t in range(poly.GetNumberOfPolys())]
    check(len(faces) > 20 and faces == vtp_faces, f"{where}: {len(faces)} ply faces, {len(vtp_faces)} vtp polys")
    directed = {}
    for a, b, c in faces:
        for e in ((a, b), (b, c), (c, a)):
            directed[e] = directed.get(e, 0) + 1
    check(all(n == 1 and directed.get((b, a)) == 1 for (a, b), n in directed.items()),
          f"{where}: not closed or not consistently wound")
    check(all(abs(math.sqrt(sum(x * x for x in row[3:])) - 1) < 1e-4 for row in rows), f"{where}: normals not unit")
print(f"surface: 2 frames of {len(faces)} triangles, closed and wound one way, vtp (VTK reader) and ply agree")

if failures:
    sys.exit(f"{len(failures)} checks failed")
print("all exports read back")
