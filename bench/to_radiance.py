#!/usr/bin/env python3
"""A Lucerna scene (quads and inline triangle meshes; diffuse and glazing materials) as a
Radiance scene, for bench/radiance_annual.sh. Coordinates: Lucerna's (x east, y up, z south with
the default north) become Radiance's (x east, y north, z up): (x, y, z) -> (x, -z, y), a rotation.
Diffuse albedo -> plastic. Glazing (SPEC.md: transmittance t whatever the angle, no reflection)
has no Radiance equivalent: `glass` with the transmissivity that gives t at normal incidence, which
adds Fresnel's fall-off at oblique angles and its reflection. usage: to_radiance.py SCENE.json"""
import json, math, sys

def transmissivity(t):
    return (math.sqrt(0.8402528435 + 0.0072522239 * t * t) - 0.9166530661) / 0.0036261119 / t if t > 0 else 0

scene = json.load(open(sys.argv[1]))
out = []
for name, m in scene['materials'].items():
    if m['type'] == 'diffuse':
        out.append("void plastic %s\n0\n0\n5 %g %g %g 0 0\n" % ((name,) + tuple(m['albedo'])))
    elif m['type'] == 'glazing':
        out.append("void glass %s\n0\n0\n3 %g %g %g\n" % ((name,) + tuple(transmissivity(t) for t in m['transmittance'])))
    else:
        sys.exit("to_radiance.py: material type %s is not converted" % m['type'])
for o in scene['objects']:
    mesh = o['mesh']
    polygons = [mesh['quad']] if 'quad' in mesh else [[mesh['vertices'][i] for i in t] for t in mesh['triangles']]
    for j, polygon in enumerate(polygons):
        coords = " ".join("%g %g %g" % (x, -z, y) for x, y, z in polygon)
        out.append("%s polygon %s_%d\n0\n0\n%d %s\n" % (o['material'], o['name'], j, 3 * len(polygon), coords))
print("\n".join(out))
