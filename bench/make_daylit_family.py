#!/usr/bin/env python3
"""Writes five daylit rooms to OUTDIR, the family bench_particle_entry measures daylight
particles on (how many enter the room, with and without daylight_portals):

  a_sun_window.json     3.6 x 4.2 x 2.7 m, one window facing the sun, CIE clear sky (type 12)
  b_away_overcast.json  the same room, the window facing away from the sun, CIE overcast sky
                        (type 2: overcast, slightly brighter toward a weak sun of 10 klx)
  c_ribbon.json         7.2 x 5.4 x 3 m, a ribbon window across the facade, intermediate sky
                        (type 10) with the sun 50 degrees off the facade's normal
  d_door_window.json    4 x 5 x 2.7 m, an open door (no pane) toward the low morning sun and a
                        small window in the opposite wall, CIE clear sky
  e_deep_plan.json      9 wide, 15 deep, 3 m high, three windows in one facade, CIE overcast sky

Each is a drawn room (README, "Rooms": walls of zero thickness, the floor, the ceiling, a pane in
each window, doors and plain openings real holes) whose surfaces are written as objects tagged
with it, exactly as the window generates them (core/scene/room_geometry.cpp), with a camera
inside. North is -z (SPEC.md's default), so the south facade faces +z.

usage: bench/make_daylit_family.py OUTDIR"""
import json, math, pathlib, sys

MATERIALS = {
    "floor": {"type": "diffuse", "albedo": [0.3, 0.27, 0.24]},
    "walls": {"type": "diffuse", "albedo": [0.65, 0.64, 0.6]},
    "ceiling": {"type": "diffuse", "albedo": [0.82, 0.82, 0.82]},
    "glass": {"type": "glazing", "transmittance": [0.7, 0.72, 0.7]},
}


def sub(a, b): return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def facing_quad(corners, facing):
    """A quad whose normal (corner 0 to 1 cross 0 to 2) points along `facing`."""
    c = list(corners)
    if dot(cross(sub(c[1], c[0]), sub(c[2], c[0])), facing) < 0:
        c[1], c[3] = c[3], c[1]
    return {"quad": c}


def walls_of(outline):
    """Wall k (1-based) from corner k to k + 1: (from, to, length, inward unit normal in plan)."""
    twice = sum(outline[i][0] * outline[(i + 1) % len(outline)][1] - outline[i][1] * outline[(i + 1) % len(outline)][0]
                for i in range(len(outline)))
    sign = 1 if twice >= 0 else -1
    walls = []
    for i, a in enumerate(outline):
        b = outline[(i + 1) % len(outline)]
        length = math.hypot(b[0] - a[0], b[1] - a[1])
        d = ((b[0] - a[0]) / length, (b[1] - a[1]) / length)
        walls.append((a, b, length, (-d[1] * sign, d[0] * sign)))
    return walls


def on_wall(wall, y0, along, up):
    a, b, length, _ = wall
    if along <= 0: p = a
    elif along >= length: p = b
    else: p = (a[0] + (b[0] - a[0]) * along / length, a[1] + (b[1] - a[1]) * along / length)
    return [p[0], y0 + up, p[1]]


def wall_mesh(wall, y0, height, holes):
    """The wall's rectangle cut by the holes' edges into a grid, each cell outside them two triangles."""
    inward = [wall[3][0], 0, wall[3][1]]
    if not holes:
        return facing_quad([on_wall(wall, y0, 0, 0), on_wall(wall, y0, wall[2], 0),
                            on_wall(wall, y0, wall[2], height), on_wall(wall, y0, 0, height)], inward)
    s = sorted({0.0, wall[2]} | {x for h in holes for x in h[:2]})
    t = sorted({0.0, height} | {x for h in holes for x in h[2:]})
    vertices, index, triangles = [], {}, []
    def vertex(i, j):
        if (i, j) not in index:
            index[(i, j)] = len(vertices)
            vertices.append(on_wall(wall, y0, s[i], t[j]))
        return index[(i, j)]
    for j in range(len(t) - 1):
        for i in range(len(s) - 1):
            sm, tm = 0.5 * (s[i] + s[i + 1]), 0.5 * (t[j] + t[j + 1])
            if any(h[0] < sm < h[1] and h[2] < tm < h[3] for h in holes):
                continue
            a, b, c, d = vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)
            n = cross(sub(vertices[b], vertices[a]), sub(vertices[c], vertices[a]))
            triangles += [[a, b, c], [a, c, d]] if dot(n, inward) >= 0 else [[a, c, b], [a, d, c]]
    return {"vertices": vertices, "triangles": triangles}


def room_scene(name, outline, height, openings, camera, daylight, notes):
    """A scene of one drawn room: its parameters and the surfaces made from them."""
    y0, y1 = 0.0, height
    room = {"name": name, "outline": outline, "floor_level": y0, "height": height,
            "materials": {"floor": "floor", "walls": "walls", "ceiling": "ceiling"}, "openings": openings}
    corners = lambda y: [[p[0], y, p[1]] for p in outline]
    objects = [
        {"name": name + " floor", "material": "floor", "room": name, "mesh": facing_quad(corners(y0), [0, 1, 0])},
        {"name": name + " ceiling", "material": "ceiling", "room": name, "mesh": facing_quad(corners(y1), [0, -1, 0])},
    ]
    walls = walls_of(outline)
    for k, wall in enumerate(walls):
        holes = [(o["offset"], o["offset"] + o["width"], o.get("sill", 0), o.get("sill", 0) + o["height"])
                 for o in openings if o["wall"] == k + 1]
        objects.append({"name": "%s wall %d" % (name, k + 1), "material": "walls", "room": name,
                        "mesh": wall_mesh(wall, y0, height, holes)})
    windows = 0
    for o in openings:
        if o["type"] != "window":
            continue
        windows += 1
        w = walls[o["wall"] - 1]
        s0, s1, t0, t1 = o["offset"], o["offset"] + o["width"], o["sill"], o["sill"] + o["height"]
        objects.append({"name": "%s window %d" % (name, windows), "material": o["glazing"], "room": name,
                        "mesh": facing_quad([on_wall(w, y0, s0, t0), on_wall(w, y0, s1, t0), on_wall(w, y0, s1, t1),
                                             on_wall(w, y0, s0, t1)], [w[3][0], 0, w[3][1]])})
    scene = {"lucerna": 1, "meters_per_unit": 1,
             "camera": dict(camera, up=[0, 1, 0], fov_y=65, resolution=[320, 240]),
             "materials": MATERIALS, "objects": objects}
    scene.update(daylight)
    scene["rooms"] = [room]
    scene["project"] = {"name": name, "notes": notes}
    return scene


def sun(azimuth_from_south_deg, elevation_deg, illuminance):
    """A sun at that azimuth (positive toward the west) and elevation: `direction` is where its light travels."""
    az, el = math.radians(azimuth_from_south_deg), math.radians(elevation_deg)
    toward = [-math.sin(az) * math.cos(el), math.sin(el), math.cos(az) * math.cos(el)]  # south +z, west -x
    return {"name": "sun", "type": "sun", "illuminance": illuminance,
            "direction": [round(-c, 6) for c in toward]}


def window(wall, offset, sill, width, height):
    return {"type": "window", "wall": wall, "offset": offset, "sill": sill, "width": width, "height": height,
            "glazing": "glass"}


def family():
    small = [[0, 0], [3.6, 0], [3.6, 4.2], [0, 4.2]]  # walls: 1 north (z = 0), 2 east, 3 south, 4 west
    clear = lambda s: {"lights": [s], "sky": {"model": "cie_general", "cie_type": 12, "horizontal_illuminance": 15000}}
    yield "a_sun_window", room_scene(
        "small room", small, 2.7, [window(3, 0.9, 0.9, 1.8, 1.4)],
        {"position": [0.4, 1.6, 0.4], "target": [2.4, 0.9, 4.0]}, clear(sun(20, 35, 70000)),
        "3.6 x 4.2 x 2.7 m, a 1.8 x 1.4 m window in the south wall facing the sun (35 degrees up, 20 west of "
        "south); CIE clear sky (type 12).")
    yield "b_away_overcast", room_scene(
        "small room", small, 2.7, [window(1, 0.9, 0.9, 1.8, 1.4)],
        {"position": [3.2, 1.6, 3.8], "target": [1.2, 0.9, 0.0]},
        {"lights": [sun(20, 35, 10000)], "sky": {"model": "cie_general", "cie_type": 2, "horizontal_illuminance": 10000}},
        "The same room, its window in the north wall, away from a weak sun (10 klx) behind the clouds; CIE "
        "overcast sky (type 2).")
    yield "c_ribbon", room_scene(
        "ribbon office", [[0, 0], [7.2, 0], [7.2, 5.4], [0, 5.4]], 3.0, [window(3, 0.3, 1.0, 6.6, 1.3)],
        {"position": [0.5, 1.6, 0.5], "target": [5.0, 0.9, 5.4]},
        {"lights": [sun(-50, 45, 50000)], "sky": {"model": "cie_general", "cie_type": 10, "horizontal_illuminance": 20000}},
        "7.2 x 5.4 x 3 m, a 6.6 x 1.3 m ribbon window (sill 1 m) in the south wall; the sun 45 degrees up, 50 "
        "east of south; CIE intermediate sky (type 10).")
    yield "d_door_window", room_scene(
        "workshop", [[0, 0], [4, 0], [4, 5], [0, 5]], 2.7,
        [{"type": "door", "wall": 2, "offset": 2.0, "width": 0.9, "height": 2.1}, window(4, 2.0, 1.2, 0.8, 0.8)],
        {"position": [0.4, 1.6, 0.5], "target": [4.0, 1.0, 2.5]}, clear(sun(-75, 25, 60000)),
        "4 x 5 x 2.7 m, an open door (0.9 x 2.1 m, no pane) in the east wall toward the low morning sun (25 "
        "degrees up, 75 east of south), a 0.8 x 0.8 m window in the west wall; CIE clear sky (type 12).")
    yield "e_deep_plan", room_scene(
        "deep office", [[0, 0], [9, 0], [9, 15], [0, 15]], 3.0,
        [window(3, 0.6, 0.9, 2.4, 1.7), window(3, 3.3, 0.9, 2.4, 1.7), window(3, 6.0, 0.9, 2.4, 1.7)],
        {"position": [4.5, 1.6, 0.4], "target": [4.5, 1.0, 15.0]},
        {"sky": {"model": "cie_overcast", "horizontal_illuminance": 10000}},
        "9 m wide, 15 m deep, 3 m high, three 2.4 x 1.7 m windows in the south facade only; CIE overcast sky, "
        "no sun.")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.split("\n\n")[-1])
    out = pathlib.Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    for name, scene in family():
        path = out / (name + ".json")
        path.write_text(json.dumps(scene, indent=1) + "\n")
        triangles = sum(len(o["mesh"].get("triangles", [])) or 2 for o in scene["objects"])
        print("wrote %s (%d triangles)" % (path, triangles))


if __name__ == "__main__":
    main()
