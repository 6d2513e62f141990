#!/usr/bin/env python3
"""Derives the numbers of scenarios/adis16355-ar5.yaml and scenarios/adis16355-gm.yaml.

Pure Python (no numpy), so anyone can rerun it:  python3 scripts/derive_adis16355_presets.py
tests/errormodels/test_presets.cpp recomputes the same numbers in C++ and checks the YAML files.

1. AR(5) (seed paper's table; arburg convention A(z) = 1 + a1 z^-1 + ... + a5 z^-5, at 1 kHz):
   the output of the model must have the ADIS16355's total output noise, sigma_y = 0.60 deg/s rms
   (gyro) and 4.7 mg rms (accel), both stated for the unfiltered output over the sensor's 350 Hz
   bandwidth, which is what 1 ms sampling sees. The variance gain G = r(0)/sigma_e^2 of 1/A(z)
   (Yule-Walker equations) gives the driving noise sigma_e = sigma_y / sqrt(G).
2. GM (first order, discrete at 1 kHz): same variance sigma_y^2, and the correlation time tau that
   minimises sum_{k=1..500} (rho_AR(k) - exp(-k h / tau))^2 over lags 1 ms .. 500 ms
   (rho_AR = r(k)/r(0); by 500 lags every rho_AR is below 1e-3, so the range does not matter).
"""
import math

H = 1e-3  # [s] the paper's sampling interval
AXES = {
    "Gx": [-1.0327, -0.34341, 0.037895, 0.19732, 0.14724],
    "Gy": [-1.2391, -0.063362, 0.091524, 0.13092, 0.086379],
    "Gz": [-1.0604, -0.30249, 0.043657, 0.18006, 0.14555],
    "Ax": [-0.51552, -0.068261, -0.047218, -0.049565, -0.13655],
    "Ay": [-0.46354, -0.078197, -0.077146, -0.020449, -0.062445],
    "Az": [-0.41897, -0.10907, -0.077718, -0.074069, -0.1431],
}
SIGMA_Y = {"G": 0.60, "A": 4.7}  # deg/s, mg
UNIT = {"G": "deg/s", "A": "mg"}
MAXLAG = 500


def solve(M, b):
    n = len(b)
    M = [row[:] + [b[i]] for i, row in enumerate(M)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(M[r][c]))
        M[c], M[p] = M[p], M[c]
        for r in range(n):
            if r != c:
                f = M[r][c] / M[c][c]
                for k in range(c, n + 1):
                    M[r][k] -= f * M[c][k]
    return [M[i][n] / M[i][i] for i in range(n)]


def acov(a, maxlag):
    """r(0..maxlag) for sigma_e = 1: Yule-Walker r(k) + sum a_i r(|k-i|) = delta(k), k = 0..p."""
    p = len(a)
    M = [[0.0] * (p + 1) for _ in range(p + 1)]
    for k in range(p + 1):
        M[k][k] += 1.0
        for i in range(1, p + 1):
            M[k][abs(k - i)] += a[i - 1]
    r = solve(M, [1.0] + [0.0] * p)
    for k in range(p + 1, maxlag + 1):
        r.append(-sum(a[i - 1] * r[k - i] for i in range(1, p + 1)))
    return r


def gm_tau(rho):
    cost = lambda tau: sum((rho[k] - math.exp(-k * H / tau)) ** 2 for k in range(1, MAXLAG + 1))
    lo, hi = math.log(1e-4), math.log(1.0)  # golden section on log tau
    g = (math.sqrt(5) - 1) / 2
    for _ in range(200):
        x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
        if cost(math.exp(x1)) < cost(math.exp(x2)):
            hi = x2
        else:
            lo = x1
    tau = math.exp(0.5 * (lo + hi))
    return tau, cost(tau)


for name, a in AXES.items():
    r = acov(a, MAXLAG)
    G = r[0]
    sy = SIGMA_Y[name[0]]
    se = sy / math.sqrt(G)
    rho = [v / r[0] for v in r]
    A1 = 1 + sum(a)
    # Low-frequency density of the AR output (two-sided, IEEE 952 N): sigma_e sqrt(h) / |A(1)|
    N = se * math.sqrt(H) / abs(A1)
    tau, c = gm_tau(rho)
    lag_e = next(k for k in range(MAXLAG) if rho[k] < math.exp(-1))
    nunit = "deg/sqrt(h)" if name[0] == "G" else "mg/sqrt(Hz)"
    nval = N * 60 if name[0] == "G" else N
    print(f"{name}: G = {G:.6g}, sigma_e = {se:.6g} {UNIT[name[0]]}, "
          f"rho(1) = {rho[1]:.5f}, first lag below 1/e = {lag_e} ms, "
          f"low-freq density N = {nval:.4g} {nunit}, "
          f"GM: sigma = {sy} {UNIT[name[0]]}, tau = {tau * 1e3:.4f} ms (residual {c:.3g})")
