#!/usr/bin/env bash
# Users' Butcher tableaux on the command line (docs/cli.md, "dlpverify tableau"), one mode a test:
#   slipped    `dlpverify tableau` of the midpoint rule with c2 = 0.6 exits 1, its verdict line
#              naming the row sum of c_2 with both values;
#   passes     the midpoint, RK4 and Bogacki–Shampine 3(2) files exit 0 with a PASS line;
#   json       --json of the slipped file: 2 row sums and the 1 + 1 + 2 trees to order 3, the row sum
#              of c_2 failing with residual 0.5 − 0.6, orders 1 met and 2 on an autonomous problem;
#   drag       `check --case drag --integrator tableau:<slipped>` passes at order 2 (exit 0) with
#              exactly one stderr line, the warning; the cloud is autonomous, so the slipped node is
#              invisible: every level's L2 norms equal rk2's bit for bit, at the fitted orders and
#              finest L2 errors docs/verification.md quotes (--outer 4: 2.023 position, 2.027
#              velocity; 2.319e-06 m, 1.674e-03 m/s); the midpoint file passes too, with nothing on
#              stderr;
#   gas        on a problem with explicit time, the gas adiabat's prescribed path J(t), the slip shows:
#              the slipped file's check at order 2 exits 1 with fitted orders within 0.1 of 1 (the
#              quadrature condition Σ b_i c_i = 0.6 ≠ 1/2 leaves first order), the midpoint file's
#              passes, at the orders docs/verification.md quotes (8 parcels: 1.005 temperature, 1.006
#              pressure; the midpoint's 2.038, 2.040);
#   malformed  a file with a nonzero a_22 exits 2 with one stderr line naming the file and the key,
#              and nothing on stdout.
# usage: tableau.sh DLPVERIFY SOURCE_DIR MODE
set -u
dlpverify=$1 src=$2 mode=$3
tableaux=$src/examples/tableaux
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*"; echo "--- stdout:"; cat "$out/stdout" 2>/dev/null; echo "--- stderr:"; cat "$out/stderr" 2>/dev/null; exit 1; }
run() { "$dlpverify" "$@" >"$out/stdout" 2>"$out/stderr"; }

case $mode in
  slipped)
    run tableau "$tableaux/midpoint-slipped-c2.toml"
    code=$?
    [ "$code" -eq 1 ] || fail "exit $code, expected 1"
    grep -qxF "FAIL: row sum c_2 = 0.6 but Σ_j a_2j = 0.5" "$out/stdout" || fail "no verdict naming the row sum of c_2"
    ;;
  passes)
    for file in midpoint rk4 bogacki-shampine; do
      run tableau "$tableaux/$file.toml"
      code=$?
      [ "$code" -eq 0 ] || fail "$file: exit $code, expected 0"
      grep -q "^PASS: the claimed order" "$out/stdout" || fail "$file: no PASS line"
    done
    # The stability region as SVG: drawn, titled with the tableau's name; a format gnuplot cannot
    # write is refused before any work (exit 2, one line, no file).
    run tableau "$tableaux/sdirk2-alexander.toml" --plot "$out/region.svg"
    [ $? -eq 0 ] || fail "--plot: exit $?, expected 0"
    grep -q "<svg" "$out/region.svg" && grep -qF "tableau sdirk2-alexander: stable where" "$out/region.svg" ||
      fail "--plot: no SVG with the title"
    run tableau "$tableaux/rk4.toml" --plot "$out/region.gif"
    [ $? -eq 2 ] && [ "$(wc -l <"$out/stderr")" -eq 1 ] && [ ! -e "$out/region.gif" ] ||
      fail "--plot region.gif: not refused with one line"
    ;;
  json)
    run tableau "$tableaux/midpoint-slipped-c2.toml" --json "$out/t.json"
    code=$?
    [ "$code" -eq 1 ] || fail "exit $code, expected 1"
    /usr/bin/python3 - "$out/t.json" <<'PY' || fail "the JSON does not hold the conditions"
import json, sys
j = json.load(open(sys.argv[1]))
rows = {r["condition"]: r for r in j["conditions"]}
assert len(j["conditions"]) == 2 + 1 + 1 + 2, len(j["conditions"])
assert rows["row sum c_2"]["verdict"] == "FAIL" and rows["row sum c_2"]["residual"] == 0.5 - 0.6, rows["row sum c_2"]
assert rows["order 2: Σ b_i c_i = 1/2"]["verdict"] == "ok"
assert (j["order_claimed"], j["order_met"], j["order_met_autonomous"], j["passed"]) == (2, 1, 2, False), j
PY
    ;;
  drag)
    small=(check --case drag --outer 4 --expect-order 2)
    run "${small[@]}" --integrator "tableau:$tableaux/midpoint-slipped-c2.toml" --json "$out/slipped.json"
    code=$?
    [ "$code" -eq 0 ] || fail "exit $code, expected 0"
    [ "$(wc -l <"$out/stderr")" -eq 1 ] || fail "stderr has $(wc -l <"$out/stderr") lines, expected one"
    grep -qxF "dlpverify: warning: tableau $tableaux/midpoint-slipped-c2.toml: row sum c_2 = 0.6 but Σ_j a_2j = 0.5" \
      "$out/stderr" || fail "no warning naming the row sum of c_2"
    "$dlpverify" "${small[@]}" --integrator rk2 --json "$out/rk2.json" >/dev/null || fail "rk2 did not pass"
    "$dlpverify" "${small[@]}" --integrator "tableau:$tableaux/midpoint.toml" >/dev/null 2>"$out/midpoint.stderr" ||
      fail "the midpoint file did not pass"
    [ ! -s "$out/midpoint.stderr" ] || fail "the midpoint file warned: $(cat "$out/midpoint.stderr")"
    /usr/bin/python3 - "$out/slipped.json" "$out/rk2.json" <<'PY' || fail "the slipped tableau's norms differ from rk2's"
import json, sys
a, b = (json.load(open(f))["levels"] for f in sys.argv[1:3])
keys = [k for k in a[0] if k.startswith("l2_")]
assert len(a) == len(b) == 5 and keys, (len(a), len(b), keys)
for x, y in zip(a, b):
    for k in keys:
        assert x[k] == y[k], (k, x[k], y[k])
j = json.load(open(sys.argv[1]))
quoted = (round(j["fitted_order"]["position"]["value"], 3), round(j["fitted_order"]["velocity"]["value"], 3),
          "%.3e" % a[-1]["l2_position"], "%.3e" % a[-1]["l2_velocity"])
assert quoted == (2.023, 2.027, "2.319e-06", "1.674e-03"), quoted
PY
    ;;
  gas)
    gas=(check --case adiabat-ideal --parcels 8 --expect-order 2)
    run "${gas[@]}" --integrator "tableau:$tableaux/midpoint-slipped-c2.toml" --json "$out/slipped.json"
    code=$?
    [ "$code" -eq 1 ] || fail "slipped: exit $code, expected 1"
    /usr/bin/python3 - "$out/slipped.json" <<'PY' || fail "the slipped file's fitted orders are not 1"
import json, sys
fitted = json.load(open(sys.argv[1]))["fitted_order"]
orders = [fitted[v]["value"] for v in ("temperature", "pressure")]
assert all(abs(p - 1.0) <= 0.1 for p in orders), orders
assert [round(p, 3) for p in orders] == [1.005, 1.006], orders
PY
    run "${gas[@]}" --integrator "tableau:$tableaux/midpoint.toml" --json "$out/midpoint.json"
    code=$?
    [ "$code" -eq 0 ] || fail "midpoint: exit $code, expected 0"
    /usr/bin/python3 - "$out/midpoint.json" <<'PY' || fail "the midpoint file's fitted orders are not the quoted 2.038, 2.040"
import json, sys
fitted = json.load(open(sys.argv[1]))["fitted_order"]
orders = [round(fitted[v]["value"], 3) for v in ("temperature", "pressure")]
assert orders == [2.038, 2.040], orders
PY
    ;;
  malformed)
    printf 'name = "bad"\norder = 2\nc = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.0, 0.5], [0.5, 0.0]]\n' >"$out/bad.toml"
    for command in "tableau $out/bad.toml" "check --case drag --outer 4 --expect-order 2 --integrator tableau:$out/bad.toml"; do
      # shellcheck disable=SC2086
      run $command
      code=$?
      [ "$code" -eq 2 ] || fail "$command: exit $code, expected 2"
      [ "$(wc -l <"$out/stderr")" -eq 1 ] || fail "$command: stderr is not one line"
      grep -qF "tableau $out/bad.toml: A[1][2] = 0.5: must be zero above the diagonal" "$out/stderr" ||
        fail "$command: the line does not name the file and A[1][2]"
      [ ! -s "$out/stdout" ] || fail "$command: output on stdout"
    done
    # A diagonally implicit tableau (the implicit midpoint rule, one stage) is read, checked, and
    # stepped through ARKStep at its order.
    printf 'name = "implicit midpoint"\norder = 2\nc = [0.5]\nb = [1.0]\nA = [[0.5]]\n' >"$out/dirk.toml"
    run tableau "$out/dirk.toml"
    [ $? -eq 0 ] || fail "the implicit midpoint tableau: exit $?, expected 0"
    grep -qF "A-stable: yes" "$out/stdout" || fail "the implicit midpoint rule is not reported A-stable"
    run check --case drag --outer 4 --expect-order 2 --integrator "tableau:$out/dirk.toml"
    code=$?
    [ "$code" -eq 0 ] || fail "a study of the implicit midpoint tableau: exit $code, expected 0"
    ;;
  *) echo "unknown mode $mode"; exit 2 ;;
esac
echo "ok: $mode"
