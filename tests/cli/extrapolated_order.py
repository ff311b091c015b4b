#!/usr/bin/env python3
"""The order a level search extrapolated, recomputed from its inputs (docs/verification.md, "An
order extrapolated from the pairwise orders").

For every variable of STUDY.json's level_search.extrapolated_order that has a value:
- its pairwise orders are the study's own: ln(e_{k-1}/e_k)/ln r over the run of `ok` levels that
  ends at the finest one, the last four at most ("reference errors"), or, for the differences
  between successive levels, ln(d_{k-1}/d_k)/ln r over the kept levels' self_difference_VAR (the
  orders of the levels beyond the reference's trust are not in the JSON and are taken as given);
- the gaps g_k = p_{k+1} - p_k are above 1e-6, their ratios in (0, 1) and within a factor 2;
- the value is Aitken's delta-squared on the last three, p_inf = p_last - g_last^2/(g_last - g_prev),
  and the half-width |p_inf - p_last|, plus |p_inf - p_inf'| (Aitken on the three before) with
  four orders: both to rounding;
- the check judges by it: pass exactly when |p_inf - P| <= tol.
With --contains-order, the integrator's order also lies within p_inf +/- half-width.

usage: extrapolated_order.py STUDY.json [--contains-order]
"""
import json
import math
import sys

ROUNDING = 1e-12


def aitken(orders):
    """Aitken's delta-squared limit of the last three pairwise orders."""
    p0, p1, p2 = orders[-3:]
    g_prev, g_last = p1 - p0, p2 - p1
    return p2 - g_last * g_last / (g_last - g_prev)


def half_width(orders):
    limit = aitken(orders)
    width = abs(limit - orders[-1])
    if len(orders) == 4:
        width += abs(limit - aitken(orders[:3]))
    return width


def pairwise(values, dts):
    return [math.log(values[k - 1] / values[k]) / math.log(dts[k - 1] / dts[k]) for k in range(1, len(values))]


def error_orders(study, name):
    """Pairwise orders of the errors over the run of ok (or pre-asymptotic: still converging) levels
    that ends at the finest such one."""
    levels = [level for level in study["levels"]
              if level["status_by_variable"][name]["status"] in ("ok", "pre-asymptotic")]
    run = levels[-1:]
    for level in reversed(levels[:-1]):
        if level["level"] != run[0]["level"] - 1:
            break
        run.insert(0, level)
    orders = pairwise([level["l2_" + name] for level in run], [level["dt"] for level in run])
    return orders[-4:]


def difference_orders(study, name):
    """Pairwise orders of the kept levels' differences from the level before (the first ones)."""
    levels = [level for level in study["levels"] if level["self_difference_" + name] is not None]
    return pairwise([level["self_difference_" + name] for level in levels], [level["dt"] for level in levels])


def check_variable(study, name, x, contains_order):
    orders = x["pairwise_orders"]
    assert 3 <= len(orders) <= 4, (name, orders)
    if x["source"] == "reference errors":
        recomputed = error_orders(study, name)
        assert len(recomputed) == len(orders), (name, recomputed, orders)
    else:
        assert x["source"] == "self-differences", x
        recomputed = difference_orders(study, name)
        assert 1 <= len(recomputed) < len(orders), (name, recomputed, orders)
    for mine, theirs in zip(recomputed, orders):
        assert abs(mine - theirs) <= ROUNDING * abs(mine), (name, "pairwise order", mine, theirs)
    gaps = [b - a for a, b in zip(orders, orders[1:])]
    ratios = [b / a for a, b in zip(gaps, gaps[1:])]
    assert all(abs(g) > 1e-6 for g in gaps), (name, "gaps", gaps)
    assert all(0 < q < 1 for q in ratios) and max(ratios) <= 2 * min(ratios), (name, "gap ratios", ratios)
    assert all(abs(q - r) <= ROUNDING for q, r in zip(ratios, x["gap_ratios"])), (name, ratios, x["gap_ratios"])
    limit, width = aitken(orders), half_width(orders)
    assert x["method"] == "aitken", x
    assert abs(x["value"] - limit) <= ROUNDING, (name, "value", x["value"], limit)
    assert abs(x["half_width"] - width) <= ROUNDING, (name, "half-width", x["half_width"], width)
    check = study["check"]
    miss = abs(limit - check["expected_order"])
    passes = miss <= check["tolerance"]
    # Outside the band with P inside the extrapolate's half-width, or above it, the data cannot decide.
    word = "pass" if passes else "INCONCLUSIVE" if miss <= width or limit > check["expected_order"] else "FAIL"
    finding = [f for f in check["findings"] if f.startswith(name + ": ")]
    assert len(finding) == 1 and "extrapolated (Aitken)" in finding[0], (name, check["findings"])
    assert finding[0].startswith(f"{name}: {word},"), (name, limit, check, finding)
    if contains_order:
        order = study["integrator_order"]
        assert abs(order - limit) <= width, (name, f"order {order} outside {limit:.3f} ± {width:.3f}")
    print(f"{name}: {limit:.4f} ± {width:.4f} from {', '.join(f'{p:.4f}' for p in orders)} "
          f"({x['source']}; {len(recomputed)} recomputed from the levels); {word} "
          f"at {check['expected_order']} ± {check['tolerance']}")


def main():
    study = json.load(open(sys.argv[1]))
    contains_order = "--contains-order" in sys.argv[2:]
    tried = study["level_search"]["extrapolated_order"]
    made = {name: x for name, x in tried.items() if "value" in x}
    for name, x in made.items():
        check_variable(study, name, x, contains_order)
    return made


if __name__ == "__main__":
    main()
