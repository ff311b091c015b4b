#!/usr/bin/env python3
"""Why a level search kept the levels it kept, recomputed from its JSON (docs/verification.md,
"Level statuses", "Trust margin", "Levels found by the study"), so that a test asserts the rule
rather than a count that a rounding-sized error could move.

- Every kept level's status per variable follows the rules, with e_k its L2 error, floor_k =
  1/2 eps sqrt(steps) |y|, p_k = ln(e_{k-1}/e_k)/ln r and P the expected order: unstable if e_k is
  not finite or >= |y|; round-off if e_k <= floor_k, or e_k <= 1000 floor_k and a coarser level is
  at round-off, or p_k < 3P/4 (for level 0, p_1); ok otherwise. Then the floor found from the
  errors: after a pairwise order >= 3P/4, the first ok level falling at p_k < 0.5 within 1e5
  floor_k, with no finer error back on e_{k-1} r^(-P (j-k)), is round-off with every finer ok
  level. (The growth pass is not redone: a level
  it set unstable is skipped.) Last, the window: while it has more than three ok levels, the
  coarsest leaves (pre-asymptotic) when its order to the next differs from the least-squares
  order of the finer ones by more than 0.05 and by more than the next order does.
- A search stopped on `round-off` ends at its first floor: the finest kept level is at round-off
  in some variable, every coarser one ok in every variable.
- A search stopped on `reference-accuracy` that left its newest level out kept only levels the
  reference trusts (error >= 100 x the reference's estimated error, every variable), and the
  level left out, the one after the kept ones, is named with a margin below 100.
Prints each decision's distance from its threshold.

usage: level_search_rules.py STUDY.json
"""
import json
import math
import re
import sys

EPS = 2.220446049250313e-16
TRUST = 100.0


def floor_of(level, name):
    norms = level["norms_" + name]
    floor = 0.5 * EPS * math.sqrt(level["steps"]) * norms["solution_l2"]
    assert abs(floor - norms["round_off_floor"]) <= 1e-12 * floor, (level["level"], name, floor, norms)
    return floor


def statuses(study, name, expected_order):
    """Each kept level's status for NAME by the rules of the table, coarse to fine."""
    levels, found = study["levels"], []
    errors = [level["l2_" + name] for level in levels]
    for k, level in enumerate(levels):
        e, floor, size = errors[k], floor_of(level, name), level["norms_" + name]["solution_l2"]
        order = None if k == 0 else math.log(errors[k - 1] / e) / math.log(levels[k - 1]["dt"] / level["dt"])
        next_order = None if k + 1 == len(levels) else math.log(e / errors[k + 1]) / math.log(
            level["dt"] / levels[k + 1]["dt"])
        near = e <= 1000 * floor
        if not math.isfinite(e) or e >= size:
            status = "unstable"
        elif e <= floor or (near and "round-off" in found):
            status = "round-off"
        elif near and order is not None and order < 0.75 * expected_order:
            status = "round-off"
        elif near and k == 0 and next_order is not None and next_order < 0.75 * expected_order:
            status = "round-off"
        else:
            status = "ok"
        found.append(status)
        print(f"  level {k} {name}: {status}, error/floor {e / floor:.3g}"
              + ("" if order is None else f", pairwise order {order:.3f}"))
    stalled_floor(levels, errors, [floor_of(level, name) for level in levels], found, expected_order)
    prune_window(levels, errors, found)
    return found


def pairwise(levels, errors, i, j):
    return math.log(errors[i] / errors[j]) / math.log(levels[i]["dt"] / levels[j]["dt"])


def stalled_floor(levels, errors, floors, found, expected_order):
    fastest = 0.0
    for k in range(1, len(levels)):
        if found[k] != "ok" or found[k - 1] != "ok":
            fastest = 0.0
            continue
        p = pairwise(levels, errors, k - 1, k)
        if p >= 0.5 or fastest < 0.75 * expected_order or errors[k] > 1e5 * floors[k]:
            fastest = max(fastest, p)
            continue
        ratio = levels[k - 1]["dt"] / levels[k]["dt"]
        if any(errors[j] <= errors[k - 1] * ratio ** (-expected_order * (j - k)) for j in range(k, len(levels))):
            continue
        for j in range(k, len(levels)):
            if found[j] == "ok":
                found[j] = "round-off"
        if k >= 3 and found[k - 2] == "ok" and \
                pairwise(levels, errors, k - 2, k - 1) < pairwise(levels, errors, k - 3, k - 2) - 0.1:
            found[k - 1] = "round-off"
        print(f"  floor from the errors at level {k} (order {p:.3f})")
        return


def least_squares_order(levels, errors, chosen):
    x = [math.log(levels[k]["dt"]) for k in chosen]
    y = [math.log(errors[k]) for k in chosen]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)


def prune_window(levels, errors, found):
    window = [k for k, status in enumerate(found) if status == "ok"]
    while len(window) > 3:
        finer = least_squares_order(levels, errors, window[1:])
        order = pairwise(levels, errors, window[0], window[1])
        following = pairwise(levels, errors, window[1], window[2])
        if not (abs(order - finer) > 0.05 and abs(following - finer) < abs(order - finer)):
            break
        found[window[0]] = "pre-asymptotic"
        print(f"  level {window[0]}: pre-asymptotic, order {order:.3f} vs {finer:.3f} of the finer levels")
        window.pop(0)


def check_statuses(study):
    expected_order = study["check"]["expected_order"]
    by_variable = {}
    for name in study["variables"]:
        found = statuses(study, name, expected_order)
        for level, status in zip(study["levels"], found):
            given = level["status_by_variable"][name]
            if given["rule"].startswith("error grows under refinement"):
                continue
            assert given["status"] == status, (level["level"], name, status, given)
        by_variable[name] = found
    return by_variable


def check_round_off_stop(study, by_variable):
    finest = len(study["levels"]) - 1
    assert any(found[finest] == "round-off" for found in by_variable.values()), by_variable
    for name, found in by_variable.items():
        assert all(status in ("ok", "pre-asymptotic") for status in found[:finest]), (name, found)


def check_trust(study):
    reason = study["level_search"]["reason"]
    left_out = re.match(r"level (\d+)'s (\w+) error is only ([0-9.e+-]+) x the reference's estimated error"
                        r" \(needs 100 x\)", reason)
    if not left_out or "it is left out" not in reason:
        return
    index, name, margin = int(left_out[1]), left_out[2], float(left_out[3])
    assert index == len(study["levels"]) and margin < TRUST, reason
    print(f"  level {index} left out: {name} margin {margin:g} < {TRUST:g}")
    for level in study["levels"]:
        for var, estimate in study["reference_error"].items():
            kept_margin = level["l2_" + var] / estimate
            assert kept_margin >= TRUST, (level["level"], var, kept_margin)
    finest = study["levels"][-1]
    print("  finest kept level's margins: " + ", ".join(
        f"{var} {finest['l2_' + var] / estimate:.3g}" for var, estimate in study["reference_error"].items()))


def main():
    study = json.load(open(sys.argv[1]))
    by_variable = check_statuses(study)
    stop = study["level_search"]["stop"]
    if stop == "round-off":
        check_round_off_stop(study, by_variable)
    if stop == "reference-accuracy":
        check_trust(study)


if __name__ == "__main__":
    main()
