# unit conversions through the model reader (with_param with unit strings and dict models), vs hand-computed SI
import sinsim, math
d2r = math.pi / 180; g0 = 9.80665
base = sinsim.Model({"gyro": {"all": [{"type": "white", "density": "0.3 deg/sqrt(h)"}, {"type": "bias", "value": "1 deg/h"}, {"type": "random_walk", "K": "1 deg/h/sqrt(h)"}, {"type": "gauss_markov", "sigma": "1 deg/s", "tau": "1 s"}]},
                     "accel": {"all": [{"type": "white", "density": "0.05 m/s/sqrt(h)"}, {"type": "bias", "value": "1 mg"}, {"type": "ramp", "slope": "1 m/s^3"}]}})
cases = [("gyro", 0, "density", "0.005 deg/s/sqrt(Hz)", 0.3 * d2r / 60), ("gyro", 0, "density", "18 deg/h/sqrt(Hz)", 0.3 * d2r / 60),
         ("gyro", 0, "density", "0.3 deg/sqrt(hr)", 0.3 * d2r / 60), ("gyro", 0, "density", "1 rad/sqrt(s)", 1.0),
         ("gyro", 1, "value", "1 dph", d2r / 3600), ("gyro", 1, "value", "1 arcsec/s", d2r / 3600), ("gyro", 1, "value", "1 mrad/s", 1e-3),
         ("gyro", 1, "value", "1 rev/min", 2 * math.pi / 60), ("gyro", 1, "value", "3600 deg/h", d2r), ("gyro", 1, "value", "1 deg/day", d2r / 86400),
         ("gyro", 2, "K", "1 deg/h/sqrt(h)", d2r / 3600 / 60), ("gyro", 2, "K", "1 deg/s/sqrt(s)", d2r), ("gyro", 2, "K", "1 deg/h^(3/2)", d2r / 3600 ** 1.5),
         ("gyro", 3, "tau", "1 min", 60.0), ("gyro", 3, "tau", "1 h", 3600.0), ("gyro", 3, "tau", "1 day", 86400.0), ("gyro", 3, "tau", "1 us", 1e-6), ("gyro", 3, "tau", "1 ns", 1e-9),
         ("accel", 0, "density", "100 ug/sqrt(Hz)", 100e-6 * g0), ("accel", 0, "density", "1 mg/sqrt(Hz)", 1e-3 * g0), ("accel", 0, "density", "1 ft/s/sqrt(h)", 0.3048 / 60),
         ("accel", 1, "value", "1 Gal", 0.01), ("accel", 1, "value", "1 g", g0), ("accel", 1, "value", "1 ft/s^2", 0.3048), ("accel", 1, "value", "1 km/h/s", 1 / 3.6),
         ("accel", 1, "value", "1 kn/s", 1852 / 3600), ("accel", 1, "value", "1e-3 g", 1e-3 * g0), ("accel", 1, "value", "1.5E+2 ug", 150e-6 * g0),
         ("accel", 2, "slope", "1 mg/min", 1e-3 * g0 / 60), ("accel", 2, "slope", "1 m/s^2/h", 1 / 3600)]
for s, i, k, v, exp in cases:
    try:
        got = base.with_param(s, "all", i, k, v).get(s, "all", i, k); rel = abs(got - exp) / abs(exp)
        print(f"{'ok ' if rel < 1e-12 else 'BAD'} {s}.{k} = {v!r:24} -> {got:.12g} (expected {exp:.12g}, rel {rel:.1e})")
    except Exception as e: print(f"ERR {s}.{k} = {v!r}: {type(e).__name__}: {e}")
