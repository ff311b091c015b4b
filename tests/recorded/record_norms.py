#!/usr/bin/env python3
"""Re-records l2-norms.json from a build: runs each recorded study with DLPVERIFY and replaces
its L2 norms, and the file's provenance with the build's own — the "provenance" object of the
study JSON (commit, version, compiler, build type, SUNDIALS, Eigen, GSL, date, host), the
compile flags of the dlpverify target (CMakeFiles/dlpverify.dir/flags.make in the build folder,
with -march) and the SIMD instruction set and lanes of the block kernels (`dlpverify bench`).
The studies' arguments, tolerances and reasons are kept: a tolerance is a judgement of how far
a correct build may drift (compare_norms.py), not a recording.

usage: record_norms.py DLPVERIFY RECORDED_JSON [BUILD_DIR]   (BUILD_DIR: the binary's folder)
"""
import json
import os
import subprocess
import sys
import tempfile


def run_json(binary, arguments, out):
    subprocess.run([binary, *arguments, "--json", out], check=True, stdout=subprocess.DEVNULL)
    return json.load(open(out))


def compile_flags(build_dir):
    with open(os.path.join(build_dir, "CMakeFiles", "dlpverify.dir", "flags.make")) as flags:
        for line in flags:
            if line.startswith("CXX_FLAGS = "):
                return line[len("CXX_FLAGS = "):].strip()
    raise SystemExit(f"no CXX_FLAGS in {build_dir}/CMakeFiles/dlpverify.dir/flags.make")


def main():
    if len(sys.argv) not in (3, 4):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        sys.exit(2)
    binary, recorded_path = sys.argv[1], sys.argv[2]
    build_dir = sys.argv[3] if len(sys.argv) == 4 else os.path.dirname(os.path.abspath(binary))
    recorded = json.load(open(recorded_path))
    with tempfile.TemporaryDirectory() as folder:
        provenance = None
        for name, study in recorded["studies"].items():
            result = run_json(binary, study["arguments"], os.path.join(folder, name + ".json"))
            variables = sorted(key[len("l2_"):] for key in result["levels"][0] if key.startswith("l2_"))
            study["l2"] = [{v: level["norms_" + v]["l2"] for v in variables} for level in result["levels"]]
            provenance = provenance or result["provenance"]
        bench = run_json(binary, ["bench", "--outer", "3", "--seconds", "0.001", "--threads", "1"],
                         os.path.join(folder, "bench.json"))
    keep = ("git_commit", "version", "compiler", "build_type", "sundials", "eigen", "gsl", "date", "host")
    recorded["provenance"] = {key: provenance[key] for key in keep}
    recorded["provenance"].update({"cxx_flags": compile_flags(build_dir), "simd_isa": bench["isa"],
                                   "simd_lanes": bench["lanes"]})
    text = json.dumps(recorded, indent=1) + "\n"
    with open(recorded_path + ".tmp", "w") as out:
        out.write(text)
    os.replace(recorded_path + ".tmp", recorded_path)
    print(f"recorded {len(recorded['studies'])} studies from {binary}: {recorded['provenance']}")


if __name__ == "__main__":
    main()
