#!/usr/bin/env bash
# `check --levels auto` (docs/verification.md, "Levels found by the study"): the study finds its
# own levels from the case's coarsest Δt, passes the expected order, and says in its JSON which
# levels it ran and kept and why it stopped. Asserts the stop reason when one is given, and with
# EXPECT_TIGHTENINGS=N in the environment that the reference was tightened N times, the last time
# to a reference whose description holds EXPECT_TIGHTENED_TO (which the study then reports); with
# EXPECT_KEPT=N that N levels were kept, and with EXPECT_REASON=TEXT that the stop's reason holds TEXT.
# A search stopped on its interval tries no extrapolated order; every order it extrapolated is
# recomputed by extrapolated_order.py (Aitken's Δ² from the study's own pairwise orders, the check's
# verdict by it); with EXPECT_EXTRAPOLATED=VAR the order of VAR was extrapolated and the
# integrator's order lies within its half-width, and with EXPECT_EXTRAPOLATION_REFUSED=VAR=TEXT it
# was refused for a reason holding TEXT; with EXPECT_SOURCE=S it came from S ("reference errors" or
# "self-differences"), and with EXPECT_BEYOND=N N levels beyond the reference's trust were solved
# for their self-differences, outside the fit. Every search's kept levels follow the status and
# trust rules, recomputed by level_search_rules.py.
#
# usage: levels_auto.sh DLPVERIFY EXIT STOP|any CHECK-ARGS...
set -u
dlpverify=$1 expected_exit=$2 expected_stop=$3
shift 3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$dlpverify" check --levels auto "$@" --json "$out/study.json" >"$out/table.txt" 2>"$out/stderr.txt"
code=$?
if [ "$code" -ne "$expected_exit" ]; then
  echo "FAIL: exit $code, expected $expected_exit"; cat "$out/table.txt" "$out/stderr.txt"; exit 1
fi
python3 - "$out/study.json" "$expected_stop" <<'PY' || { cat "$out/table.txt"; exit 1; }
import json, os, sys
study = json.load(open(sys.argv[1]))
search = study["level_search"]
kept = [run for run in search["run"] if run["kept"]]
# The kept levels are the study's levels, in order, each a ratio finer than the one before.
assert [run["dt"] for run in kept] == [level["dt"] for level in study["levels"]], "kept levels are not the study's"
assert len(kept) >= 3 or search["stop"] == "reference-accuracy", f"only {len(kept)} levels kept"
assert search["stop"] in ("order-interval", "round-off", "reference-accuracy"), f"stopped by {search['stop']}"
if sys.argv[2] != "any":
    assert search["stop"] == sys.argv[2], f"stopped by {search['stop']}, expected {sys.argv[2]}: {search['reason']}"
for name in study["variables"]:
    assert search["levels_used"][name] == study["fitted_order"][name]["levels_used"]
if os.environ.get("EXPECT_KEPT"):
    assert len(kept) == int(os.environ["EXPECT_KEPT"]), f"{len(kept)} levels kept, expected {os.environ['EXPECT_KEPT']}"
if os.environ.get("EXPECT_REASON"):
    assert os.environ["EXPECT_REASON"] in search["reason"], search["reason"]
extrapolated = search["extrapolated_order"]
if search["stop"] == "order-interval":
    assert not extrapolated, f"extrapolation tried on a settled search: {extrapolated}"
if os.environ.get("EXPECT_EXTRAPOLATED"):
    name = os.environ["EXPECT_EXTRAPOLATED"]
    x = extrapolated[name]
    assert "value" in x, x
    if os.environ.get("EXPECT_SOURCE"):
        assert x["source"] == os.environ["EXPECT_SOURCE"], x
if os.environ.get("EXPECT_BEYOND"):
    beyond = [run for run in search["run"] if run["note"].startswith("beyond the reference's trust")]
    assert len(beyond) == int(os.environ["EXPECT_BEYOND"]), search["run"]
    finest_kept = min(run["dt"] for run in kept)
    assert all(run["dt"] < finest_kept for run in beyond), search["run"]
    x = extrapolated[os.environ["EXPECT_EXTRAPOLATED"]]
    assert x["reference_trusted_to"] == finest_kept, x
    assert x["difference_dt"][-1] == beyond[-1]["dt"], x
if os.environ.get("EXPECT_EXTRAPOLATION_REFUSED"):
    name, text = os.environ["EXPECT_EXTRAPOLATION_REFUSED"].split("=", 1)
    assert text in extrapolated[name].get("refused", ""), extrapolated
tightenings = search["reference_tightenings"]
expected = os.environ.get("EXPECT_TIGHTENINGS")
if expected is not None:
    assert len(tightenings) == int(expected), f"{len(tightenings)} tightenings, expected {expected}: {tightenings}"
    to = os.environ.get("EXPECT_TIGHTENED_TO")
    if to:
        assert tightenings and to in tightenings[-1], tightenings
        # the study is reported against the tightest reference
        assert to in study["reference_detail"], study["reference_detail"]
print("tightenings:", tightenings)
print("stop:", search["stop"], "-", search["reason"])
PY
here=$(dirname "$0")
python3 "$here/level_search_rules.py" "$out/study.json" || { echo "FAIL: the kept levels break the search's rules"; exit 1; }
contains=()
[ -n "${EXPECT_EXTRAPOLATED:-}" ] && contains=(--contains-order)
python3 "$here/extrapolated_order.py" "$out/study.json" ${contains[@]+"${contains[@]}"} ||
  { echo "FAIL: an extrapolated order is not Aitken's of its pairwise orders"; cat "$out/table.txt"; exit 1; }
