#!/usr/bin/env python3
"""An independent implementation of the DLP model of docs/model.md (numpy, whole-array stages),
written from the documentation alone: the lattice and launch (§2), the right-hand side of §1 with
each term (drag with constant C_D or the C_D(Re) law, gravity, heat transfer with Nu(Re),
burning by the d-law), the fixed-step Runge-Kutta methods (§3), the closed forms of §4.2-§4.6
and, where §4 has none, a reference of its own (RK4 at two step counts, Richardson-extrapolated).
It recomputes the L2 norms (§5) of every level of a dlpverify study from the study's JSON and
fails unless each level's L2 error e agrees within

    closed form:  1e-6 e + eps n ||y||
    no closed form (drag-gravity, drag-law, full):  1e-6 e + eps n ||y|| + 3 (err_ref + err_own)

and the reference's own L2 size ||y|| within 1e-13 ||y|| (plus the same 3 (err_ref + err_own)).
n is the level's step count: two implementations of one scheme round differently, and their
states may differ by about eps n ||y|| (measured on the closed-form cases: within 1e-2 of this
allowance; 1e-9 relative where the error is far above round-off, up to 5e-6 on RK4's finest
levels). err_ref is the study's estimate of its CVODE reference's error, err_own this reference's:
the two errors are measured against references at most err_ref + err_own apart, and 3 covers an
estimate's own inaccuracy (on drag-law the references differ by 1.15x dlpverify's estimate). The
own reference is refined until err_own is below 1e-6 of the finest level's error, and err_ref
must be below 1e-4 of it (dlpverify's trust rule asks 1e-2), so the allowance is 1e-6 relative
plus at most 3e-4 at the finest level, and less on coarser ones by their larger errors.

usage: independent_dlp.py STUDY.json      exit 0 agrees, 1 a level disagrees, 2 bad input
"""
import json
import math
import sys

import numpy as np

EPS = np.finfo(float).eps
EULER_GAMMA = 0.57721566490153286061

TABLEAUX = {  # (a, b) of docs/model.md §3's fixed-step methods; the right-hand side is autonomous
    "euler": ([[0.0]], [1.0]),
    "rk2": ([[0.0, 0.0], [0.5, 0.0]], [0.0, 1.0]),
    "heun": ([[0.0, 0.0], [1.0, 0.0]], [0.5, 0.5]),
    "rk4": ([[0, 0, 0, 0], [0.5, 0, 0, 0], [0, 0.5, 0, 0], [0, 0, 1, 0]], [1 / 6, 1 / 3, 1 / 3, 1 / 6]),
}

# The terms each case switches on (docs/model.md §1, §4; `dlpverify cases`), and its cloud.
CASES = {
    "similarity": dict(drag=None, gravity=False, heat=False, burning=False),
    "gravity": dict(drag=None, gravity=True, heat=False, burning=False),
    "drag": dict(drag="constant", gravity=False, heat=False, burning=False),
    "drag-gravity-vertical": dict(drag="constant", gravity=True, heat=False, burning=False, z_axis=True),
    "drag-gravity": dict(drag="constant", gravity=True, heat=False, burning=False),
    "drag-heat": dict(drag="constant", gravity=False, heat=True, burning=False),
    "burn": dict(drag="constant", gravity=False, heat=True, burning=True),
    "drag-law": dict(drag="law", gravity=False, heat=False, burning=False),
    "full": dict(drag="law", gravity=True, heat=True, burning=True),
}
VARIABLES = {"position": slice(0, 3), "velocity": slice(3, 6), "temperature": slice(6, 7), "mass": slice(7, 8)}


class Physics:
    """The parameters of docs/model.md §1 and §8, from the study's options."""

    def __init__(self, o, terms):
        self.terms = terms
        self.d0 = o["diameter"]
        self.rho_p, self.rho_a, self.mu_a = o["rho-p"], o["rho-gas"], o["mu-gas"]
        self.cd, self.cs, self.cp, self.pr = o["cd"], o["cs"], o["cp-gas"], o["prandtl"]
        self.t_a, self.t_p0 = o["t-gas"], o["t-particle"]
        self.g = o["g"] if terms["gravity"] else 0.0
        self.cb = o["cb"] if terms["burning"] else 0.0
        self.k_a = self.mu_a * self.cp / self.pr                  # gas conductivity
        self.kappa = 3 * self.rho_a * self.cd / (4 * self.rho_p)  # K = kappa / d
        self.beta = 2 * self.cb / (math.pi * self.rho_p)          # dd/dt = -beta
        self.m0 = math.pi * self.rho_p * self.d0 ** 3 / 6

    def rates(self, y):
        """dy/dt for y = [x, v, T, m] per particle, quiescent gas (w = -v), g = (0, 0, -g)."""
        v, temperature, m = y[:, 3:6], y[:, 6], y[:, 7]
        d = np.cbrt(6 * m / (math.pi * self.rho_p)) if self.terms["burning"] else np.full(len(y), self.d0)
        s = np.linalg.norm(v, axis=1)
        dy = np.zeros_like(y)
        dy[:, 0:3] = v
        if self.terms["drag"] == "constant":
            dy[:, 3:6] = -(3 * self.rho_a * self.cd / (4 * self.rho_p * d) * s)[:, None] * v
        elif self.terms["drag"] == "law":
            # C_D(Re) s = 0.48 s + 28 (rho_a d / mu_a)^-0.85 s^0.15, which is 0 at rest
            cd_s = 0.48 * s + 28 * (self.rho_a * d / self.mu_a) ** -0.85 * s ** 0.15
            dy[:, 3:6] = -(3 * self.rho_a / (4 * self.rho_p * d) * cd_s)[:, None] * v
        dy[:, 5] -= self.g
        if self.terms["heat"]:
            nusselt = 2 + 0.6 * self.pr ** (1 / 3) * np.sqrt(self.rho_a * s * d / self.mu_a)
            dy[:, 6] = 6 * self.k_a * nusselt / (self.rho_p * self.cs * d * d) * (self.t_a - temperature)
        if self.terms["burning"]:
            dy[:, 7] = -self.cb * d * d
        return dy


def cloud(o, z_axis):
    """docs/model.md §2: lattice points i^2 + j^2 + k^2 in [R_in^2, R_out^2], spacing Delta."""
    outer = o["outer"]
    inner = o["inner"] if o.get("inner") is not None else (outer - 5 if o["shape"] == "shell" else 1)
    r = np.arange(-outer, outer + 1)
    i, j, k = np.meshgrid(r, r, r, indexing="ij")
    r2 = i * i + j * j + k * k
    keep = (r2 >= inner * inner) & (r2 <= outer * outer)
    if z_axis:
        keep &= (i == 0) & (j == 0)
    return np.stack([i[keep], j[keep], k[keep]], axis=1).astype(float) * o["spacing"]


def expint_e1_scaled(x):
    """e^x E1(x) for x > 0: the power series below 1, the continued fraction
    E1(x) = e^-x / (x + 1 - 1^2 / (x + 3 - 2^2 / (x + 5 - ...))) above (evaluated backwards)."""
    x = np.asarray(x, dtype=float)
    small = x <= 1
    xs = np.where(small, x, 1.0)
    term, series = np.ones_like(xs), np.zeros_like(xs)
    for k in range(1, 40):
        term = term * -xs / k
        series += term / k
    e1_small = -EULER_GAMMA - np.log(xs) - series
    xl = np.where(small, 2.0, x)
    fraction = np.zeros_like(xl)
    for k in range(200, 0, -1):
        fraction = k * k / (xl + 2 * k + 1 - fraction)
    return np.where(small, np.exp(xs) * e1_small, 1 / (xl + 1 - fraction))


def gauss_legendre(f, tau, pieces=16, nodes=20):
    """The integral of f over [0, tau], composite Gauss-Legendre; f(t) gives one value per particle."""
    t, w = np.polynomial.legendre.leggauss(nodes)
    total = 0.0
    for p in range(pieces):
        lo, hi = tau * p / pieces, tau * (p + 1) / pieces
        for tk, wk in zip(t, w):
            total = total + wk * (hi - lo) / 2 * f(lo + (hi - lo) * (tk + 1) / 2)
    return total


def closed_form(case, ph, y0, tau):
    """docs/model.md §4.1-§4.6 at tau after launch, particle by particle; None where §4 has none."""
    x0, v0 = y0[:, 0:3], y0[:, 3:6]
    y = y0.copy()
    g = np.array([0.0, 0.0, -ph.g])
    s0 = np.linalg.norm(v0, axis=1)
    unit = np.divide(v0, s0[:, None], out=np.zeros_like(v0), where=s0[:, None] > 0)
    if case in ("similarity", "gravity"):
        y[:, 0:3] = x0 + v0 * tau + 0.5 * g * tau * tau
        y[:, 3:6] = v0 + g * tau
    elif case in ("drag", "drag-heat"):
        K = ph.kappa / ph.d0
        y[:, 0:3] = x0 + unit * (np.log1p(K * s0 * tau) / K)[:, None]
        y[:, 3:6] = unit * (s0 / (1 + K * s0 * tau))[:, None]
        if case == "drag-heat":
            # Lambda = 6 k_a / (rho_p d^2 c_s) [2 tau + 0.6 Pr^(1/3) (rho_a d / mu_a)^(1/2) I],
            # I = int_0^tau sqrt(s) dt = 2 tau sqrt(s0) / (sqrt(1 + K s0 tau) + 1)
            integral = 2 * tau * np.sqrt(s0) / (np.sqrt(1 + K * s0 * tau) + 1)
            lam = 6 * ph.k_a / (ph.rho_p * ph.d0 ** 2 * ph.cs) * (
                2 * tau + 0.6 * ph.pr ** (1 / 3) * math.sqrt(ph.rho_a * ph.d0 / ph.mu_a) * integral)
            y[:, 6] = ph.t_a + (ph.t_p0 - ph.t_a) * np.exp(-lam)
    elif case == "drag-gravity-vertical":
        K = ph.kappa / ph.d0
        v_t, tau_c = math.sqrt(ph.g / K), 1 / math.sqrt(ph.g * K)
        z, w = np.empty(len(y0)), np.empty(len(y0))
        for p, (z0, w0) in enumerate(zip(x0[:, 2], v0[:, 2])):
            if w0 > 0:  # rising: w = v_t tan(phi0 - t/tau_c) up to the apex, then falling from rest
                phi0 = math.atan(w0 / v_t)
                t_apex = tau_c * phi0
                if tau <= t_apex:
                    w[p] = v_t * math.tan(phi0 - tau / tau_c)
                    z[p] = z0 + math.log(math.cos(phi0 - tau / tau_c) / math.cos(phi0)) / K
                    continue
                z0, w0, t = z0 + math.log(1 / math.cos(phi0)) / K, 0.0, tau - t_apex
            else:
                t = tau
            if -w0 < v_t:  # falling slower than v_t: w = -v_t tanh(psi)
                psi0 = math.atanh(-w0 / v_t)
                w[p] = -v_t * math.tanh(psi0 + t / tau_c)
                z[p] = z0 - math.log(math.cosh(psi0 + t / tau_c) / math.cosh(psi0)) / K
            elif -w0 > v_t:  # falling faster than v_t: w = -v_t coth(psi)
                psi0 = math.atanh(v_t / -w0)
                w[p] = -v_t / math.tanh(psi0 + t / tau_c)
                z[p] = z0 - math.log(math.sinh(psi0 + t / tau_c) / math.sinh(psi0)) / K
            else:
                w[p], z[p] = -v_t, z0 - v_t * t
        y[:, 2], y[:, 5] = z, w
    elif case == "burn":
        # d = d0 - beta tau, u = ln(d0/d), 1/s = 1/s0 + (kappa/beta) u,
        # D = (d0/kappa) [E1s(a) - (d/d0) E1s(a + u)], a = beta / (kappa s0)
        d = ph.d0 - ph.beta * tau
        u = math.log(ph.d0 / d)
        moving = s0 > 0
        s0m = np.where(moving, s0, 1.0)
        a = ph.beta / (ph.kappa * s0m)
        distance = np.where(moving, ph.d0 / ph.kappa * (expint_e1_scaled(a) - d / ph.d0 * expint_e1_scaled(a + u)), 0.0)
        speed = np.where(moving, 1 / (1 / s0m + ph.kappa / ph.beta * u), 0.0)
        y[:, 0:3] = x0 + unit * distance[:, None]
        y[:, 3:6] = unit * speed[:, None]
        y[:, 7] = ph.m0 * (d / ph.d0) ** 3

        def heat_rate(t):  # 6 k_a Nu(t) / (rho_p c_s d(t)^2)
            d_t = ph.d0 - ph.beta * t
            s_t = np.where(moving, 1 / (1 / s0m + ph.kappa / ph.beta * math.log(ph.d0 / d_t)), 0.0)
            nusselt = 2 + 0.6 * ph.pr ** (1 / 3) * np.sqrt(ph.rho_a * s_t * d_t / ph.mu_a)
            return 6 * ph.k_a * nusselt / (ph.rho_p * ph.cs * d_t * d_t)

        y[:, 6] = ph.t_a + (ph.t_p0 - ph.t_a) * np.exp(-gauss_legendre(heat_rate, tau))
    else:
        return None
    return y


def runge_kutta(rates, y0, tau, steps, tableau):
    a, b = tableau
    dt = tau / steps
    y = y0.copy()
    for _ in range(steps):
        k = []
        for i in range(len(b)):
            stage = y.copy()
            for j in range(i):
                if a[i][j] != 0.0:
                    stage += dt * a[i][j] * k[j]
            k.append(rates(stage))
        for i in range(len(b)):
            if b[i] != 0.0:
                y = y + dt * b[i] * k[i]
    return y


def l2(difference, variable):
    return math.sqrt(np.sum(difference[:, VARIABLES[variable]] ** 2))


def numerical_reference(ph, y0, tau, finest, variables, steps):
    """RK4 at n and 2n steps, Richardson-extrapolated (order 5); its error is at most the
    2n solution's, estimated as |y_2n - y_n| / 15, and n doubles until that is below 1e-6 of the
    finest level's error in every variable."""
    coarse = runge_kutta(ph.rates, y0, tau, steps, TABLEAUX["rk4"])
    while True:
        fine = runge_kutta(ph.rates, y0, tau, 2 * steps, TABLEAUX["rk4"])
        reference = fine + (fine - coarse) / 15
        estimate = {v: l2(fine - coarse, v) / 15 for v in variables}
        finest_error = {v: l2(finest - reference, v) for v in variables}
        if all(estimate[v] <= 1e-6 * finest_error[v] for v in variables):
            return reference, estimate, finest_error, 2 * steps
        if steps > 100000:
            print(f"own reference: RK4 at {2 * steps} steps still {estimate} against finest {finest_error}")
            sys.exit(2)
        coarse, steps = fine, 2 * steps


def main(path):
    study = json.load(open(path))
    o, case = study["options"], study["case"]
    if case not in CASES or study["integrator"] not in TABLEAUX:
        print(f"independent_dlp.py covers the cases {', '.join(CASES)} and the integrators {', '.join(TABLEAUX)}")
        return 2
    terms = CASES[case]
    ph = Physics(o, terms)
    x0 = cloud(o, terms.get("z_axis", False))
    t0 = o["outer"] * o["spacing"] / o["us"]
    y0 = np.hstack([x0, x0 / t0, np.full((len(x0), 1), ph.t_p0), np.full((len(x0), 1), ph.m0)])
    tau = o["t-end"]
    variables = [v for v in VARIABLES if "l2_" + v in study["levels"][0]]
    expected = ["position", "velocity"] + (["temperature"] if terms["heat"] else []) + (["mass"] if terms["burning"] else [])
    if len(x0) != study["particles"] or variables != expected or len(study["levels"]) != o["levels"]:
        print(f"{len(x0)} particles and variables {expected} here; the study has {study['particles']} and {variables}")
        return 1

    solutions = [runge_kutta(ph.rates, y0, tau, level["steps"], TABLEAUX[study["integrator"]])
                 for level in study["levels"]]
    exact = closed_form(case, ph, y0, tau)
    reference_slack = {v: 0.0 for v in variables}
    if exact is None:
        exact, own, finest, steps = numerical_reference(ph, y0, tau, solutions[-1], variables,
                                                        max(study["levels"][-1]["steps"], 64))
        theirs = study["reference_error"]
        for v in variables:
            reference_slack[v] = 3 * (theirs[v] + own[v])
            print(f"reference {v}: own (RK4 at {steps} steps, Richardson) error <= {own[v]:.2e}, "
                  f"dlpverify's estimate {theirs[v]:.2e}, finest level's error {finest[v]:.2e}")
            if not theirs[v] <= 1e-4 * finest[v]:
                print(f"FAIL {v}: the study's reference error {theirs[v]:.2e} is not below 1e-4 of the finest "
                      f"level's error {finest[v]:.2e}: too loose to compare (--reference-rtol)")
                return 1

    # The reference's own L2 size, ||y(t)||: closed forms computed two ways agree to round-off.
    worst = 0.0
    for v in variables:
        mine, theirs = math.sqrt(np.sum(exact[:, VARIABLES[v]] ** 2)), study["levels"][-1]["norms_" + v]["solution_l2"]
        allowed = 1e-13 * mine + reference_slack[v]
        worst = max(worst, abs(mine - theirs) / allowed)
        print(f"reference size {v}: independent {mine:.15e} dlpverify {theirs:.15e} rel diff "
              f"{abs(mine - theirs) / mine:.2e} ({abs(mine - theirs) / allowed:.2e} of allowed)"
              + ("  FAIL" if abs(mine - theirs) > allowed else ""))
    for level, y in zip(study["levels"], solutions):
        for v in variables:
            mine, theirs = l2(y - exact, v), level["l2_" + v]
            size = math.sqrt(np.sum(exact[:, VARIABLES[v]] ** 2))
            allowed = 1e-6 * abs(mine) + EPS * level["steps"] * size + reference_slack[v]
            score = abs(mine - theirs) / allowed  # <= 1 passes
            worst = max(worst, score)
            print(f"level {level['level']} {v}: independent {mine:.12e} dlpverify {theirs:.12e} "
                  f"rel diff {abs(mine - theirs) / abs(mine) if mine else 0.0:.2e} ({score:.2e} of allowed)"
                  + ("  FAIL" if score > 1 else ""))
    print(f"{case}, {study['integrator']}, {len(x0)} particles: worst difference {worst:.2e} of allowed")
    return 0 if worst <= 1.0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
