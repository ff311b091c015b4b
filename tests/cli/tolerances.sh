#!/usr/bin/env bash
# A study by --tolerances (docs/verification.md, "Adaptive integrators by tolerance"): exit EXIT,
# every variable with a fitted exponent of error against rtol and its 95% interval in the JSON,
# and, when given, TEXT in the table; every exponent is the one its error control predicts, by
# tolerance_exponent.py (E = q/(min(p, q) + 1) from the ARKODE name, q/(q + 1) over CVODE's
# orders, or EXPONENT=E from the environment for an integrator without error control). With
# IMPLICIT=1 every run must count its Newton and Krylov iterations.
#
# usage: [EXPONENT=E] [IMPLICIT=1] tolerances.sh DLPVERIFY EXIT TEXT|- ARGS...
set -u
dlpverify=$1 expected_exit=$2 text=$3
shift 3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$dlpverify" "$@" --json "$out/study.json" >"$out/table.txt" 2>"$out/stderr.txt"
code=$?
fail() { echo "FAIL: $*"; cat "$out/table.txt" "$out/stderr.txt"; exit 1; }
[ "$code" -eq "$expected_exit" ] || fail "exit $code, expected $expected_exit"
[ "$text" = "-" ] || grep -qF -- "$text" "$out/table.txt" || fail "the table does not say '$text'"
IMPLICIT=${IMPLICIT:-} python3 - "$out/study.json" <<'PY' || fail "the JSON lacks an exponent with its interval or the work"
import json, os, sys
study = json.load(open(sys.argv[1]))
implicit = os.environ["IMPLICIT"] == "1"
if implicit:
    for run in study["runs"]:
        assert run["nonlinear_iterations"] > 0 and run["linear_iterations"] > 0, run
        assert run["rhs_evals"] > run["steps"] > 0 and run["rhs_evals_jacobian"] > 0, run
        assert run["nonlinear_convergence_failures"] >= 0 and run["linear_convergence_failures"] >= 0, run
assert study["proportionality"], "no variables"
for name, p in study["proportionality"].items():
    assert p["exponent"] is not None and p["ci95"] is not None and len(p["runs_used"]) >= 3, (name, p)
    assert p["ci95"][0] <= p["exponent"] <= p["ci95"][1], (name, p)
for run in study["runs"]:
    assert "steps" in run and "rhs_evals" in run and "rejected_steps" in run
PY
python3 "$(dirname "$0")/tolerance_exponent.py" "$out/study.json" ${EXPONENT:+"$EXPONENT"} ||
  fail "an exponent is not the one its error control predicts"
