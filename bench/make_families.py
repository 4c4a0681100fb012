#!/usr/bin/env python3
"""Writes the held-out scene families of issue 21 (MIR, IR and CMLT on scenes nobody tuned them to):

    python3 bench/make_families.py DIR

DIR/door-*.json      two rooms joined by a door ajar at 2, 8 or 30 degrees, lit in the far room by a
                     ceiling panel, a point light or a luminaire, walls of different albedo
                     (variants of resources/scenes/door.json), 160x108;
DIR/caustic-*.json   glass of different shapes, mirrors and glossy floors under a small light
                     (variants of resources/scenes/caustics.json), 160x120;
DIR/cornell-*.json   the Cornell box with one block a mirror (chrome) or glass, under its area light
                     (issue 38: auto's candidates with specular surfaces and no point light), 128x128.
The closed spheres (albedo 0.5 to 0.9, closed form) come from `bench_make_scenes DIR`: albedo 0.5
and 0.8 decide, 0.6, 0.7 and 0.9 are held out.

Which members were used to decide changes and which were kept out of tuning is fixed in
FAMILIES below and in BENCHMARKS.md, "Held-out scene families (issue 21)"; it was committed
before the first change to a backend.
"""
import copy
import json
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "resources", "scenes")

# name -> (role, parameters). role "tune": used to decide; "held-out": only to confirm.
FAMILIES = {
    "door-a02-panel":          ("tune",     dict(angle=2,  light="panel",     albedo=1.0)),
    "door-a08-point":          ("tune",     dict(angle=8,  light="point",     albedo=1.0)),
    "door-a30-luminaire":      ("tune",     dict(angle=30, light="luminaire", albedo=1.0)),
    "door-a08-panel-dark":     ("held-out", dict(angle=8,  light="panel",     albedo=0.6)),
    "door-a02-luminaire-pale": ("held-out", dict(angle=2,  light="luminaire", albedo=1.15)),
    "caustic-satin-ball":      ("tune",     dict(glass="ball", floor_roughness=0.3,  mirrors=1, lamp=0.30)),
    "caustic-glass-cube":      ("tune",     dict(glass="cube", floor_roughness=0.12, mirrors=1, lamp=0.30)),
    "caustic-two-mirrors":     ("tune",     dict(glass=None,   floor_roughness=0.12, mirrors=2, lamp=0.30)),
    "caustic-small-light":     ("held-out", dict(glass="ball", floor_roughness=0.12, mirrors=1, lamp=0.12)),
    "caustic-slab-mirror":     ("held-out", dict(glass="slab", floor_roughness=0.05, mirrors=2, lamp=0.30)),
    "cornell-mirror-block":    ("held-out", dict(block="tall_block",  material="chrome")),
    "cornell-glass-block":     ("held-out", dict(block="short_block", material="glass")),
}

BOX_TRIANGLES = [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4], [3, 7, 6], [3, 6, 2],
                 [0, 4, 7], [0, 7, 3], [1, 2, 6], [1, 6, 5]]


def box(x0, y0, z0, x1, y1, z1):
    v = [[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0], [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]]
    return {"vertices": v, "triangles": BOX_TRIANGLES}


def door_scene(base, angle, light, albedo):
    s = copy.deepcopy(base)
    s["camera"]["resolution"] = [160, 108]
    for name, m in s["materials"].items():
        if m["type"] in ("diffuse", "glossy"):
            m["albedo"] = [min(0.95, a * albedo) for a in m["albedo"]]
    for o in s["objects"]:
        if o["name"] == "door":
            o["transform"]["rotate"] = [0, 1, 0, angle]
    panel_power = 600 * 0.8 * 0.8 * 3.14159  # W of the bundled door's panel (radiance x area x pi)
    if light != "panel":
        s["objects"] = [o for o in s["objects"] if o["name"] != "lamp"]
        del s["materials"]["lamp"]
        if light == "point":
            i = panel_power / (4 * 3.14159)
            s["lights"] = [{"name": "bulb", "type": "point", "position": [0.8, 2.3, 5.8], "intensity": [i, i * 0.93, i * 0.83]}]
        else:
            s["lights"] = [{"name": "downlight", "type": "luminaire", "file": "luminaires/downlight.ies",
                            "position": [0.8, 2.55, 5.8], "direction": [0, -1, 0], "lumens": 200000,
                            "temperature": 3000}]
    return s


def caustic_scene(base, glass, floor_roughness, mirrors, lamp):
    s = copy.deepcopy(base)
    s["camera"]["resolution"] = [160, 120]
    s["materials"]["floor"]["roughness"] = floor_roughness
    h = lamp / 2
    radiance = [c * (0.30 / lamp) ** 2 for c in s["materials"]["lamp"]["radiance"]]  # the same power
    s["materials"]["lamp"]["radiance"] = radiance
    objects = []
    for o in s["objects"]:
        if o["name"] == "lamp":
            o["mesh"] = {"quad": [[h, 2.49, 0.3 - h], [h, 2.49, 0.3 + h], [-h, 2.49, 0.3 + h], [-h, 2.49, 0.3 - h]]}
        if o["name"] == "glass_ball":
            if glass is None:
                continue
            if glass == "cube":
                o = {"name": "glass_cube", "material": "glass", "mesh": box(-0.3, 0, -0.3, 0.3, 0.6, 0.3),
                     "transform": {"rotate": [0, 1, 0, 30], "translate": [-0.45, 0, 0.2]}}
            elif glass == "slab":
                o = {"name": "glass_slab", "material": "glass", "mesh": box(-0.5, 0, -0.06, 0.5, 0.8, 0.06),
                     "transform": {"rotate": [0, 1, 0, -20], "translate": [-0.4, 0, 0.3]}}
        objects.append(o)
    if mirrors == 2:
        objects.append({"name": "mirror_panel", "material": "chrome", "mesh": box(-0.02, 0, -0.5, 0.02, 1.4, 0.5),
                        "transform": {"rotate": [0, 1, 0, 35], "translate": [-1.4, 0, 0.6]}})
    s["objects"] = objects
    return s


def cornell_scene(base, materials, block, material):
    s = copy.deepcopy(base)
    s["camera"]["resolution"] = [128, 128]
    s["materials"][material] = materials[material]
    for o in s["objects"]:
        if o["name"] == block:
            o["material"] = material
    return s


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_families.py DIR")
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for folder in ("luminaires", "meshes"):
        target = os.path.join(out, folder)
        if not os.path.exists(target):
            shutil.copytree(os.path.join(SCENES, folder), target)
    door = json.load(open(os.path.join(SCENES, "door.json")))
    caustic = json.load(open(os.path.join(SCENES, "caustics.json")))
    cornell = json.load(open(os.path.join(SCENES, "cornell-box.json")))
    for name, (role, p) in FAMILIES.items():
        if name.startswith("door"):
            scene = door_scene(door, **p)
        elif name.startswith("cornell"):
            scene = cornell_scene(cornell, caustic["materials"], **p)
        else:
            scene = caustic_scene(caustic, **p)
        path = os.path.join(out, name + ".json")
        with open(path, "w") as f:
            json.dump(scene, f, indent=1)
        print(f"{path} {role}")


if __name__ == "__main__":
    main()
