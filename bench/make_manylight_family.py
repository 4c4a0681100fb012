#!/usr/bin/env python3
"""Writes five many-luminaire interiors with glass or mirrors, or lit indirectly, to OUTDIR: the
family on which next-event light selection by the light tree (`--option light_sampler=tree`) is
measured against selection by power in bdpt and cmlt (issue 37):

  glass_partition_office.json  an open office 20 x 12 x 3 m, 95 lights under the ceiling in a grid
                               (spots and pendants), a 5 x 4 m meeting room in one corner behind a
                               glass partition (glazing, transmittance 0.8) with its own 4 lights;
                               the camera in the meeting room looking out through the glass
  corridor.json                a corridor 2 m wide and 20 m long between eight 5 x 4 m rooms of 8
                               lights each, a doorway (a hole) from each room into the corridor,
                               the corridor lit by one dim pendant; the camera in the corridor
  mirror_lobby.json            a lobby 15 x 10 x 4 m whose far wall is a mirror (reflectance 0.9),
                               60 downlights, two columns and a desk; the camera looks at the
                               mirror at an angle
  glass_rooms_floor.json       a floor 24 x 14 x 3 m: five 4.8 x 4 m offices of 6 lights each with
                               glazed fronts (and a doorway) onto a hall of 72 lights, 102 in all;
                               the camera in the hall
  lit_from_next_room.json      a dark room 6 x 5 x 3 m lit only through a 4 x 2.6 m glazed opening
                               from the room beside it (10 x 8 m, 40 lights); the camera in the
                               dark room (held out: measured last, not decided on)

Every room is a closed box (floor, ceiling, walls of zero thickness, all two-sided diffuse, albedos
0.3 to 0.8) but for the openings drawn in it, which are real holes in the wall's triangles (a pane
of glazing fills the glazed ones). Lights are point and spot lights (SPEC.md: intensity in W/sr, a
few hundred candela / 683) a little under the ceiling and away from every surface. SPEC.md's
format, meters_per_unit 1, camera resolution 160 x 120.

usage: bench/make_manylight_family.py OUTDIR"""
import json, pathlib, sys

MATERIALS = {
    "floor": {"type": "diffuse", "albedo": [0.3, 0.28, 0.25]},
    "walls": {"type": "diffuse", "albedo": [0.65, 0.64, 0.6]},
    "ceiling": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8]},
    "accent": {"type": "diffuse", "albedo": [0.7, 0.5, 0.35]},
    "furniture": {"type": "diffuse", "albedo": [0.5, 0.45, 0.4]},
    "glass": {"type": "glazing", "transmittance": [0.8, 0.8, 0.8]},
    "mirror": {"type": "mirror", "reflectance": [0.9, 0.9, 0.9]},
}
WARM = [1.0, 0.93, 0.82]  # a warm white, luminance about 0.94


def point3(axis, c, u, v):
    """The point (u, v) of the plane axis = c: walls z = c take (x, y), walls x = c (z, y), floors y = c (x, z)."""
    return {"z": [u, v, c], "x": [c, v, u], "y": [u, c, v]}[axis]


def plane(axis, c, u0, u1, v0, v1, holes=()):
    """The rectangle [u0, u1] x [v0, v1] of the plane axis = c cut by the holes (u0, u1, v0, v1) into a grid,
    each cell outside them two triangles (the surfaces are two-sided, the winding is free)."""
    s = sorted({u0, u1} | {x for h in holes for x in h[:2]})
    t = sorted({v0, v1} | {x for h in holes for x in h[2:]})
    vertices, index, triangles = [], {}, []

    def vertex(i, j):
        if (i, j) not in index:
            index[(i, j)] = len(vertices)
            vertices.append([round(x, 6) for x in point3(axis, c, s[i], t[j])])
        return index[(i, j)]
    for j in range(len(t) - 1):
        for i in range(len(s) - 1):
            sm, tm = 0.5 * (s[i] + s[i + 1]), 0.5 * (t[j] + t[j + 1])
            if any(h[0] < sm < h[1] and h[2] < tm < h[3] for h in holes):
                continue
            a, b, cc, d = vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)
            triangles += [[a, b, cc], [a, cc, d]]
    return {"vertices": vertices, "triangles": triangles}


def box(x0, x1, y0, y1, z0, z1):
    """A closed box (12 triangles)."""
    v = [[x, y, z] for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return {"vertices": v, "triangles": [t for a, b, c, d in faces for t in ([a, b, c], [a, c, d])]}


class Scene:
    def __init__(self, notes):
        self.objects, self.lights, self.notes = [], [], notes

    def add(self, name, material, mesh):
        self.objects.append({"name": name, "material": material, "mesh": mesh})

    def shell(self, name, x0, x1, z0, z1, height, floor="floor", ceiling="ceiling"):
        self.add(name + " floor", floor, plane("y", 0.0, x0, x1, z0, z1))
        self.add(name + " ceiling", ceiling, plane("y", height, x0, x1, z0, z1))

    def wall(self, name, axis, c, u0, u1, height, holes=(), material="walls"):
        self.add(name, material, plane(axis, c, u0, u1, 0.0, height, holes))

    def pane(self, name, axis, c, u0, u1, v0, v1):
        self.add(name, "glass", plane(axis, c, u0, u1, v0, v1))

    def light(self, name, position, candela, spot=None):
        intensity = [round(candela / 683.0 * w, 6) for w in WARM]
        light = {"name": name, "type": "spot" if spot else "point", "position": [round(x, 4) for x in position]}
        if spot:
            light["direction"] = [0, -1, 0]
        light["intensity"] = intensity
        if spot:
            light["cone_angle"], light["falloff_start"] = spot
        self.lights.append(light)

    def json(self, camera):
        return {"lucerna": 1, "meters_per_unit": 1,
                "camera": dict(camera, up=[0, 1, 0], fov_y=60, resolution=[160, 120]),
                "materials": MATERIALS, "objects": self.objects, "lights": self.lights,
                "project": {"name": "many-light family", "notes": self.notes}}


def grid(u0, u1, nu, v0, v1, nv):
    """nu x nv points centred in their cells of [u0, u1] x [v0, v1]."""
    return [(u0 + (u1 - u0) * (i + 0.5) / nu, v0 + (v1 - v0) * (j + 0.5) / nv) for j in range(nv) for i in range(nu)]


def glass_partition_office():
    s = Scene("Open office 20 x 12 x 3 m, 95 lights (two of three 350 cd spots, every third a 250 cd pendant) "
              "in a 13 x 8 grid less the meeting room's corner; meeting room x 0-5, z 0-4 behind a glass wall "
              "(x = 5, glazing 0.8 up to 2.6 m) with 4 dimmer pendants; camera in the meeting room looking out.")
    H = 3.0
    s.shell("office", 0, 20, 0, 12, H)
    s.wall("office wall north", "z", 0, 0, 20, H)
    s.wall("office wall south", "z", 12, 0, 20, H, material="accent")
    s.wall("office wall west", "x", 0, 0, 12, H)
    s.wall("office wall east", "x", 20, 0, 12, H)
    s.wall("meeting wall south", "z", 4, 0, 5, H)
    s.wall("meeting partition header", "x", 5, 0, 4, H, holes=[(0, 4, 0, 2.6)])
    s.pane("meeting partition glass", "x", 5, 0, 4, 0, 2.6)
    s.add("meeting table", "furniture", box(1.6, 3.6, 0.7, 0.75, 1.3, 2.7))
    for k, (x, z) in enumerate([(7.5, 2.0), (11.0, 2.0), (14.5, 2.0), (7.5, 6.0), (11.0, 6.0), (14.5, 6.0),
                                (7.5, 9.5), (11.0, 9.5), (14.5, 9.5), (18.0, 6.0), (2.5, 8.0), (2.5, 10.5)]):
        s.add("desk %d" % (k + 1), "furniture", box(x - 1.2, x + 1.2, 0.0, 0.75, z - 0.8, z + 0.8))
        s.add("screen %d" % (k + 1), "furniture", box(x - 1.2, x + 1.2, 0.75, 1.3, z + 0.75, z + 0.8))
    n = 0
    for x, z in grid(0, 20, 13, 0, 12, 8):
        if x < 5.3 and z < 4.3:
            continue
        n += 1
        if n % 3 == 0:
            s.light("office pendant %d" % n, (x, 2.6, z), 250)
        else:
            s.light("office spot %d" % n, (x, 2.88, z), 350, spot=(55, 40))
    for k, (x, z) in enumerate(grid(0, 5, 2, 0, 4, 2)):
        s.light("meeting pendant %d" % (k + 1), (x, 2.5, z), 120)
    return s.json({"position": [0.6, 1.35, 1.0], "target": [10.0, 1.1, 5.0]})


def corridor():
    s = Scene("Corridor 2 x 20 x 2.7 m (z 0-2) between eight 5 x 4 m rooms (four a side), each lit by 8 lights "
              "(spots or pendants, 150 to 500 cd by room), a 0.9 x 2.1 m doorway from each into the corridor; "
              "the corridor lit by one dim 15 cd pendant near its far end; camera in the corridor.")
    H = 2.7
    s.shell("floor", 0, 20, -4, 6, H)
    s.wall("outer wall north", "z", -4, 0, 20, H)
    s.wall("outer wall south", "z", 6, 0, 20, H)
    s.wall("outer wall west", "x", 0, -4, 6, H)
    s.wall("outer wall east", "x", 20, -4, 6, H)
    doors_north = [1.0, 3.6, 2.0, 0.6]
    doors_south = [3.2, 1.4, 3.8, 2.4]
    s.wall("corridor wall north", "z", 0, 0, 20, H,
           holes=[(5 * i + d, 5 * i + d + 0.9, 0, 2.1) for i, d in enumerate(doors_north)], material="accent")
    s.wall("corridor wall south", "z", 2, 0, 20, H,
           holes=[(5 * i + d, 5 * i + d + 0.9, 0, 2.1) for i, d in enumerate(doors_south)])
    for i in (1, 2, 3):
        s.wall("partition north %d" % i, "x", 5 * i, -4, 0, H)
        s.wall("partition south %d" % i, "x", 5 * i, 2, 6, H)
    candela = [300, 150, 500, 250, 400, 200, 350, 450]
    for r in range(8):
        side, i = ("north", r) if r < 4 else ("south", r - 4)
        z0, z1 = (-4, 0) if side == "north" else (2, 6)
        spots = r % 2 == 0
        for k, (x, z) in enumerate(grid(5 * i, 5 * i + 5, 4, z0, z1, 2)):
            name = "room %s %d light %d" % (side, i + 1, k + 1)
            if spots:
                s.light(name, (x, 2.58, z), candela[r], spot=(50, 35))
            else:
                s.light(name, (x, 2.35, z), candela[r] * 0.6)
        s.add("room %s %d desk" % (side, i + 1), "furniture",
              box(5 * i + 1.5, 5 * i + 3.5, 0, 0.75, 0.5 * (z0 + z1) - 0.6, 0.5 * (z0 + z1) + 0.6))
    s.light("corridor pendant", (17.0, 2.4, 1.0), 15)
    return s.json({"position": [0.5, 1.6, 1.0], "target": [20.0, 1.1, 1.25]})


def mirror_lobby():
    s = Scene("Lobby 15 x 10 x 4 m, the far wall (z = 10) a mirror (reflectance 0.9), 60 downlights (600 cd "
              "spots, 40-degree cone) in a 10 x 6 grid, two columns, a reception desk, an accent wall; camera "
              "looking at the mirror at an angle.")
    H = 4.0
    s.shell("lobby", 0, 15, 0, 10, H)
    s.wall("lobby wall north", "z", 0, 0, 15, H)
    s.wall("lobby mirror wall", "z", 10, 0, 15, H, material="mirror")
    s.wall("lobby wall west", "x", 0, 0, 10, H, material="accent")
    s.wall("lobby wall east", "x", 15, 0, 10, H)
    for k, (x, z) in enumerate([(4.4, 4.8), (10.1, 4.8)]):
        s.add("column %d" % (k + 1), "walls", box(x, x + 0.5, 0, H, z, z + 0.5))
    s.add("reception desk", "furniture", box(8.5, 11.5, 0, 1.1, 1.6, 2.4))
    for k, (x, z) in enumerate(grid(0, 15, 10, 0, 10, 6)):
        s.light("downlight %d" % (k + 1), (x, 3.85, z), 600, spot=(40, 30))
    return s.json({"position": [1.5, 1.7, 0.8], "target": [11.0, 1.4, 10.0]})


def glass_rooms_floor():
    s = Scene("Floor 24 x 14 x 3 m: five 4.8 x 4 m offices (z 0-4) with glazed fronts (glazing 0.8, 3.6 m wide, "
              "2.5 m high) and a 0.9 m doorway each onto a hall (z 4-14); 6 pendants of 250 cd in each office, "
              "72 spots of 300 cd in the hall: 102 lights; camera in the hall looking along the glass fronts.")
    H = 3.0
    s.shell("floor", 0, 24, 0, 14, H)
    s.wall("outer wall north", "z", 0, 0, 24, H)
    s.wall("outer wall south", "z", 14, 0, 24, H, material="accent")
    s.wall("outer wall west", "x", 0, 0, 14, H)
    s.wall("outer wall east", "x", 24, 0, 14, H)
    glazed = [(4.8 * i + 0.1, 4.8 * i + 3.7, 0, 2.5) for i in range(5)]
    doors = [(4.8 * i + 3.8, 4.8 * i + 4.7, 0, 2.1) for i in range(5)]
    s.wall("office fronts", "z", 4, 0, 24, H, holes=glazed + doors)
    for i, (u0, u1, v0, v1) in enumerate(glazed):
        s.pane("office %d glass" % (i + 1), "z", 4, u0, u1, v0, v1)
    for i in range(1, 5):
        s.wall("office partition %d" % i, "x", 4.8 * i, 0, 4, H)
    for i in range(5):
        s.add("office %d desk" % (i + 1), "furniture", box(4.8 * i + 1.2, 4.8 * i + 3.6, 0, 0.75, 0.6, 1.6))
        for k, (x, z) in enumerate(grid(4.8 * i, 4.8 * i + 4.8, 3, 0, 4, 2)):
            s.light("office %d pendant %d" % (i + 1, k + 1), (x, 2.6, z), 250)
    for k, (x, z) in enumerate(grid(0, 24, 12, 4, 14, 6)):
        s.light("hall spot %d" % (k + 1), (x, 2.88, z), 300, spot=(50, 35))
    s.add("hall bench 1", "furniture", box(8, 11, 0, 0.45, 8.5, 9.3))
    s.add("hall bench 2", "furniture", box(14, 17, 0, 0.45, 8.5, 9.3))
    return s.json({"position": [21.5, 1.6, 12.5], "target": [8.0, 1.2, 3.0]})


def lit_from_next_room():
    s = Scene("Dark room 6 x 5 x 3 m (x 0-6) without lights, lit through a 4 x 2.6 m opening glazed with a pane "
              "(0.8) in its east wall from a room 10 x 8 m (x 6-16) of 40 lights (two of three 300 cd spots, "
              "every third a 200 cd pendant); camera in the dark room, facing away from the opening.")
    H = 3.0
    s.shell("dark room", 0, 6, 0, 5, H)
    s.shell("lit room", 6, 16, 0, 8, H)
    s.wall("dark room wall west", "x", 0, 0, 5, H, material="accent")
    s.wall("dark room wall north", "z", 0, 0, 6, H)
    s.wall("dark room wall south", "z", 5, 0, 6, H)
    s.wall("shared wall", "x", 6, 0, 8, H, holes=[(0.5, 4.5, 0, 2.6)])
    s.pane("opening glass", "x", 6, 0.5, 4.5, 0, 2.6)
    s.wall("lit room wall north", "z", 0, 6, 16, H)
    s.wall("lit room wall south", "z", 8, 6, 16, H)
    s.wall("lit room wall east", "x", 16, 0, 8, H)
    s.add("dark room table", "furniture", box(1.5, 3.0, 0, 0.75, 1.0, 2.2))
    s.add("lit room desk", "furniture", box(10, 12.4, 0, 0.75, 3.2, 4.8))
    for k, (x, z) in enumerate(grid(6, 16, 8, 0, 8, 5)):
        if (k + 1) % 3 == 0:
            s.light("pendant %d" % (k + 1), (x, 2.5, z), 200)
        else:
            s.light("spot %d" % (k + 1), (x, 2.88, z), 300, spot=(55, 40))
    return s.json({"position": [5.5, 1.6, 4.7], "target": [0.0, 0.9, 1.0]})


def family():
    yield "glass_partition_office", glass_partition_office()
    yield "corridor", corridor()
    yield "mirror_lobby", mirror_lobby()
    yield "glass_rooms_floor", glass_rooms_floor()
    yield "lit_from_next_room", lit_from_next_room()


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.split("\n\n")[-1])
    out = pathlib.Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    for name, scene in family():
        path = out / (name + ".json")
        path.write_text(json.dumps(scene, indent=1) + "\n")
        triangles = sum(len(o["mesh"]["triangles"]) for o in scene["objects"])
        print("wrote %s (%d lights, %d triangles)" % (path, len(scene["lights"]), triangles))


if __name__ == "__main__":
    main()
