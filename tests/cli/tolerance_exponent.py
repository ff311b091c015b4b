#!/usr/bin/env python3
"""A tolerance study's exponents against the exponent its error control predicts
(docs/verification.md, "Adaptive integrators by tolerance", "Which exponent to expect").

Per variable, over the study's runs_used:
- the exponent and its 95% interval are recomputed: the least-squares slope of ln e against
  ln rtol, its standard error sqrt(SSR/(n-2)/Sxx) and slope +/- t(0.975, n-2) x SE (to rounding,
  the interval to the table's digits);
- the predicted exponent: with the estimate held near rtol at the local error of the lower of a
  table's order q and its embedding's p, h^(min(p,q)+1) ~ rtol, and the global error h^q,
  E = q/(min(p,q)+1), p and q the last two numbers of the ARKODE name; CVODE estimates the local
  error of its own order-q formula (p = q), E = q/(q+1), and changes q as it goes, so the band
  from the lowest to the highest order it reports over the runs (last_order) is predicted; an
  integrator without error control (EXPONENT=0 given) has E = 0;
- the exponent lies within the band widened by the fit's 95% half-width plus the spread of the
  pairwise exponents ln(e_i/e_{i+1})/ln(rtol_i/rtol_{i+1}) over the sweep (how far the local slope
  still moves: the distance from the asymptotic regime), for a table of fixed order; for CVODE,
  whose pairwise exponents jump by about 1 as its order changes, the widening is the fit's
  half-width alone.

usage: tolerance_exponent.py STUDY.json [EXPONENT]
"""
import json
import math
import re
import sys

# Student's t, 0.975 quantile, by degrees of freedom (any statistics table).
T975 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306, 9: 2.262, 10: 2.228}


def fit(x, y):
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((a - mx) ** 2 for a in x)
    slope = sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx
    residuals = [b - my - slope * (a - mx) for a, b in zip(x, y)]
    stderr = math.sqrt(sum(r * r for r in residuals) / (n - 2) / sxx)
    return slope, stderr, T975[n - 2] * stderr


def predicted(study, runs, given):
    """The band [low, high] of exponents the error control predicts, and whether the order varies."""
    if given is not None:
        return (given, given), False
    integrator = study["integrator"]
    if integrator == "cvode":
        orders = [run["solver_statistics"]["last_order"] for run in runs]
        return (min(orders) / (min(orders) + 1), max(orders) / (max(orders) + 1)), True
    p, q = map(int, re.fullmatch(r"arkode-adaptive:ARKODE_\w+_\d+_(\d+)_(\d+)", integrator).groups())
    e = q / (min(p, q) + 1)
    return (e, e), False


def main():
    study = json.load(open(sys.argv[1]))
    given = float(sys.argv[2]) if len(sys.argv) > 2 else None
    for name, p in study["proportionality"].items():
        runs = [study["runs"][i] for i in p["runs_used"]]
        x = [math.log(run["rtol"]) for run in runs]
        y = [math.log(run["l2_" + name]) for run in runs]
        slope, stderr, half = fit(x, y)
        assert abs(slope - p["exponent"]) <= 1e-9, (name, slope, p)
        assert abs(stderr - p["stderr"]) <= 1e-9 + 1e-9 * stderr, (name, stderr, p)
        given_half = (p["ci95"][1] - p["ci95"][0]) / 2
        assert abs(given_half - half) <= 1e-3 * half + 1e-12, (name, half, p)
        pairwise = [(y[i] - y[i + 1]) / (x[i] - x[i + 1]) for i in range(len(x) - 1)]
        (low, high), variable_order = predicted(study, runs, given)
        spread = max(pairwise) - min(pairwise)
        width = given_half + (0 if variable_order else spread)
        print(f"{name}: exponent {slope:.3f} ± {given_half:.3f}, predicted {low:.3f}"
              + (f" … {high:.3f}" if high > low else "")
              + f"; pairwise {', '.join(f'{e:.3f}' for e in pairwise)} (spread {spread:.3f}); allowed ± {width:.3f}")
        assert low - width - 1e-12 <= slope <= high + width + 1e-12, (name, slope, (low, high), width)


if __name__ == "__main__":
    main()
