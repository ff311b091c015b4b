#!/usr/bin/env bash
# `dlpverify bench`'s contract on a tiny cloud (R_out = 4: the 256 lattice points with
# 1 ≤ i² + j² + k² ≤ 16, counted independently below): bad input exits 2 with one line and no
# file; a run writes the JSON the speed issue names — isa, bandwidth_gbs, and one kernel row per
# case × tableau × thread count × path, each with a finite positive rate. No speed is asserted.
#
# usage: bench_contract.sh DLPVERIFY
set -u
dlpverify=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*"; cat "$out/.stderr" 2>/dev/null; exit 1; }

"$dlpverify" bench --outer 4 --seconds 0 --json "$out/bad.json" >"$out/.stdout" 2>"$out/.stderr"
code=$?
[ "$code" -eq 2 ] || fail "--seconds 0: exit $code, expected 2"
[ "$(wc -l <"$out/.stderr")" -eq 1 ] || fail "--seconds 0: not exactly one line on stderr"
grep -qF -- "--seconds" "$out/.stderr" || fail "--seconds 0: the message does not name --seconds"
[ ! -e "$out/bad.json" ] || fail "--seconds 0: a JSON file was written"

"$dlpverify" bench --outer 4 --seconds 0.002 --json "$out/bench.json" >"$out/.stdout" 2>"$out/.stderr" ||
  fail "bench exited $?"
python3 - "$out/bench.json" <<'PY' || exit 1
import json, math, sys
d = json.load(open(sys.argv[1]))
particles = sum(1 for i in range(-4, 5) for j in range(-4, 5) for k in range(-4, 5) if 1 <= i*i + j*j + k*k <= 16)
problems = []
if d["isa"] not in ("avx512f", "avx2", "sse2", "scalar"): problems.append(f"isa {d['isa']}")
if not (d["bandwidth_gbs"] > 0 and math.isfinite(d["bandwidth_gbs"])): problems.append("bandwidth_gbs")
threads = sorted({k["threads"] for k in d["kernels"]})
if threads[0] != 1: problems.append(f"thread counts {threads}")
expected = {(c, i, t, p) for c in ("drag", "full") for i in ("euler", "heun", "rk2", "rk4") for t in threads for p in ("simd", "scalar")}
seen = {(k["case"], k["integrator"], k["threads"], k["path"]) for k in d["kernels"]}
if seen != expected or len(d["kernels"]) != len(expected): problems.append(f"kernel rows {sorted(seen ^ expected)}")
for k in d["kernels"]:
    if k["particles"] != particles: problems.append(f"particles {k['particles']} != {particles}")
    r = k["particle_steps_per_s"]
    if not (isinstance(r, float) and math.isfinite(r) and r > 0): problems.append(f"rate {r} in {k}")
if problems:
    print("FAIL:", "; ".join(problems[:5])); sys.exit(1)
print(f"ok: {len(d['kernels'])} kernel rows of {particles} particles, isa {d['isa']}")
PY
