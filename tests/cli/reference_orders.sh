#!/usr/bin/env bash
# check --case full with rk2 against the CVODE reference and against rk4 at Δt = 1e-5 s (1000
# steps over the 10 ms): both pass, and every variable's fitted order agrees to the three decimals
# the table prints (rk4's error at 1e-5 s is ~1e-8 of the finest rk2 level's, below what three
# decimals of an order can see). The JSON names the reference and its settings.
# usage: reference_orders.sh DLPVERIFY
set -u
dlpverify=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
common=(check --case full --outer 4 --integrator rk2 --expect-order 2)
"$dlpverify" "${common[@]}" --reference cvode --json "$out/cvode.json" >/dev/null || { echo "FAIL: cvode reference run"; exit 1; }
"$dlpverify" "${common[@]}" --reference integrator:rk4@1e-5 --json "$out/rk4.json" >/dev/null ||
  { echo "FAIL: integrator reference run"; exit 1; }
/usr/bin/python3 - "$out/cvode.json" "$out/rk4.json" <<'PY'
import json, sys
cvode, rk4 = (json.load(open(path)) for path in sys.argv[1:3])
failed = False
if rk4["reference"] != "integrator" or "rk4 at dt = 1e-05" not in rk4["reference_detail"]:
    print("FAIL: reference", rk4["reference"], rk4["reference_detail"]); failed = True
for name, fit in cvode["fitted_order"].items():
    a, b = fit["value"], rk4["fitted_order"][name]["value"]
    ok = a is not None and b is not None and f"{a:.3f}" == f"{b:.3f}"
    print(f"{name}: cvode {a:.3f}, integrator:rk4@1e-5 {b:.3f}", "" if ok else "FAIL")
    failed |= not ok
sys.exit(1 if failed else 0)
PY
