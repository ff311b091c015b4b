"""A result JSON as the same-bits tests compare it (threads, ranks, a resumed study against an
uninterrupted one): every number the study computed, without what depends on the machine or the
command line: the provenance, the echoed options and every wall time, at any depth."""
import json


def without_wall_times(value):
    if isinstance(value, dict):
        return {k: without_wall_times(v) for k, v in value.items() if "wall" not in k}
    if isinstance(value, list):
        return [without_wall_times(v) for v in value]
    return value


def comparable(path):
    with open(path) as f:
        d = json.load(f)
    for key in ("provenance", "options"):
        d.pop(key)
    return without_wall_times(d)
