#!/usr/bin/env bash
# The bundled office's year by Radiance's 2-phase daylight coefficients (rfluxmtx with the Reinhart
# MF:4 sky, gendaymtx, dctimestep) against `lucerna annual` on the same 54 points (BENCHMARKS.md,
# "Annual daylight"). RADIANCE: a build of github.com/NREL/Radiance (cmake; its bin/ and the
# source tree for RAYPATH), never a dependency of Lucerna. With OPEN=1 the glazed panes are taken
# out of both (Radiance's glass has Fresnel's angular fall-off, SPEC.md's glazing none).
# usage: [OPEN=1] bench/radiance_annual.sh RADIANCE_SRC RADIANCE_BIN [OUT]; then
# python3 bench/radiance_compare.py OUT/lucerna.csv OUT/radiance.txt
set -euo pipefail
cd "$(dirname "$0")/.."
SRC=$1 BIN=$2 OUT=${3:-/tmp/radiance_annual}
export PATH=$BIN:$PATH RAYPATH=$SRC/src/cal/cal:$SRC/src/util:$SRC/src/rt:.
mkdir -p "$OUT"
SCENE=resources/scenes/daylit_office.json EPW=resources/weather/paris_synthetic.epw
if [ "${OPEN:-0}" = 1 ]; then
    python3 -c "
import json
s = json.load(open('$SCENE'))
s['objects'] = [o for o in s['objects'] if s['materials'][o['material']]['type'] != 'glazing']
json.dump(s, open('$OUT/open.json', 'w'))"
    SCENE=$OUT/open.json
fi
build/app/lucerna annual $SCENE --weather $EPW --task-area "Reference plane" --spacing 0.6 --dew-point 11 \
    --csv "$OUT/points.csv" --hourly "$OUT/lucerna.csv" > /dev/null
python3 -c "
import csv
rows = list(csv.DictReader(open('$OUT/points.csv')))
open('$OUT/points.txt', 'w').write(''.join('%s %g %s 0 0 1\n' % (p['x'], -float(p['z']), p['y']) for p in rows))"
python3 bench/to_radiance.py $SCENE > "$OUT/office.rad"
cat > "$OUT/sky.rad" <<'SKY'
#@rfluxmtx h=u u=+Y
void glow groundglow 0 0 4 1 1 1 0
groundglow source ground 0 0 4 0 0 -1 180
#@rfluxmtx h=r4 u=+Y
void glow skyglow 0 0 4 1 1 1 0
skyglow source skydome 0 0 4 0 0 1 180
SKY
cd "$OUT"
/usr/bin/time -f "rfluxmtx %e s" rfluxmtx -I+ -ab 6 -ad 8192 -lw 2e-5 -n 2 -y 54 - sky.rad office.rad < points.txt > dc.mtx
epw2wea "$OLDPWD/$EPW" sky.wea > /dev/null
/usr/bin/time -f "gendaymtx %e s" gendaymtx -m 4 sky.wea > sky.smx
/usr/bin/time -f "dctimestep %e s" sh -c 'dctimestep dc.mtx sky.smx | rmtxop -fa -c 47.4 119.9 11.6 - > radiance.txt'
