"""Independent reference for the terminal ratio eps* of a sliding-spinning body (docs/physics.md §4).

Nothing here uses frictionid: the ring kernels P(k) and J(k) = Q + S of docs/physics.md §2 (kappa = 1,
no tilt) come from scipy's complete elliptic integrals, the radial integrals from adaptive
quadrature split at rho = eps, and eps* is the root of
    t(eps)/eps = (m2/m1) m_hat(eps) / i,    i = I/(M_b R^2),
i.e. T/(M_b v) = M_z/(I omega). For the seed/corrected closed forms (no tilt) the root is explicit:
    eps*^2 = ((mu/i)^2 a - 1) / (m - (mu/i)^2),  a = (2 m1/m0)^2, m = (2 m2/m3)^2, mu = m2/m1.
Prints CSV: case,eta_or_n,inertia_ratio,eps_exact,eps_seed ('' when there is no interior root).
"""
import math
import sys
import warnings

import numpy as np
from scipy.integrate import quad, IntegrationWarning
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

warnings.simplefilter("ignore", IntegrationWarning)


def P(k):  # ∫ (k - sin θ)/Δ dθ
    if k == 0.0:
        return 0.0
    if k < 1.0:
        return 4.0 / k * (ellipe(k * k) - (1.0 - k * k) * ellipk(k * k))
    return 4.0 * ellipe(1.0 / (k * k))


def J(k):  # ∫ (1 - k sin θ)/Δ dθ
    if k <= 1.0:
        return 4.0 * ellipe(k * k)
    q = 1.0 / (k * k)
    return 4.0 * k * (ellipe(q) - (1.0 - q) * ellipk(q))


def terminal(sigma, lo, inertia_ratio):
    """eps* for pressure sigma(rho) supported on [lo, 1]; None when there is no interior root."""
    mom = [quad(lambda r: sigma(r) * r ** n, lo, 1, epsabs=0, epsrel=1e-13, limit=200)[0]
           for n in range(4)]

    def radial(f, eps):
        pts = [eps] if lo < eps < 1 else None
        return quad(f, lo, 1, points=pts, epsabs=0, epsrel=1e-12, limit=400)[0]

    t = lambda e: radial(lambda r: sigma(r) * r * P(e / r), e) / (2 * math.pi * mom[1])
    mh = lambda e: radial(lambda r: sigma(r) * r * r * J(e / r), e) / (2 * math.pi * mom[2])
    mu = mom[2] / mom[1]
    G = lambda e: t(e) / e - mu * mh(e) / inertia_ratio
    grid = np.geomspace(1e-3, 1e3, 61)
    vals = [G(e) for e in grid]
    exact = None
    for (e0, g0), (e1, g1) in zip(zip(grid, vals), zip(grid[1:], vals[1:])):
        if g0 < 0 < g1:  # G rises through 0: d(eps)/dt = -(...)G falls, a stable root
            exact = brentq(G, e0, e1, xtol=1e-15, rtol=1e-15)
            break
    a = (2 * mom[1] / mom[0]) ** 2
    m = (2 * mom[2] / mom[3]) ** 2
    r = (mu / inertia_ratio) ** 2
    num, den = r * a - 1.0, m - r
    # num = 0 is the marginal case (e.g. Hertz pressure with i = 1/2): eps -> 0 only slowly.
    seed = math.sqrt(num / den) if num / den > 0 and abs(num) > 1e-12 else None
    return exact, seed


# Inner radii of the annulus curve (run.sh simulates the same list).
ANNULUS_B = (0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.99)


def ring_terminal():
    """eps* of the ring law (all load on rho = 1, I = M_b R^2): the root of P(eps) = eps J(eps).
    By the closed forms P - eps J = (1 - eps^2)(E - K) 4/eps (eps < 1, modulus eps), which
    vanishes only at eps = 1; the root is found numerically all the same."""
    return brentq(lambda e: P(e) / e - J(e), 0.5, 2.0, xtol=1e-15, rtol=1e-15)


def fmt(x):
    return "" if x is None else repr(float(x))


def main():
    rows = []
    e, s = terminal(lambda r: 1.0, 0.0, 0.5)
    rows.append(("uniform_disk", 0, 0.5, e, s))
    e, s = terminal(lambda r: 1.0, 0.0, 1.0)
    rows.append(("uniform_pressure_ring_inertia", 0, 1.0, e, s))
    e, s = terminal(lambda r: math.sqrt(max(0.0, 1 - r * r)), 0.0, 0.5)
    rows.append(("hertz_disk", 0, 0.5, e, s))
    for n in (8, 20, 50):
        e, s = terminal(lambda r, n=n: r ** n, 0.0, 1.0)
        rows.append(("rim_pressure_rho^n", n, 1.0, e, s))
    for eta in ANNULUS_B + (0.999,):
        # uniform annular disk: contact on eta < rho < 1, I = M (R_in^2 + R^2)/2
        e, s = terminal(lambda r: 1.0, eta, (1 + eta * eta) / 2)
        rows.append(("annulus", eta, (1 + eta * eta) / 2, e, s))
    # The ring law is the annulus at B = 1; its seed coefficients a = 4, m = 4 with mu = 1, i = 1
    # give eps*^2 = (4 - 1)/(4 - 1) = 1.
    rows.append(("annulus", 1.0, 1.0, ring_terminal(), 1.0))
    print("case,eta_or_n,inertia_ratio,eps_exact,eps_seed")
    for c, p, i, e, s in rows:
        print(f"{c},{p},{i!r},{fmt(e)},{fmt(s)}")


if __name__ == "__main__":
    sys.exit(main())
