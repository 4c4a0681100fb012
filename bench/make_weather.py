#!/usr/bin/env python3
"""Generate a synthetic typical-year EnergyPlus weather file (EPW).

Lucerna's annual daylight calculation (SPEC section 6) reads an EPW file.  We
do not bundle downloaded weather data, so this script makes a physically
sensible stand-in from models only (Python standard library, deterministic for
a given --seed):

* Sun position: NOAA solar-position algorithm (the NOAA Solar Calculator
  spreadsheet equations) at the mid-instant of each hour (hour - 0.5, local
  standard time, no daylight saving), apparent elevation with NOAA's
  refraction correction.  Instants fall in 2021, as SPEC section 6 reads them.
* Clear sky: Ineichen-Perez (Ineichen and Perez 2002) with Kasten-Young air
  mass, pressure-corrected, and a monthly Linke turbidity for Paris (3.0-4.4).
* Cloud cover: a Markov chain.  A daily weather regime (clear / broken /
  overcast) follows a persistent Markov chain whose stationary distribution is
  seasonal (cloudier winters); within it the hourly cover is a first-order
  (AR(1)) process that relaxes towards the regime's cover, so the cover
  persists over hours and days.  Cover is quantised to tenths (EPW's unit).
  As in a TMY's typical months, each month is the one of CANDIDATES
  continuations of the chain closest to Paris's monthly sunshine-duration
  and global-irradiation normals, so any seed gives a typical year.
* All-sky irradiance: direct normal Ib = Ib_clear * (1 - c)^K_BEAM (zero under
  full overcast); global horizontal by Kasten-Czeplak (1980),
  G = G_clear * (1 - 0.75 c^3.4), with an hourly optical-thickness variation
  under full overcast; diffuse horizontal Ed = G - Ib cos Z.
* Temperature, dew point, pressure, wind, rain: seasonal Paris-like
  climatology plus persistent (AR(1)) daily and hourly noise tied to the
  cloud regime.  Horizontal infrared radiation as EnergyPlus derives it.
* Illuminances: irradiance times a fixed luminous efficacy (not read by
  Lucerna).  Fields with no model carry EPW's missing-value codes.
* Temperature, dew point and pressure anomalies are centred per month, so
  monthly means follow the climatology.

The climate tables (turbidity, temperatures, cloudiness, sunshine) are Paris's
whatever --latitude/--longitude say; the site options only move the sun.

Usage: python3 bench/make_weather.py [--seed N] [-o FILE.epw]
A summary (annual global horizontal irradiation, sunshine hours, ...) goes to
stderr.
"""

import argparse
import math
import random
import sys

YEAR = 2021  # SPEC section 6: instants of a 8760-row file fall in 2021
DAYS_IN_MONTH = [31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31]
MONTH_NAMES = ["Jan", "Feb", "Mar", "Apr", "May", "Jun",
               "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"]

# Paris climatology (approximate 1981-2010 normals; Linke turbidity after the
# SoDa/Remund climatology).  Indexed by month 0..11.
LINKE_TURBIDITY = [3.0, 3.2, 3.5, 3.9, 4.0, 4.2, 4.4, 4.3, 3.8, 3.4, 3.1, 3.0]
# Stationary probability of the daily regimes (clear, broken, overcast).
REGIME_PROB = [
    (0.10, 0.28, 0.62),  # Jan
    (0.14, 0.31, 0.55),  # Feb
    (0.19, 0.37, 0.44),  # Mar
    (0.23, 0.41, 0.36),  # Apr
    (0.25, 0.43, 0.32),  # May
    (0.27, 0.44, 0.29),  # Jun
    (0.32, 0.43, 0.25),  # Jul
    (0.31, 0.43, 0.26),  # Aug
    (0.26, 0.41, 0.33),  # Sep
    (0.17, 0.36, 0.47),  # Oct
    (0.11, 0.29, 0.60),  # Nov
    (0.09, 0.26, 0.65),  # Dec
]
REGIME_COVER = (0.12, 0.52, 0.96)      # cover each regime relaxes towards
REGIME_NOISE = (0.10, 0.20, 0.06)      # innovation s.d. of the hourly AR(1)
DAY_PERSISTENCE = 0.55                 # P(regime repeats from one day to next)
HOUR_RELAX = 0.20                      # hourly relaxation towards the target
HOUR_AR = 0.85                         # hourly autocorrelation of the anomaly
K_BEAM = 1.6                           # Ib = Ib_clear * (1 - c)^K_BEAM
CANDIDATES = 8                         # chain continuations tried per month
# Paris normals the typical months are chosen against: sunshine duration
# (hours, Paris-Montsouris 1981-2010, 1662 h a year) and global horizontal
# irradiation (kWh/m^2, about 1120 a year).
SUNSHINE_NORMAL = [63, 79, 129, 166, 194, 202, 212, 212, 168, 118, 68, 51]
GHI_NORMAL = [28, 46, 84, 121, 149, 160, 163, 142, 101, 62, 32, 23]

T_MEAN, T_AMP = 12.4, 7.8              # dry bulb: annual mean and amplitude (C)
TD_MEAN, TD_AMP = 7.5, 5.5             # dew point: about 2 C Jan, 13 C Jul
COLDEST_DAY = 17                       # day of year of the seasonal minimum

EFFICACY_DIRECT = 95.0                 # lm/W
EFFICACY_DIFFUSE = 120.0               # lm/W
SIGMA = 5.6697e-8                      # Stefan-Boltzmann (EnergyPlus's value)


# --------------------------------------------------------------------------
# Sun position (NOAA Solar Calculator equations)
# --------------------------------------------------------------------------

def julian_day(year, month, day, hour_utc):
    """Julian day of a Gregorian calendar instant (hour_utc may be fractional
    or outside 0..24)."""
    y, m = year, month
    if m <= 2:
        y -= 1
        m += 12
    a = y // 100
    b = 2 - a + a // 4
    return (math.floor(365.25 * (y + 4716)) + math.floor(30.6001 * (m + 1))
            + day + b - 1524.5 + hour_utc / 24.0)


def sun_position(year, month, day, local_hour, lat, lon, tz):
    """Apparent solar zenith and azimuth (degrees, azimuth clockwise from
    north) at local standard time local_hour (fractional) of the date."""
    jd = julian_day(year, month, day, local_hour - tz)
    jc = (jd - 2451545.0) / 36525.0
    l0 = (280.46646 + jc * (36000.76983 + jc * 0.0003032)) % 360.0
    m = 357.52911 + jc * (35999.05029 - 0.0001537 * jc)
    e = 0.016708634 - jc * (0.000042037 + 0.0000001267 * jc)
    mr = math.radians(m)
    c = (math.sin(mr) * (1.914602 - jc * (0.004817 + 0.000014 * jc))
         + math.sin(2 * mr) * (0.019993 - 0.000101 * jc)
         + math.sin(3 * mr) * 0.000289)
    true_long = l0 + c
    omega = math.radians(125.04 - 1934.136 * jc)
    app_long = true_long - 0.00569 - 0.00478 * math.sin(omega)
    mean_obliq = 23.0 + (26.0 + (21.448 - jc * (46.815 + jc * (0.00059 - jc * 0.001813))) / 60.0) / 60.0
    obliq = mean_obliq + 0.00256 * math.cos(omega)
    eps = math.radians(obliq)
    decl = math.asin(math.sin(eps) * math.sin(math.radians(app_long)))
    y = math.tan(eps / 2.0) ** 2
    l0r = math.radians(l0)
    eq_time = 4.0 * math.degrees(
        y * math.sin(2 * l0r) - 2 * e * math.sin(mr)
        + 4 * e * y * math.sin(mr) * math.cos(2 * l0r)
        - 0.5 * y * y * math.sin(4 * l0r) - 1.25 * e * e * math.sin(2 * mr))
    tst = (local_hour * 60.0 + eq_time + 4.0 * lon - 60.0 * tz) % 1440.0
    ha = tst / 4.0 - 180.0
    latr = math.radians(lat)
    har = math.radians(ha)
    cosz = math.sin(latr) * math.sin(decl) + math.cos(latr) * math.cos(decl) * math.cos(har)
    cosz = max(-1.0, min(1.0, cosz))
    zen = math.degrees(math.acos(cosz))
    # azimuth, clockwise from north
    sz = math.sin(math.radians(zen))
    if abs(sz) < 1e-9 or abs(math.cos(latr)) < 1e-9:
        az = 180.0
    else:
        ca = (math.sin(latr) * cosz - math.sin(decl)) / (math.cos(latr) * sz)
        ca = max(-1.0, min(1.0, ca))
        a = math.degrees(math.acos(ca))
        az = (a + 180.0) % 360.0 if ha > 0 else (540.0 - a) % 360.0
    # NOAA atmospheric refraction (degrees)
    elev = 90.0 - zen
    if elev > 85.0:
        refr = 0.0
    else:
        te = math.tan(math.radians(elev))
        if elev > 5.0:
            refr = 58.1 / te - 0.07 / te ** 3 + 0.000086 / te ** 5
        elif elev > -0.575:
            refr = 1735.0 + elev * (-518.2 + elev * (103.4 + elev * (-12.79 + elev * 0.711)))
        else:
            refr = -20.772 / te
        refr /= 3600.0
    return zen - refr, az


# --------------------------------------------------------------------------
# Clear sky (Ineichen-Perez)
# --------------------------------------------------------------------------

def eccentricity(doy):
    """Spencer's Sun-Earth distance factor (as SPEC section 6 writes it)."""
    t = 2.0 * math.pi * (doy - 1) / 365.0
    return (1.00011 + 0.034221 * math.cos(t) + 0.00128 * math.sin(t)
            + 0.000719 * math.cos(2 * t) + 0.000077 * math.sin(2 * t))


def clear_sky(zen_deg, i0, linke, altitude_m):
    """Ineichen-Perez clear-sky (GHI, DNI, DHI) in W/m^2 for the apparent
    zenith angle zen_deg and extraterrestrial normal irradiance i0."""
    if zen_deg >= 90.0:
        return 0.0, 0.0, 0.0
    cosz = math.cos(math.radians(zen_deg))
    pressure = 101325.0 * (1.0 - 2.25577e-5 * altitude_m) ** 5.25588
    am_rel = 1.0 / (cosz + 0.50572 * (96.07995 - zen_deg) ** -1.6364)  # Kasten-Young 1989
    am = am_rel * pressure / 101325.0
    fh1 = math.exp(-altitude_m / 8000.0)
    fh2 = math.exp(-altitude_m / 1250.0)
    cg1 = 5.09e-5 * altitude_m + 0.868
    cg2 = 3.92e-5 * altitude_m + 0.0387
    ghi = cg1 * i0 * cosz * max(0.0, math.exp(-cg2 * am * (fh1 + fh2 * (linke - 1.0))))
    b = 0.664 + 0.163 / fh1
    dni1 = b * i0 * max(0.0, math.exp(-0.09 * am * (linke - 1.0)))
    dni2 = ghi * (1.0 - (0.1 - 0.2 * math.exp(-linke)) / (0.1 + 0.882 / fh1)) / cosz
    dni = max(0.0, min(dni1, dni2))
    dhi = max(0.0, ghi - dni * cosz)
    return ghi, dni, dhi


# --------------------------------------------------------------------------
# Helpers
# --------------------------------------------------------------------------

def season(doy):
    """-1 at the coldest time of year (mid January), +1 half a year later."""
    return -math.cos(2.0 * math.pi * (doy - COLDEST_DAY) / 365.0)


def sat_vapour_hpa(t):
    """Saturation vapour pressure over water, Magnus (Sonntag 1990), hPa."""
    return 6.112 * math.exp(17.62 * t / (243.12 + t))


def interp_daily(values, doy0, hour_mid):
    """Value of a per-day series at a fractional hour of day doy0 (0-based),
    linear between the days' noons."""
    x = doy0 + (hour_mid - 12.0) / 24.0
    i = math.floor(x)
    f = x - i
    n = len(values)
    a = values[max(0, min(n - 1, i))]
    b = values[max(0, min(n - 1, i + 1))]
    return a + (b - a) * f


def fmt(x, nd):
    s = "%.*f" % (nd, x)
    if s.startswith("-") and float(s) == 0.0:
        s = s[1:]
    return s


# --------------------------------------------------------------------------
# Generator
# --------------------------------------------------------------------------

def all_sky(g_cs, b_cs, cosz, tenths, tau):
    """Hourly (Ib, G, Ed), whole W/m^2, for a cover of tenths (0..10) from the
    clear-sky global g_cs and direct normal b_cs; tau scales the global
    irradiance under full overcast (optical thickness)."""
    if cosz <= 0.0:
        return 0, 0, 0
    c = tenths / 10.0
    ib = b_cs * (1.0 - c) ** K_BEAM
    g = g_cs * (1.0 - 0.75 * c ** 3.4)            # Kasten-Czeplak
    if tenths >= 10:
        ib = 0.0
        g *= tau
    ib_r = int(math.floor(ib + 0.5))
    g_r = int(math.floor(g + 0.5))
    ed_r = max(0, int(math.floor(g - ib_r * cosz + 0.5)))
    return ib_r, g_r, ed_r


def generate(args):
    ndays = 365
    lat, lon, tz, elev = args.latitude, args.longitude, args.timezone, args.elevation
    # independent, reproducible streams (str seeds are hashed deterministically)
    rng_cloud = random.Random("%d-cloud" % args.seed)
    rng = random.Random("%d-weather" % args.seed)

    # ---- sun and clear sky for every hour's mid-instant ------------------------
    sun = []           # (cosz, i0, g_cs, b_cs)
    doy = 0
    for mi, nd in enumerate(DAYS_IN_MONTH):
        for day in range(1, nd + 1):
            doy += 1
            i0 = 1367.0 * eccentricity(doy)
            for hour in range(1, 25):
                zen, _az = sun_position(YEAR, mi + 1, day, hour - 0.5, lat, lon, tz)
                g_cs, b_cs, _d_cs = clear_sky(zen, i0, LINKE_TURBIDITY[mi], elev)
                cosz = math.cos(math.radians(zen)) if zen < 90.0 else 0.0
                sun.append((cosz, i0, g_cs, b_cs))

    # ---- cloud cover: Markov chain, typical month selection --------------------
    # Daily regime: repeats with DAY_PERSISTENCE, else drawn from the month's
    # stationary distribution.  Hourly: latent cover m relaxes towards the
    # regime's cover, plus an AR(1) anomaly x.  Like a TMY's typical months,
    # each month is the candidate (of CANDIDATES continuations of the chain)
    # closest to Paris's monthly sunshine and global irradiation normals.
    def draw_regime(p):
        u = rng_cloud.random()
        return 0 if u < p[0] else (1 if u < p[0] + p[1] else 2)

    state = (draw_regime(REGIME_PROB[0]), None, 0.0, 0.0)   # (regime, m, x, tau)
    regimes, covers, overcast_tau = [], [], []
    first_day = 0
    for mi, nd in enumerate(DAYS_IN_MONTH):
        best = None
        for _k in range(CANDIDATES):
            r, m, x, tau = state
            c_reg, c_cov, c_tau = [], [], []
            sun_h, ghi = 0, 0.0
            for d in range(first_day, first_day + nd):
                if d > 0 and rng_cloud.random() >= DAY_PERSISTENCE:
                    r = draw_regime(REGIME_PROB[mi])
                c_reg.append(r)
                if m is None:
                    m = REGIME_COVER[r]
                for h in range(24):
                    m += HOUR_RELAX * (REGIME_COVER[r] - m)
                    x = HOUR_AR * x + REGIME_NOISE[r] * rng_cloud.gauss(0.0, 1.0)
                    tenths = int(math.floor(10.0 * min(1.0, max(0.0, m + x)) + 0.5))
                    tau = 0.8 * tau + 0.18 * rng_cloud.gauss(0.0, 1.0)
                    t_f = min(1.6, max(0.45, math.exp(tau)))
                    c_cov.append(tenths)
                    c_tau.append(t_f)
                    cosz, _i0, g_cs, b_cs = sun[24 * d + h]
                    ib_r, g_r, _ed = all_sky(g_cs, b_cs, cosz, tenths, t_f)
                    ghi += g_r
                    if ib_r > 120:
                        sun_h += 1
            score = (abs(sun_h - SUNSHINE_NORMAL[mi]) / SUNSHINE_NORMAL[mi]
                     + abs(ghi / 1000.0 - GHI_NORMAL[mi]) / GHI_NORMAL[mi])
            if best is None or score < best[0]:
                best = (score, c_reg, c_cov, c_tau, (r, m, x, tau))
        _s, c_reg, c_cov, c_tau, state = best
        regimes += c_reg
        covers += c_cov
        overcast_tau += c_tau
        first_day += nd

    # ---- daily synoptic anomalies (AR(1) over days) ---------------------------
    t_anom, td_anom, p_anom, wind_mean, wind_dir = [], [], [], [], []
    a_t = rng.gauss(0.0, 2.5)
    a_td = rng.gauss(0.0, 1.2)
    a_p = rng.gauss(0.0, 700.0)
    a_w = rng.gauss(0.0, 0.8)
    for d in range(ndays):
        s = season(d + 1)
        sd_t = 2.9 - 0.5 * s                     # more variable in winter
        a_t = 0.75 * a_t + math.sqrt(1 - 0.75 ** 2) * rng.gauss(0.0, sd_t)
        a_td = 0.6 * a_td + math.sqrt(1 - 0.6 ** 2) * rng.gauss(0.0, 1.3)
        a_p = 0.7 * a_p + math.sqrt(1 - 0.7 ** 2) * rng.gauss(0.0, 900.0 - 250.0 * s)
        a_w = 0.5 * a_w + math.sqrt(1 - 0.5 ** 2) * rng.gauss(0.0, 0.8)
        reg = regimes[d]
        # clear days: colder in winter, warmer in summer; overcast the reverse
        sign = 1.0 if reg == 0 else (-1.0 if reg == 2 else 0.0)
        t_anom.append(a_t + sign * 1.5 * s)
        td_anom.append(0.55 * a_t + a_td - (1.0 if reg == 0 else 0.0))
        p_anom.append(a_p + (500.0 if reg == 0 else (-500.0 if reg == 2 else 0.0)))
        base_w = 3.6 - 0.5 * s + (0.7 if reg == 2 else (-0.6 if reg == 0 else 0.0))
        wind_mean.append(max(0.8, base_w + a_w))
        # prevailing south-westerlies; anticyclonic clear days north-easterly
        centre = 45.0 if (reg == 0 and rng.random() < 0.6) else 225.0
        wind_dir.append((centre + rng.gauss(0.0, 50.0)) % 360.0)

    # A typical year: each month's mean anomaly is removed, so monthly means
    # of temperature, dew point and pressure follow the climatology.
    first_day = 0
    for nd in DAYS_IN_MONTH:
        for series in (t_anom, td_anom, p_anom):
            mean = sum(series[first_day:first_day + nd]) / nd
            for d in range(first_day, first_day + nd):
                series[d] -= mean
        first_day += nd

    # daily mean cover (drives the diurnal temperature range)
    day_cover = [sum(covers[24 * d:24 * d + 24]) / 240.0 for d in range(ndays)]
    t_day = []
    dtr_day = []
    for d in range(ndays):
        s = season(d + 1)
        t_day.append(T_MEAN + T_AMP * s + t_anom[d])
        dtr_max = 8.0 + 6.0 * (s + 1.0) / 2.0          # clear-day range, 8..14 K
        dtr_day.append(dtr_max * (1.0 - 0.6 * day_cover[d]))

    # ---- hourly rows ----------------------------------------------------------
    rows = []
    stats = {"ghi_wh": 0.0, "sun_hours": 0, "max_ib": 0, "daylight": 0,
             "rain_mm": 0.0, "cover_sum": 0.0, "t_sum": 0.0,
             "month_ghi": [0.0] * 12, "month_sun": [0] * 12,
             "possible_sun": 0}
    t_noise = 0.0
    td_noise = 0.0
    idx = 0
    doy = 0
    pressure_base = 101325.0 * (1.0 - 2.25577e-5 * elev) ** 5.25588
    for mi, nd in enumerate(DAYS_IN_MONTH):
        linke = LINKE_TURBIDITY[mi]
        for day in range(1, nd + 1):
            doy += 1
            for hour in range(1, 25):
                hm = hour - 0.5
                tenths = covers[idx]
                c = tenths / 10.0
                cosz, i0, g_cs, b_cs = sun[idx]
                ib_r, g_r, ed_r = all_sky(g_cs, b_cs, cosz, tenths, overcast_tau[idx])
                if cosz > 0.0:
                    etr_h = int(math.floor(i0 * cosz + 0.5))
                    etr_n = int(math.floor(i0 + 0.5))
                    if b_cs > 120.0:
                        stats["possible_sun"] += 1
                else:
                    etr_h = etr_n = 0

                # temperature and humidity
                t_noise = 0.7 * t_noise + 0.35 * rng.gauss(0.0, 1.0)
                td_noise = 0.8 * td_noise + 0.3 * rng.gauss(0.0, 1.0)
                tmean = interp_daily(t_day, doy - 1, hm)
                dtr = interp_daily(dtr_day, doy - 1, hm)
                t = tmean + 0.5 * dtr * math.cos(2.0 * math.pi * (hm - 15.0) / 24.0) + t_noise
                td = (TD_MEAN + TD_AMP * season(doy)
                      + interp_daily(td_anom, doy - 1, hm) + td_noise)
                td = min(td, t)
                rh = int(math.floor(100.0 * sat_vapour_hpa(td) / sat_vapour_hpa(t) + 0.5))
                rh = max(1, min(100, rh))
                pres = int(math.floor(pressure_base + interp_daily(p_anom, doy - 1, hm)
                                      - 150.0 * c + 0.5))

                # sky cover and infrared
                opaque = tenths
                if 0 < tenths < 10 and rng.random() < 0.5:
                    opaque = tenths - 1
                eps_sky = ((0.787 + 0.764 * math.log((td + 273.15) / 273.0))
                           * (1.0 + 0.0224 * opaque - 0.0035 * opaque ** 2
                              + 0.00028 * opaque ** 3))
                ir = int(math.floor(eps_sky * SIGMA * (t + 273.15) ** 4 + 0.5))

                # wind
                wmean = interp_daily(wind_mean, doy - 1, hm)
                ws = wmean * (1.0 + 0.25 * math.cos(2.0 * math.pi * (hm - 14.0) / 24.0))
                ws = max(0.0, ws + rng.gauss(0.0, 0.25 * wmean))
                ws = round(ws, 1)
                if ws < 0.5:
                    ws, wd = 0.0, 0
                else:
                    wd = int(10 * math.floor((wind_dir[doy - 1] + rng.gauss(0.0, 20.0)) % 360.0 / 10.0 + 0.5)) % 360
                    if wd == 0:
                        wd = 360

                # rain: mostly from overcast skies
                p_rain = 0.25 if tenths >= 10 else (0.06 if tenths >= 8 else 0.0)
                rain = 0.0
                if rng.random() < p_rain:
                    rain = round(min(12.0, rng.expovariate(1.0 / 0.9)), 1)

                pw_mm = 10.0 * math.exp(0.07 * td - 0.075)
                aod = 0.05 + 0.04 * (linke - 2.0)

                ill_dn = int(math.floor(EFFICACY_DIRECT * ib_r + 0.5))
                ill_dh = int(math.floor(EFFICACY_DIFFUSE * ed_r + 0.5))
                ill_gh = int(math.floor(EFFICACY_DIRECT * ib_r * cosz + ill_dh + 0.5))

                fields = [
                    str(YEAR), str(mi + 1), str(day), str(hour), "0",
                    "?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9?9?9*9*9?9?9?9",
                    fmt(t, 1), fmt(td, 1), str(rh), str(pres),
                    str(etr_h), str(etr_n), str(ir),
                    str(g_r), str(ib_r), str(ed_r),
                    str(ill_gh), str(ill_dn), str(ill_dh), "9999",
                    str(wd), fmt(ws, 1), str(tenths), str(opaque),
                    "9999", "99999", "9", "999999999",
                    str(int(math.floor(pw_mm + 0.5))), fmt(aod, 3),
                    "0", "88", "0.20", fmt(rain, 1), "1.0",
                ]
                assert len(fields) == 35
                rows.append(",".join(fields))

                stats["ghi_wh"] += g_r
                stats["month_ghi"][mi] += g_r
                if ib_r > 120:
                    stats["sun_hours"] += 1
                    stats["month_sun"][mi] += 1
                stats["max_ib"] = max(stats["max_ib"], ib_r)
                if ib_r > 0 or ed_r > 0:
                    stats["daylight"] += 1
                    stats["cover_sum"] += tenths / 10.0
                stats["rain_mm"] += rain
                stats["t_sum"] += t
                idx += 1
    stats["regime_days"] = [regimes.count(k) for k in range(3)]
    return rows, stats, t_day


def ground_temperatures(t_day):
    """Monthly ground temperatures at 0.5, 2 and 4 m (Kusuda-Achenbach with
    a soil diffusivity of 0.055 m^2/day) from the daily air temperatures."""
    mean = sum(t_day) / len(t_day)
    # amplitude and phase of the annual harmonic
    a = sum(t * math.cos(2 * math.pi * d / 365.0) for d, t in enumerate(t_day)) * 2 / 365.0
    b = sum(t * math.sin(2 * math.pi * d / 365.0) for d, t in enumerate(t_day)) * 2 / 365.0
    amp = math.hypot(a, b)
    phase = math.atan2(b, a)        # t(d) ~ mean + amp cos(w d - phase)
    alpha = 0.055
    out = ["GROUND TEMPERATURES", "3"]
    for depth in (0.5, 2.0, 4.0):
        damp = depth * math.sqrt(math.pi / (365.0 * alpha))
        out += ["%.1f" % depth, "", "", ""]
        start = 0
        for nd in DAYS_IN_MONTH:
            mid = start + nd / 2.0
            start += nd
            v = mean + amp * math.exp(-damp) * math.cos(2 * math.pi * mid / 365.0 - phase - damp)
            out.append("%.2f" % v)
    return ",".join(out)


def extreme_periods(rows):
    """Weeks nearest the summer maximum and winter minimum temperature."""
    temps = [float(r.split(",")[6]) for r in rows]
    daily = [sum(temps[24 * d:24 * d + 24]) / 24.0 for d in range(365)]

    def week_label(d0):
        def md(d):
            mi = 0
            while d >= DAYS_IN_MONTH[mi]:
                d -= DAYS_IN_MONTH[mi]
                mi += 1
            return "%2d/%2d" % (mi + 1, d + 1)
        return md(d0), md(d0 + 6)

    def best_week(first, last, key):
        best = None
        for d0 in range(first, last - 6 + 1):
            v = sum(daily[d0:d0 + 7]) / 7.0
            if best is None or key(v) > key(best[1]):
                best = (d0, v)
        return best[0]

    summer = best_week(151, 242, lambda v: v)        # June-August
    winter = best_week(0, 58, lambda v: -v)          # January-February
    s0, s1 = week_label(summer)
    w0, w1 = week_label(winter)
    return ("TYPICAL/EXTREME PERIODS,2,Summer - Week Nearest Max Temperature For Period,Extreme,"
            "%s,%s,Winter - Week Nearest Min Temperature For Period,Extreme,%s,%s" % (s0, s1, w0, w1))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seed", type=int, default=1, help="random seed (default 1)")
    ap.add_argument("-o", "--output", default="-", help="EPW file to write (default stdout)")
    ap.add_argument("--city", default="Paris (synthetic)")
    ap.add_argument("--region", default="Ile-de-France")
    ap.add_argument("--country", default="FRA")
    ap.add_argument("--wmo", default="071560")
    ap.add_argument("--latitude", type=float, default=48.857)
    ap.add_argument("--longitude", type=float, default=2.352)
    ap.add_argument("--timezone", type=float, default=1.0, help="hours from UTC")
    ap.add_argument("--elevation", type=float, default=35.0, help="metres")
    args = ap.parse_args()

    rows, st, t_day = generate(args)
    header = [
        "LOCATION,%s,%s,%s,Lucerna synthetic (clear-sky model with generated cloud cover),%s,%s,%s,%s,%s"
        % (args.city, args.region, args.country, args.wmo, fmt(args.latitude, 3),
           fmt(args.longitude, 3), fmt(args.timezone, 1), fmt(args.elevation, 1)),
        "DESIGN CONDITIONS,0",
        extreme_periods(rows),
        ground_temperatures(t_day),
        "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0",
        "COMMENTS 1,Synthetic typical year for Lucerna's annual daylight tests -- NOT measured weather",
        "COMMENTS 2,Generated by bench/make_weather.py --seed %d: NOAA sun position at hour-0.5 LST;"
        " Ineichen-Perez clear sky with monthly Linke turbidity; Markov-chain cloud cover;"
        " Ib=Ib_clear(1-c)^%g; Kasten-Czeplak global; diffuse=global-Ib cosZ; Paris-like climatology"
        % (args.seed, K_BEAM),
        "DATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31",
    ]
    text = "\n".join(header + rows) + "\n"
    if args.output == "-":
        sys.stdout.write(text)
    else:
        with open(args.output, "w", newline="\n", encoding="ascii") as f:
            f.write(text)

    err = sys.stderr
    print("make_weather: seed %d, %d rows" % (args.seed, len(rows)), file=err)
    print("  annual global horizontal irradiation: %.0f kWh/m^2" % (st["ghi_wh"] / 1000.0), file=err)
    print("  sunshine hours (Ib > 120 W/m^2): %d (of %d possible under clear sky)"
          % (st["sun_hours"], st["possible_sun"]), file=err)
    print("  max direct normal irradiance Ib: %d W/m^2" % st["max_ib"], file=err)
    print("  daylight hours (Ib > 0 or Ed > 0): %d" % st["daylight"], file=err)
    print("  monthly GHI kWh/m^2: " + " ".join("%s %.0f" % (n, v / 1000.0) for n, v in
                                              zip(MONTH_NAMES, st["month_ghi"])), file=err)
    print("  monthly sunshine h:  " + " ".join("%s %d" % (n, v) for n, v in
                                              zip(MONTH_NAMES, st["month_sun"])), file=err)
    print("  mean daytime cover %.2f; regime days clear/broken/overcast %d/%d/%d; "
          "mean dry bulb %.1f C; rain %.0f mm"
          % (st["cover_sum"] / max(1, st["daylight"]), *st["regime_days"],
             st["t_sum"] / len(rows), st["rain_mm"]), file=err)


if __name__ == "__main__":
    main()
