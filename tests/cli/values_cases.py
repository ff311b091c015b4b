"""dlpverify cases: lists exactly the cases docs/cli.md's --case option documents, each with the
reference it names (closed form: "exact", else "cvode"), and exactly the integrators it documents:
the named ones and one arkode-erk: entry for every explicit table of ARKODE in SUNDIALS 6.4
(the ARKODE_ERKTableID enum of arkode/arkode_butcher_erk.h), with its stages and order (ARKODE
names a table NAME_stages_[embedding order_]order); then, for --tolerances, cvode, one
arkode-adaptive: entry for every explicit table with an embedding and every implicit table (the
ARKODE_DIRKTableID enum of arkode/arkode_butcher_dirk.h) with its stages and order, and exec:COMMAND.
usage: values_cases.py DLPVERIFY
"""
import sys

from values_common import check, finish, run

dlpverify = sys.argv[1]

# docs/cli.md, option --case: closed form, CVODE reference, gas parcels (closed form), cooling
# particles (cooling: CVODE, the others a closed form), coupled systems (cosh/sinh, matrix exponential).
cases = {
    "similarity": "exact", "gravity": "exact", "drag": "exact", "drag-gravity-vertical": "exact",
    "drag-heat": "exact", "burn": "exact",
    "drag-gravity": "cvode", "drag-law": "cvode", "full": "cvode",
    "adiabat-ideal": "exact", "adiabat-vdw": "exact",
    "cooling": "cvode", "cooling-radiation": "exact", "cooling-radiation-vacuum": "exact", "cooling-bernoulli": "exact",
    "stagger-2x2": "exact", "stagger-3x3": "exact",
}
# docs/cli.md, option --integrator, with the orders it states ("var": a variable order).
named = {
    "rk2": "2", "euler": "1", "heun": "2", "rk4": "4", "cvode": "var",
    "implicit-fp": "1", "stagger-jacobi": "1", "stagger-gauss-seidel": "1",
    "mpm-trapezoid": "1", "mpm-trapezoid-corrected": "2", "exec:COMMAND": "var",
    "tableau:FILE": "var",  # the file's order
}
arkode_tables = [
    "ARKODE_HEUN_EULER_2_1_2", "ARKODE_BOGACKI_SHAMPINE_4_2_3", "ARKODE_ARK324L2SA_ERK_4_2_3",
    "ARKODE_ZONNEVELD_5_3_4", "ARKODE_ARK436L2SA_ERK_6_3_4", "ARKODE_SAYFY_ABURUB_6_3_4",
    "ARKODE_CASH_KARP_6_4_5", "ARKODE_FEHLBERG_6_4_5", "ARKODE_DORMAND_PRINCE_7_4_5",
    "ARKODE_ARK548L2SA_ERK_8_4_5", "ARKODE_VERNER_8_5_6", "ARKODE_FEHLBERG_13_7_8",
    "ARKODE_KNOTH_WOLKE_3_3", "ARKODE_ARK437L2SA_ERK_7_3_4", "ARKODE_ARK548L2SAb_ERK_8_4_5",
]
dirk_tables = [
    "ARKODE_SDIRK_2_1_2", "ARKODE_BILLINGTON_3_3_2", "ARKODE_TRBDF2_3_3_2", "ARKODE_KVAERNO_4_2_3",
    "ARKODE_ARK324L2SA_DIRK_4_2_3", "ARKODE_CASH_5_2_4", "ARKODE_CASH_5_3_4", "ARKODE_SDIRK_5_3_4",
    "ARKODE_KVAERNO_5_3_4", "ARKODE_ARK436L2SA_DIRK_6_3_4", "ARKODE_KVAERNO_7_4_5", "ARKODE_ARK548L2SA_DIRK_8_4_5",
    "ARKODE_ARK437L2SA_DIRK_7_3_4", "ARKODE_ARK548L2SAb_DIRK_8_4_5", "ARKODE_ESDIRK324L2SA_4_2_3",
    "ARKODE_ESDIRK325L2SA_5_2_3", "ARKODE_ESDIRK32I5L2SA_5_2_3", "ARKODE_ESDIRK436L2SA_6_3_4",
    "ARKODE_ESDIRK43I6L2SA_6_3_4", "ARKODE_QESDIRK436L2SA_6_3_4", "ARKODE_ESDIRK437L2SA_7_3_4",
    "ARKODE_ESDIRK547L2SA_7_4_5", "ARKODE_ESDIRK547L2SA2_7_4_5",
]
# A table with an embedding has three numbers in its name (KNOTH_WOLKE_3_3 has none).
embedded = [t for t in arkode_tables if len([w for w in t.split("_") if w.isdigit()]) == 3] + dirk_tables
adaptive = {"cvode": "var", "exec:COMMAND": "var"}
adaptive.update({"arkode-adaptive:" + t: t.rsplit("_", 1)[1] for t in embedded})
integrators = dict(named)
integrators.update({"arkode-erk:" + t: t.rsplit("_", 1)[1] for t in arkode_tables})
stages = {"arkode-erk:" + t: [w for w in t.split("_") if w.isdigit()][0] for t in arkode_tables}
stages.update({"arkode-adaptive:" + t: [w for w in t.split("_") if w.isdigit()][0] for t in embedded})

lines = run(dlpverify, "cases").splitlines()
split = lines.index("") if "" in lines else len(lines)
# Case lines start at column 0: name, reference, terms; their detail lines are indented.
listed_cases = {}
for line in lines[1:split]:
    if line and not line[0].isspace():
        name, reference = line.split()[:2]
        check(name not in listed_cases, f"case {name} listed twice")
        listed_cases[name] = reference
check(lines[0].split() == ["case", "reference", "terms", "on"], f"case header {lines[0]!r}")
for name in sorted(set(cases) | set(listed_cases)):
    check(listed_cases.get(name) == cases.get(name),
          f"case {name}: listed with reference {listed_cases.get(name)}, documented {cases.get(name)}")



def section(lines, header, expected):
    """The integrator lines under `header` up to an empty line: each once, with the expected order and stages."""
    check(lines and lines[0].startswith(header), f"no header {header!r}: {lines[:1]}")
    listed = {}
    for line in lines[1:]:
        if not line:
            break
        name, order = line.split()[:2]
        check(name not in listed, f"integrator {name} listed twice")
        listed[name] = order
        if name in stages:
            check(f", {stages[name]} stages," in line, f"integrator {name}: {line.split(None, 2)[2]!r}, expected {stages[name]} stages")
    for name in sorted(set(expected) | set(listed)):
        check(listed.get(name) == expected.get(name),
              f"integrator {name}: listed with order {listed.get(name)}, expected {expected.get(name)}")
    return len(listed) + 2


rest = lines[split + 1:]
used = section(rest, "integrator ", integrators)
section(rest[used:], "adaptive integrator (--tolerances)", adaptive)

finish(f"{len(cases)} cases with their references, {len(integrators)} integrators ({len(arkode_tables)} ARKODE tables) "
       f"and {len(adaptive)} adaptive ones ({len(dirk_tables)} implicit tables) with their orders")
