#!/usr/bin/env python3
"""The CI examples (examples/ci/) run as written, so that they cannot go stale.

From each workflow (GitHub Actions, GitLab CI) the commands are read as the CI would read them
(the `run:` of each step, the job's `script:`), and:
  - the install command names the Debian package this build makes (dlpverify_VERSION_amd64.deb,
    cpack's name) — it is not run: installing would change this machine;
  - every other command runs in a copy of the example project (its checks/), with the dlpverify of
    this build first on PATH: it exits 0, and writes the JUnit XML, which validates against
    Jenkins' schema, and the HTML report the workflow publishes;
  - with a failing study added, the same command exits 1, so the job fails: the gate holds;
  - the reports are published whatever the outcome (`if: always()`, `when: always`).

usage: examples.py DLPVERIFY_DIR SOURCE_DIR PROJECT_VERSION
"""
import os
import shutil
import subprocess
import sys
import tempfile

import yaml

build, source, version = sys.argv[1:4]
examples = os.path.join(source, "examples", "ci")
schema = os.path.join(source, ".deps", "junit", "jenkins-junit.xsd")
deb = f"./packages/dlpverify_{version}_amd64.deb"
# junit-4.xsd, but for one change: <skipped> takes a message attribute as <failure> does (as in the
# xunit plugin's junit-10.xsd and Surefire's schema), as tests/cli/suite.sh validates it.
SKIPPED = '<xs:element name="skipped" type="xs:string"/>'
WITH_MESSAGE = ('<xs:element name="skipped"><xs:complexType mixed="true">'
                '<xs:attribute name="message" type="xs:string" use="optional"/></xs:complexType></xs:element>')


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def github():
    with open(os.path.join(examples, "github-actions.yml")) as f:
        workflow = yaml.safe_load(f)
    steps = workflow["jobs"]["verify"]["steps"]
    for step in steps:
        if "upload-artifact" in step.get("uses", "") or "junit-report" in step.get("uses", ""):
            if step.get("if") != "always()":
                fail(f"GitHub step {step.get('name')} is not run always")
    return [step["run"] for step in steps if "run" in step]


def gitlab():
    with open(os.path.join(examples, "gitlab-ci.yml")) as f:
        job = yaml.safe_load(f)["verify"]
    if job["artifacts"].get("when") != "always":
        fail("GitLab artifacts are not kept always")
    return list(job["script"]), job["artifacts"]["reports"]["junit"]


def run(command, folder):
    env = dict(os.environ, PATH=build + os.pathsep + os.environ["PATH"])
    return subprocess.run(["bash", "-c", command], cwd=folder, env=env, capture_output=True, text=True)


def check(name, commands, reports):
    installs = [c for c in commands if "apt-get install" in c]
    if len(installs) != 1 or deb not in installs[0]:
        fail(f"{name}: the install command does not name {deb}: {installs}")
    others = [c for c in commands if c not in installs]
    with tempfile.TemporaryDirectory() as project:
        shutil.copytree(os.path.join(examples, "checks"), os.path.join(project, "checks"))
        for command in others:
            done = run(command, project)
            if done.returncode != 0:
                fail(f"{name}: `{command}` exited {done.returncode}\n{done.stdout}\n{done.stderr}")
        for report in reports:
            if not os.path.isfile(os.path.join(project, report)):
                fail(f"{name}: {report} was not written")
        xml = os.path.join(project, "dlpverify-report.xml")
        with open(schema) as f:
            text = f.read()
        if SKIPPED not in text:
            fail(f"{schema} has no {SKIPPED} to give a message")
        relaxed = os.path.join(project, "junit.xsd")
        with open(relaxed, "w") as f:
            f.write(text.replace(SKIPPED, WITH_MESSAGE))
        valid = subprocess.run(["xmllint", "--noout", "--schema", relaxed, xml], capture_output=True, text=True)
        if valid.returncode != 0:
            fail(f"{name}: the JUnit XML does not validate\n{valid.stderr}")
        with open(os.path.join(project, "dlpverify-report.html")) as f:
            if not f.read().startswith("<!DOCTYPE html>"):
                fail(f"{name}: the HTML report is no HTML page")
        shutil.copy(os.path.join(source, "tests", "cli", "suite", "drag-euler-expects-2.toml"), os.path.join(project, "checks"))
        for command in others:
            done = run(command, project)
            if done.returncode != 1:
                fail(f"{name}: with a failing study `{command}` exited {done.returncode}, expected 1")
    print(f"ok: {name}: {len(others)} command(s) run as written, reports written, a failing study fails the job")


check("GitHub Actions", github(), ["dlpverify-report.xml", "dlpverify-report.html"])
script, junit = gitlab()
check("GitLab CI", script, [junit, "dlpverify-report.html"])
