#!/usr/bin/env bash
# Shows which loops of the SIMD path the compiler vectorised: recompiles the DLP block kernels and
# the DLP fused steps and the Runge–Kutta family's instantiations with the build's own flags plus -fopt-info-vec-optimized,
# and lists each vectorised source line with the vector width. Run after a build:
#   bash scripts/vectorisation-report.sh [build]        (also: cmake --build build --target vectorisation-report)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
python3 - "$build" <<'PY'
import json, re, shlex, subprocess, sys, collections
build = sys.argv[1]
commands = json.load(open(f"{build}/compile_commands.json"))
wanted = {"src/problems/dlp/block_rates.cpp": "DLP block right-hand side",
          "src/integrators/registry.cpp": "Runge-Kutta stages (include/dlpverify/runge_kutta.hpp)",
          "src/problems/dlp/fused_steps.cpp": "DLP fused steps (include/dlpverify/fused_runge_kutta.hpp)"}
for entry in commands:
    source = entry["file"]
    match = next((w for w in wanted if source.endswith(w)), None)
    if not match:
        continue
    words = shlex.split(entry["command"])
    out = words.index("-o")
    words[out + 1] = "/dev/null"
    words.append("-fopt-info-vec-optimized")
    report = subprocess.run(words, cwd=entry["directory"], capture_output=True, text=True).stderr
    lines = collections.Counter()
    for line in report.splitlines():
        m = re.search(r"([\w/.]+\.(?:cpp|hpp)):(\d+):\d+: optimized: loop vectorized using (\d+) byte vectors", line)
        if m and any(name in m.group(1) for name in ("block_rates", "runge_kutta", "fused_steps")):
            lines[(m.group(1).split("/")[-1], int(m.group(2)), int(m.group(3)))] += 1
    print(f"{wanted[match]} ({match}):")
    for (name, number, width), count in sorted(lines.items()):
        print(f"  {name}:{number}  vectorised with {width}-byte vectors ({count} instantiations)")
PY
