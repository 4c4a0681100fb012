#!/usr/bin/env python3
"""Writes resources/scenes/daylit_office.json: a 6 x 4.5 x 3 m office with two glazed windows in
its south wall (+z; north is -z), desks, a cabinet and a shelf, under a CIE general clear sky
(type 12) with the sun of 21 March at 11:00 in Paris. Walls are single surfaces (zero thickness);
the window wall is cut around the openings; each opening holds one glazing pane. With the project
and EN 17037's reference plane as a task area, for the report."""
import json, sys, pathlib

W, D, H = 6.0, 4.5, 3.0            # x, z, y (m)
windows = [(0.8, 2.6), (3.4, 5.2)] # x ranges of the two windows
sill, head = 0.9, 2.4

def quad(a, b, c, d):
    return {"quad": [a, b, c, d]}

def box(x0, y0, z0, x1, y1, z1):
    v = [[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
         [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]]
    t = [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
         [3, 7, 6], [3, 6, 2], [0, 4, 7], [0, 7, 3], [1, 2, 6], [1, 6, 5]]
    return {"vertices": v, "triangles": t}

def merge(meshes):
    v, t = [], []
    for m in meshes:
        base = len(v)
        v += m["vertices"]
        t += [[a + base, b + base, c + base] for a, b, c in m["triangles"]]
    return {"vertices": v, "triangles": t}

objects = [
    {"name": "floor", "material": "floor", "mesh": quad([0, 0, 0], [0, 0, D], [W, 0, D], [W, 0, 0])},
    {"name": "ceiling", "material": "ceiling", "mesh": quad([0, H, 0], [W, H, 0], [W, H, D], [0, H, D])},
    {"name": "wall_north", "material": "wall", "mesh": quad([0, 0, 0], [W, 0, 0], [W, H, 0], [0, H, 0])},
    {"name": "wall_west", "material": "wall", "mesh": quad([0, 0, 0], [0, H, 0], [0, H, D], [0, 0, D])},
    {"name": "wall_east", "material": "wall", "mesh": quad([W, 0, 0], [W, 0, D], [W, H, D], [W, H, 0])},
]
# The south wall around the windows: below the sills, above the heads, and the piers between.
south = [quad([0, 0, D], [0, sill, D], [W, sill, D], [W, 0, D]),
         quad([0, head, D], [0, H, D], [W, H, D], [W, head, D])]
xs = [0.0] + [x for w in windows for x in w] + [W]
for i in range(0, len(xs), 2):
    x0, x1 = xs[i], xs[i + 1]
    if x1 > x0:
        south.append(quad([x0, sill, D], [x0, head, D], [x1, head, D], [x1, sill, D]))
for i, q in enumerate(south):
    objects.append({"name": "wall_south_%d" % i, "material": "wall", "mesh": q})
for i, (x0, x1) in enumerate(windows):
    objects.append({"name": "window_%d" % (i + 1), "material": "glass",
                    "mesh": quad([x0, sill, D], [x1, sill, D], [x1, head, D], [x0, head, D])})
# Two desks (tops on four legs), a cabinet against the north wall, a shelf on the west wall.
desks = []
for x0, z0 in [(0.9, 2.6), (3.5, 2.6)]:
    x1, z1 = x0 + 1.6, z0 + 0.8
    desks.append(box(x0, 0.72, z0, x1, 0.75, z1))
    for lx, lz in [(x0 + 0.05, z0 + 0.05), (x1 - 0.1, z0 + 0.05), (x0 + 0.05, z1 - 0.1), (x1 - 0.1, z1 - 0.1)]:
        desks.append(box(lx, 0.0, lz, lx + 0.05, 0.72, lz + 0.05))
objects.append({"name": "desks", "material": "desk", "mesh": merge(desks)})
objects.append({"name": "cabinet", "material": "cabinet", "mesh": box(2.2, 0.0, 0.02, 3.8, 1.1, 0.5)})
objects.append({"name": "shelf", "material": "shelf", "mesh": box(0.02, 1.5, 0.8, 0.35, 1.54, 2.6)})

scene = {
    "lucerna": 1,
    "meters_per_unit": 1,
    "camera": {"position": [0.35, 1.6, 0.35], "target": [4.6, 0.7, 4.5], "up": [0, 1, 0],
               "fov_y": 62, "resolution": [480, 320]},
    "materials": {
        "floor": {"type": "diffuse", "albedo": [0.32, 0.27, 0.22]},
        "ceiling": {"type": "diffuse", "albedo": [0.82, 0.82, 0.82]},
        "wall": {"type": "diffuse", "albedo": [0.7, 0.68, 0.63]},
        "desk": {"type": "diffuse", "albedo": [0.62, 0.55, 0.45]},
        "cabinet": {"type": "diffuse", "albedo": [0.35, 0.42, 0.52]},
        "shelf": {"type": "diffuse", "albedo": [0.5, 0.36, 0.25]},
        "glass": {"type": "glazing", "transmittance": [0.7, 0.72, 0.7]},
    },
    "objects": objects,
    "lights": [{"name": "sun", "type": "sun", "illuminance": 70000, "time": "2026-03-21T11:00"}],
    "site": {"latitude": 48.857, "longitude": 2.352, "utc_offset": 1},
    "sky": {"model": "cie_general", "cie_type": 12, "horizontal_illuminance": 12000, "ground_reflectance": 0.2},
    # The report's cover and its task area (README, "Reports"): EN 17037's reference plane, 0.85 m
    # above the floor less a 0.5 m band along the walls (u along z, v along x: it faces up).
    "project": {"name": "Daylit office (bundled example)",
                "notes": "6.0 x 4.5 m, ceiling 3.0 m; two glazed windows in the south wall (sill 0.9 m, head "
                         "2.4 m, transmittance 0.7); Paris, 21 March 11:00, CIE clear sky type 12 with the sun."},
    "task_areas": [{"name": "Reference plane", "corner": [0.5, 0.85, 0.5], "u": [0, 0, 3.5], "v": [5.0, 0, 0]}],
}
out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "resources/scenes/daylit_office.json")
out.write_text(json.dumps(scene, indent=1) + "\n")
print("wrote", out)
