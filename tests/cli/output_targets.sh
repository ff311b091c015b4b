#!/usr/bin/env bash
# What an output path may name (issue 9). usage: output_targets.sh DLPVERIFY CHECK
#   non-regular  every output option of every command, pointed at a character device (root only:
#                mknod), a FIFO, a socket, a directory or a link to a FIFO: exit 2 before any work,
#                one line naming the option and the path, the node still what it was
#   devnull      /dev/null discards every output, produces none (no gnuplot run) and stays the
#                character device 1,3 — checked in a private /dev when root can make one, so a
#                regression cannot take the machine's /dev/null with it
#   stdout       - and /dev/stdout write to standard output (then without the console table);
#                two outputs there are refused
#   symlink      a link is written through to its target and stays a link; a loop is refused
#   proc         an output under /proc or /sys is bad input, refused before any work
#   folder       an output in a missing folder, plainly or through a dangling link: bad input, no folder made
set -uo pipefail
dlpverify=$(realpath "$1") check=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; [ -f "$dir/err" ] && { echo "--- stderr:"; cat "$dir/err"; }; exit 1; }
small=(--case drag --outer 4 --levels 2)

# expect_refusal OPTION PATH COMMAND...: exit 2, one stderr line naming OPTION and PATH, no stdout.
expect_refusal() {
  local option=$1 path=$2
  shift 2
  "$@" >"$dir/out" 2>"$dir/err"
  local code=$?
  [ "$code" -eq 2 ] || fail "$option $path: exit $code, expected 2"
  [ "$(wc -l <"$dir/err")" -eq 1 ] || fail "$option $path: stderr is not one line"
  grep -qF -- "$option" "$dir/err" || fail "$option $path: stderr does not name $option"
  grep -qF -- "$path" "$dir/err" || fail "$option $path: stderr does not name the path"
  [ ! -s "$dir/out" ] || fail "$option $path: output on stdout, so the study ran"
}

# Every command's every output option, with the arguments that make it run.
each_output() {  # calls $1 OPTION COMMAND... for each
  local f=$1
  for option in --json --csv --table --plot --history --per-particle; do
    "$f" "$option" converge "${small[@]}"
  done
  "$f" --json check "${small[@]}" --expect-order 2
  for option in --json --csv --table --plot; do
    "$f" "$option" precision "${small[@]}" --rtol-max 1e-4 --rtol-min 1e-5
  done
  "$f" --json audit
  "$dlpverify" converge "${small[@]}" --json "$dir/s.json" >/dev/null || fail "converge for plot's input"
  "$f" -o plot "$dir/s.json"
}

# The devnull and stdout checks name /dev/null and /dev/stdout themselves: as root, a regression
# would replace the machine's nodes. So they run, when root can, in a private mount namespace
# with a /dev of their own (null, the stdout/stderr links, and shm, without which LLVM's OpenMP
# runtime of the sanitizer builds aborts), checked after each command.
run=(bash -c '"$@"' _)
if [ "$(id -u)" -eq 0 ] && unshare --mount --propagation private true 2>/dev/null; then
  run=(unshare --mount --propagation private bash -c '
    mount -t tmpfs none /dev && mknod -m 666 /dev/null c 1 3 && ln -s /proc/self/fd /dev/fd &&
      ln -s /proc/self/fd/1 /dev/stdout && ln -s /proc/self/fd/2 /dev/stderr &&
      mkdir /dev/shm && mount -t tmpfs none /dev/shm || exit 8
    "$@"; code=$?
    [ "$(stat -c %F:%t,%T /dev/null)" = "character special file:1,3" ] || { echo "/dev/null was replaced" >&2; exit 9; }
    [ -L /dev/stdout ] || { echo "/dev/stdout was replaced" >&2; exit 9; }
    exit $code' _)
fi

case $check in
non-regular)
  nodes=()
  if [ "$(id -u)" -eq 0 ]; then mknod "$dir/device.png" c 1 3 && nodes+=("device.png:-c"); fi
  mkfifo "$dir/fifo.png" && nodes+=("fifo.png:-p")
  /usr/bin/python3 -c "import socket, sys; socket.socket(socket.AF_UNIX).bind(sys.argv[1])" "$dir/socket.png" &&
    nodes+=("socket.png:-S")
  mkdir "$dir/folder.png" && nodes+=("folder.png:-d")
  ln -s fifo.png "$dir/link-to-fifo.png" && nodes+=("link-to-fifo.png:-p")
  refuse_all() {
    local option=$1
    shift
    for node in "${nodes[@]}"; do
      local name=${node%%:*} kind=${node##*:}
      expect_refusal "$option" "$dir/$name" "$dlpverify" "$@" "$option" "$dir/$name"
      test "$kind" "$dir/$name" || fail "$option replaced $name"
    done
  }
  each_output refuse_all
  [ -L "$dir/link-to-fifo.png" ] || fail "the link to the FIFO was replaced"
  leftovers=$(find "$dir" -name '.*' | wc -l)
  [ "$leftovers" -eq 0 ] || fail "temporary files left behind: $(ls -A "$dir")"
  echo "ok: ${#nodes[@]} kinds of node refused for every output option, none replaced"
  ;;
devnull)
  # The issue's own command first: as root it used to replace the device with a regular file.
  "${run[@]}" "$dlpverify" converge "${small[@]}" --json /dev/null >"$dir/out" 2>"$dir/err" ||
    fail "converge --json /dev/null exited $?"
  "${run[@]}" env PATH=/nonexistent "$dlpverify" converge "${small[@]}" --json /dev/null --csv /dev/null --table /dev/null \
    --plot /dev/null --history /dev/null --per-particle /dev/null >"$dir/out" 2>"$dir/err" ||
    fail "converge with every output to /dev/null (and no gnuplot in PATH) exited $?"
  grep -q "fitted order" "$dir/out" || fail "the console table is missing"
  "${run[@]}" env PATH=/nonexistent "$dlpverify" precision "${small[@]}" --rtol-max 1e-4 --rtol-min 1e-5 \
    --json /dev/null --csv /dev/null --table /dev/null --plot /dev/null >/dev/null 2>"$dir/err" || fail "precision exited $?"
  "${run[@]}" "$dlpverify" audit --json /dev/null >/dev/null 2>"$dir/err" || fail "audit exited $?"
  "$dlpverify" converge "${small[@]}" --json "$dir/s.json" >/dev/null || fail "converge for plot's input"
  "${run[@]}" env PATH=/nonexistent "$dlpverify" plot "$dir/s.json" -o /dev/null 2>"$dir/err" ||
    fail "plot -o /dev/null (no gnuplot in PATH) exited $?"
  [ "$(stat -c %F:%t,%T /dev/null)" = "character special file:1,3" ] || fail "/dev/null is no longer the device"
  echo "ok: /dev/null discards every output unproduced and stays a character device"
  ;;
stdout)
  cd "$dir" || fail "cd"  # an old build would write a file named - here
  "${run[@]}" "$dlpverify" converge "${small[@]}" --json - >"$dir/out" 2>"$dir/err" || fail "--json - exited $?"
  /usr/bin/python3 -c "import json, sys; d = json.load(open(sys.argv[1])); sys.exit(d['case'] != 'drag' or len(d['levels']) != 2)" \
    "$dir/out" || fail "standard output is not the study's JSON alone"
  "${run[@]}" "$dlpverify" converge "${small[@]}" --csv /dev/stdout >"$dir/out" 2>"$dir/err" || fail "--csv /dev/stdout exited $?"
  [[ $(head -1 "$dir/out") == "# dlpverify"* ]] || fail "standard output does not start with the CSV header"
  grep -q "fitted order" "$dir/out" && fail "the console table went to standard output beside the CSV"
  "${run[@]}" "$dlpverify" converge "${small[@]}" --table - >"$dir/out" 2>"$dir/err" || fail "--table - exited $?"
  [ "$(grep -c '^level' "$dir/out")" -eq 1 ] || fail "the table is not on standard output exactly once"
  expect_refusal --csv /dev/stdout "${run[@]}" "$dlpverify" converge "${small[@]}" --json - --csv /dev/stdout
  "$dlpverify" converge "${small[@]}" --json "$dir/s.json" >/dev/null || fail "converge for plot's input"
  "${run[@]}" "$dlpverify" plot "$dir/s.json" -o - >"$dir/figure" 2>"$dir/err" || fail "plot -o - exited $?"
  [ "$(head -c 8 "$dir/figure" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "plot -o - did not write a PNG"
  "${run[@]}" "$dlpverify" audit --json /dev/stdout >"$dir/out" 2>"$dir/err" || fail "audit --json /dev/stdout exited $?"
  /usr/bin/python3 -c "import json, sys; sys.exit(json.load(open(sys.argv[1]))['passed'] is not True)" "$dir/out" ||
    fail "audit's standard output is not its JSON alone"
  [ ! -e "$dir/-" ] || fail "a file named - was written"
  echo "ok: - and /dev/stdout write to standard output, the table steps aside, two outputs there are refused"
  ;;
symlink)
  mkdir "$dir/results" "$dir/links"
  echo old >"$dir/results/kept.json"
  ln -s ../results/kept.json "$dir/links/relative.json"          # relative, from the link's folder
  ln -s "$dir/links/relative.json" "$dir/links/chain.json"       # a link to a link
  ln -s ../results/new.json "$dir/links/dangling.json"           # its target does not exist yet
  for link in chain dangling; do
    "$dlpverify" converge "${small[@]}" --json "$dir/links/$link.json" >/dev/null 2>"$dir/err" || fail "--json $link exited $?"
    [ -L "$dir/links/$link.json" ] || fail "$link.json is no longer a symbolic link"
  done
  [ -L "$dir/links/relative.json" ] || fail "relative.json is no longer a symbolic link"
  for f in kept new; do
    /usr/bin/python3 -c "import json, sys; json.load(open(sys.argv[1]))" "$dir/results/$f.json" ||
      fail "results/$f.json (the link's target) does not hold the study"
  done
  ln -s loop-b.json "$dir/loop-a.json"
  ln -s loop-a.json "$dir/loop-b.json"
  expect_refusal --csv "$dir/loop-a.json" "$dlpverify" converge "${small[@]}" --csv "$dir/loop-a.json"
  [ -L "$dir/loop-a.json" ] && [ -L "$dir/loop-b.json" ] || fail "the loop's links were replaced"
  echo "ok: links are written through to their targets and stay links; a loop is refused"
  ;;
proc)
  expect_refusal --json /proc/dlpverify-test.json "$dlpverify" converge "${small[@]}" --json /proc/dlpverify-test.json
  expect_refusal --plot /proc/self/dlpverify.png "$dlpverify" converge "${small[@]}" --plot /proc/self/dlpverify.png
  expect_refusal --history /sys/dlpverify.csv "$dlpverify" converge "${small[@]}" --history /sys/dlpverify.csv
  expect_refusal --csv /proc/dlpverify.csv "$dlpverify" precision "${small[@]}" --csv /proc/dlpverify.csv
  expect_refusal --json /proc/dlpverify.json "$dlpverify" audit --json /proc/dlpverify.json
  [ ! -e /proc/dlpverify-test.json ] || fail "a file appeared under /proc"
  echo "ok: outputs under /proc and /sys are refused before any work"
  ;;
folder)
  # No command creates a folder: an output in a missing folder, plainly or through a link whose
  # target's folder is missing (an absolute one, where root could create anything), is bad input
  # before any work, for every command's every output, and no folder appears.
  missing="$dir/no-such-folder/sub"
  ghost="/nonexistent-dlpverify-$$/dir"
  ln -s "$ghost/file.png" "$dir/dangling.png"  # .png: a figure option checks the ending first
  refuse_missing() {
    local option=$1
    shift
    expect_refusal "$option" "$missing/x.png" "$dlpverify" "$@" "$option" "$missing/x.png"
    grep -qF "does not exist; no command creates a folder" "$dir/err" || fail "$option: the refusal does not say why"
    expect_refusal "$option" "$dir/dangling.png" "$dlpverify" "$@" "$option" "$dir/dangling.png"
  }
  each_output refuse_missing
  [ ! -e "$dir/no-such-folder" ] && [ ! -e "/nonexistent-dlpverify-$$" ] || fail "a folder was created"
  echo "ok: an output in a missing folder, plainly or through a dangling link, is refused; no folder made"
  ;;
*) fail "unknown check $check" ;;
esac
