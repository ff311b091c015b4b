#!/usr/bin/env python3
"""The CI examples (examples/ci/) run as written, so that they cannot go stale.

From each workflow (GitHub Actions, GitLab CI) the commands are read as the CI would read them
(the `run:` of each step, the job's `script:` lines as one shell), and run in a copy of the example
project: its checks/, and dlpverify/ holding this source's CMakeLists.txt, cmake/, src/, include/
and scripts/, as a submodule would. Then:
  - the package installs are not run (they would change this machine): the build's packages come
    from `scripts/install-deps.sh --study`, and the Debian package the header's alternative
    installs is the one this build makes (dlpverify_VERSION_amd64.deb, cpack's name);
  - the build runs as written with one exception: `cmake --build … --target dlpverify` links this
    build's dlpverify where the build would put it (a build takes minutes on 2 cores). Its configure
    runs for real and must use every option it is given (CMake names an unused one);
  - dlpverify reaches the suite's command only through the workflow's own PATH step, which exits 0
    and writes the JUnit XML (valid against Jenkins' schema), the HTML report and the Markdown
    summary ($GITHUB_STEP_SUMMARY on GitHub) with the verdict as its heading ("pass");
  - a second run is the cache's hit: the build is skipped (GitHub: the step's `if` on the cache's
    output; GitLab: the cached folder's source hash), and with a failing study added the job fails
    (exit 1) with FAIL in its summary: the gate holds;
  - the build is cached by a hash of dlpverify's source, portable (DLPVERIFY_NATIVE=OFF: the cache
    may land on another CPU); the GitHub workflow grants `checks: write` (its JUnit reporter's check
    run) and `contents: read`; the reports are kept whatever the outcome (`if: always()`,
    `when: always`).

usage: examples.py DLPVERIFY_DIR SOURCE_DIR PROJECT_VERSION
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import yaml

build, source, version = sys.argv[1:4]
build = os.path.abspath(build)
examples = os.path.join(source, "examples", "ci")
schema = os.path.join(source, ".deps", "junit", "jenkins-junit.xsd")
deb = f"./packages/dlpverify_{version}_amd64.deb"
# junit-4.xsd, but for one change: <skipped> takes a message attribute as <failure> does (as in the
# xunit plugin's junit-10.xsd and Surefire's schema), as tests/cli/suite.sh validates it.
SKIPPED = '<xs:element name="skipped" type="xs:string"/>'
WITH_MESSAGE = ('<xs:element name="skipped"><xs:complexType mixed="true">'
                '<xs:attribute name="message" type="xs:string" use="optional"/></xs:complexType></xs:element>')
SOURCE_PARTS = ["CMakeLists.txt", "cmake", "src", "include", "scripts"]
REPORTS = ["dlpverify-report.xml", "dlpverify-report.html"]
# cmake, but `--build DIR … --target dlpverify` links this build's command into DIR.
CMAKE_SHIM = """#!/bin/sh
if [ "$1" = --build ]; then
  case " $* " in *" --target dlpverify "*) ;; *) echo "cmake shim: the build is not of --target dlpverify: $*" >&2; exit 1 ;; esac
  [ -f "$2/CMakeCache.txt" ] || { echo "cmake shim: $2 is not configured" >&2; exit 1; }
  ln -sf "{binary}" "$2/dlpverify"
  exit 0
fi
exec "{cmake}" "$@"
"""


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def header_alternative(path):
    """The .deb the header comment's alternative installs."""
    with open(path) as f:
        lines = [line for line in f if line.startswith("#") and "apt-get install" in line]
    if len(lines) != 1 or deb not in lines[0]:
        fail(f"{path}: the header's alternative does not install {deb}: {lines}")


def configure_options(command):
    """The -D options of a `cmake -S` command."""
    return dict(re.findall(r"-D(\w+)=(\S+)", command))


def check_configure(name, command):
    options = configure_options(command)
    for option, value in {"CMAKE_BUILD_TYPE": "Release", "DLPVERIFY_NATIVE": "OFF", "DLPVERIFY_BUILD_TESTS": "OFF"}.items():
        if options.get(option) != value:
            fail(f"{name}: the build's configure does not set {option}={value}: {command}")


def new_project(folder):
    shutil.copytree(os.path.join(examples, "checks"), os.path.join(folder, "checks"))
    os.makedirs(os.path.join(folder, "dlpverify"))
    for part in SOURCE_PARTS:
        copy = shutil.copytree if os.path.isdir(os.path.join(source, part)) else shutil.copy
        copy(os.path.join(source, part), os.path.join(folder, "dlpverify", part))


def environment(scratch):
    """PATH without this build (the workflow must bring dlpverify), with the cmake shim first."""
    shim = os.path.join(scratch, "shim")
    os.makedirs(shim, exist_ok=True)
    with open(os.path.join(shim, "cmake"), "w") as f:
        f.write(CMAKE_SHIM.replace("{binary}", os.path.join(build, "dlpverify")).replace("{cmake}", shutil.which("cmake")))
    os.chmod(os.path.join(shim, "cmake"), 0o755)
    path = [p for p in os.environ["PATH"].split(os.pathsep) if os.path.abspath(p) != os.path.abspath(build)]
    return dict(os.environ, PATH=os.pathsep.join([shim] + path))


def require_built(name, found, project, folder):
    """`command -v dlpverify` after the workflow's PATH step names the command it built."""
    last = (found.stdout.strip().splitlines() or [""])[-1]  # after the build's own output
    if found.returncode != 0 or last != os.path.join(project, folder, "dlpverify"):
        fail(f"{name}: after the PATH step dlpverify is '{last}', not the one built in {folder}\n{found.stderr}")


def run(command, folder, env):
    return subprocess.run(["bash", "-e", "-c", command], cwd=folder, env=env, capture_output=True, text=True)


def check_reports(name, project, summary, verdict):
    for report in REPORTS:
        if not os.path.isfile(os.path.join(project, report)):
            fail(f"{name}: {report} was not written")
    with open(summary) as f:
        heading = f.readline().strip()
    if heading != f"### dlpverify suite: {verdict}":
        fail(f"{name}: the summary's heading is '{heading}', not '### dlpverify suite: {verdict}'")
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


def add_failing_study(project):
    shutil.copy(os.path.join(source, "tests", "cli", "suite", "drag-euler-expects-2.toml"), os.path.join(project, "checks"))


def github():
    path = os.path.join(examples, "github-actions.yml")
    header_alternative(path)
    with open(path) as f:
        workflow = yaml.safe_load(f)
    if workflow.get("permissions") != {"contents": "read", "checks": "write"}:
        fail(f"GitHub: permissions are {workflow.get('permissions')}, not contents: read and checks: write")
    steps = workflow["jobs"]["verify"]["steps"]
    for step in steps:
        if "upload-artifact" in step.get("uses", "") or "junit-report" in step.get("uses", ""):
            if step.get("if") != "always()":
                fail(f"GitHub step {step.get('name')} is not run always")
    caches = [s for s in steps if s.get("uses", "").startswith("actions/cache@")]
    builds = [s for s in steps if "cmake -S" in s.get("run", "")]
    if len(caches) != 1 or len(builds) != 1:
        fail(f"GitHub: {len(caches)} cache steps and {len(builds)} build steps, not one each")
    cache, build_step = caches[0], builds[0]
    configure, _, build_command = build_step["run"].partition(" && ")
    check_configure("GitHub", configure)
    folder = re.search(r"-B (\S+)", configure).group(1)
    if cache["with"]["path"] != folder:
        fail(f"GitHub: the cache keeps {cache['with']['path']}, the build is in {folder}")
    key = cache["with"]["key"]
    for part in ["dlpverify/CMakeLists.txt", "dlpverify/cmake/**", "dlpverify/src/**", "dlpverify/include/**"]:
        if "hashFiles(" not in key or f"'{part}'" not in key:
            fail(f"GitHub: the cache key {key} does not hash {part}")
    if "restore-keys" in cache["with"]:
        fail("GitHub: restore-keys would restore another source's build")
    if build_step.get("if") != f"steps.{cache['id']}.outputs.cache-hit != 'true'":
        fail(f"GitHub: the build step runs on a cache hit too (if: {build_step.get('if')})")

    with tempfile.TemporaryDirectory() as scratch:
        project = os.path.join(scratch, "project")
        new_project(project)
        env = environment(scratch)

        def job(cache_hit):
            """Each step in turn as the runner takes it; the Verify step's exit code and summary."""
            path = os.path.join(scratch, "github-path")
            open(path, "w").close()
            outcome = None
            for step in steps:
                if "run" not in step:
                    continue
                command = step["run"]
                if "apt-get install" in command:
                    continue
                if "install-deps.sh" in command:
                    if command != "bash dlpverify/scripts/install-deps.sh --study":
                        fail(f"GitHub: the packages step is `{command}`, not install-deps.sh --study")
                    continue
                if step is build_step and cache_hit:
                    continue
                with open(path) as f:
                    added = [line.strip() for line in f if line.strip()]
                summary = os.path.join(scratch, "summary-" + str(steps.index(step)))
                open(summary, "w").close()
                step_env = dict(env, GITHUB_PATH=path, GITHUB_STEP_SUMMARY=summary,
                                PATH=os.pathsep.join(list(reversed(added)) + [env["PATH"]]))
                if "dlpverify suite" in command:
                    require_built("GitHub", run("command -v dlpverify", project, step_env), project, folder)
                done = run(command, project, step_env)
                if "dlpverify suite" in command:
                    outcome = (done, summary)
                elif done.returncode != 0:
                    fail(f"GitHub: step '{step.get('name')}' `{command}` exited {done.returncode}\n{done.stdout}\n{done.stderr}")
                elif step is build_step and "Manually-specified variables were not used" in done.stderr:
                    fail(f"GitHub: the build's configure names an option the project does not have\n{done.stderr}")
            return outcome

        done, summary = job(cache_hit=False)
        if done.returncode != 0:
            fail(f"GitHub: the suite exited {done.returncode}\n{done.stdout}\n{done.stderr}")
        check_reports("GitHub", project, summary, "pass")
        add_failing_study(project)
        done, summary = job(cache_hit=True)
        if done.returncode != 1:
            fail(f"GitHub: with a failing study the suite exited {done.returncode}, expected 1\n{done.stderr}")
        check_reports("GitHub", project, summary, "FAIL")
    print("ok: GitHub Actions: built (configured, the build linked) and cached by the source's hash, "
          "the suite run as written, reports and summary written, a failing study fails the job")


def gitlab():
    path = os.path.join(examples, "gitlab-ci.yml")
    header_alternative(path)
    with open(path) as f:
        job = yaml.safe_load(f)["verify"]
    if job["artifacts"].get("when") != "always":
        fail("GitLab artifacts are not kept always")
    script = list(job["script"])
    if script[0] != "bash dlpverify/scripts/install-deps.sh --study":
        fail(f"GitLab: the first line is `{script[0]}`, not install-deps.sh --study")
    builds = [line for line in script if "cmake -S" in line]
    if len(builds) != 1:
        fail(f"GitLab: {len(builds)} build lines, not one")
    configure = next(line for line in builds[0].splitlines() if "cmake -S" in line).strip()
    check_configure("GitLab", configure)
    folder = re.search(r"-B (\S+)", configure).group(1)
    if job["cache"]["paths"] != [folder + "/"]:
        fail(f"GitLab: the cache keeps {job['cache']['paths']}, the build is in {folder}")
    summary_file = re.search(r"--summary (\S+)", script[-1]).group(1)
    for report in REPORTS + [summary_file]:
        if report not in job["artifacts"]["paths"]:
            fail(f"GitLab: {report} is not kept")
    if job["artifacts"]["reports"]["junit"] != "dlpverify-report.xml":
        fail("GitLab: the JUnit report is not dlpverify-report.xml")

    with tempfile.TemporaryDirectory() as scratch:
        project = os.path.join(scratch, "project")
        new_project(project)
        env = environment(scratch)
        # One shell, as GitLab runs a script: first up to the suite, with the cache empty.
        done = run("\n".join(script[1:-1] + ["command -v dlpverify"]), project, env)
        if "Manually-specified variables were not used" in done.stderr:
            fail(f"GitLab: the build's configure names an option the project does not have\n{done.stderr}")
        require_built("GitLab", done, project, folder)
        stamp = os.path.join(project, folder, "source.sha256")
        if not os.path.isfile(stamp):
            fail(f"GitLab: the build left no {stamp}")
        # Then whole, twice, as the cache's hits: the same source, so the configured tree must stay
        # as it is.
        cache = os.path.join(project, folder, "CMakeCache.txt")
        os.utime(cache, (0, 0))
        lines = "\n".join(script[1:])
        done = run(lines, project, env)
        if done.returncode != 0:
            fail(f"GitLab: the script exited {done.returncode}\n{done.stdout}\n{done.stderr}")
        check_reports("GitLab", project, os.path.join(project, summary_file), "pass")
        add_failing_study(project)
        done = run(lines, project, env)
        if done.returncode != 1:
            fail(f"GitLab: with a failing study the script exited {done.returncode}, expected 1\n{done.stderr}")
        if os.stat(cache).st_mtime != 0:
            fail("GitLab: the build ran again on the same source")
        check_reports("GitLab", project, os.path.join(project, summary_file), "FAIL")
    print("ok: GitLab CI: built (configured, the build linked) and cached by the source's hash, "
          "the suite run as written, reports and summary written, a failing study fails the job")


github()
gitlab()
