#!/usr/bin/env bash
# A program dlpverify starts never outlives it (docs/exchange.md, "The command"), and nothing of
# its temporary folder stays behind.
#   leave          the program starts a child in its group and a grandchild in a session of its
#                  own (setsid), writes its output and exits 0: the study succeeds, both are gone
#   fail           the same, but it exits 7: exit 3, both are gone
#   paren-name     as leave, the child and the grandchild named "sl) 1 2": /proc/PID/stat then reads
#                  "PID (sl) 1 2) S PPID …", whose fields count from the last ')': both are gone
#   timeout        the same, then it blocks: --exec-timeout ends it (exit 3), all three are gone
#   signal         SIGTERM to dlpverify while it blocks: exit 143, all gone, TMPDIR empty
#   signal-journal the same in a journaled study (--json), where a first SIGTERM is a request to stop
#                  after the level: the second ends it (143), all gone, TMPDIR empty
#   fifo           the program leaves a FIFO at {output}, a grandchild blocked opening it for writing:
#                  exit 3 at once, one line saying the output is a FIFO, the grandchild gone, TMPDIR empty
#   fifo-hang      the program itself blocks writing into the FIFO: --exec-timeout ends it (exit 3)
#   quoting-space  TMPDIR has a blank (and ' " $ ` \ in a second one): with --exec-shell, {input} and
#                  {output} bare, in "…" and in '…' all name the files; without a shell as well
#   quoting-semicolon  TMPDIR is "t;touch X;": the studies succeed and no X is ever made
# No outcome depends on the machine's speed: a program says it is ready by creating a file, a
# timeout that fired before it was ready is tried again with a longer limit, and a wait for a
# process to end is a poll with a bound that fails naming the process.
# usage: exec_tree.sh DLPVERIFY MODE
set -uo pipefail
dlpverify=$1 mode=$2
marker=$((900000 + $$))  # in every process the program starts: a reused pid is never taken for one
d=$(mktemp -d -t "exec-tree-$marker.XXXXXX")  # the program's own command line holds it too
export TREE_DIR=$d TREE_MARKER=$marker

# Whether process $1 is one of the program's: alive (not a zombie) with the marker in its command line.
ours() {
  local cmdline stat state
  cmdline=$(tr '\0' ' ' 2>/dev/null <"/proc/$1/cmdline") || return 1
  stat=$(cat "/proc/$1/stat" 2>/dev/null) || return 1
  state=${stat##*) }  # after the name, which may hold blanks and ')'
  state=${state%% *}
  [ "$state" != Z ] && [[ $cmdline == *"$marker"* ]]
}
leftovers() {
  local pid
  [ -f "$d/pids" ] || return 0
  while read -r pid; do ours "$pid" && kill -KILL "$pid"; done <"$d/pids"
  return 0
}
trap 'leftovers; rm -rf "$d"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# Every process the program wrote down has ended (each polled for up to 10 s, in case it is dying).
all_ended() {
  local pid deadline
  [ -s "$d/pids" ] || fail "the program wrote down no process"
  while read -r pid; do
    deadline=$((SECONDS + 10))
    while ours "$pid" && [ $SECONDS -lt $deadline ]; do sleep 0.1; done
    ours "$pid" && fail "process $pid ($(tr '\0' ' ' <"/proc/$pid/cmdline")) outlived dlpverify"
  done <"$d/pids"
  return 0
}
empty() {
  local left
  left=$(ls -A "$1")
  [ -z "$left" ] || fail "left in $1: $left"
}

# The program: prog MODE INPUT OUTPUT. It writes the pid of everything it starts to $TREE_DIR/pids.
cat >"$d/prog" <<'EOF'
mode=$1 in=$2 out=$3
echo "prog: $mode is what I do" >&2
start_both() {
  sleep "$TREE_MARKER" & echo $! >>"$TREE_DIR/pids"                  # a child, in the program's group
  (setsid sleep "$TREE_MARKER" & echo $! >>"$TREE_DIR/pids")          # a grandchild in a session of its own
}
case $mode in
leave) start_both; cp "$in" "$out" ;;
paren-name)
  "$TREE_DIR/sl) 1 2" "$TREE_MARKER" & echo $! >>"$TREE_DIR/pids"
  (setsid "$TREE_DIR/sl) 1 2" "$TREE_MARKER" & echo $! >>"$TREE_DIR/pids")
  cp "$in" "$out" ;;
fail) start_both; exit 7 ;;
hang) echo $$ >>"$TREE_DIR/pids"; start_both; : >"$TREE_DIR/ready"; wait ;;
fifo)
  mkfifo "$out"
  (setsid bash -c 'exec 3>"$1"' "fifo-writer-$TREE_MARKER" "$out" & echo $! >>"$TREE_DIR/pids") ;;
fifo-hang) mkfifo "$out"; exec 3>"$out" ;;
esac
EOF
small=(--outer 2 --levels 2)
prog="exec:bash $d/prog"
limits=(0.5 2 8 32 128)  # tried in turn until the program was ready before its timeout fired

# study_bg ARGS…: dlpverify in the background with TMPDIR=$d/tmp, its pid in $study, once the
# program has said it is ready.
study_bg() {
  mkdir -p "$d/tmp"
  TMPDIR=$d/tmp "$dlpverify" "$@" >/dev/null 2>"$d/err" &
  study=$!
  local deadline=$((SECONDS + 120))
  while [ ! -e "$d/ready" ] && [ $SECONDS -lt $deadline ] && kill -0 $study 2>/dev/null; do sleep 0.05; done
  [ -e "$d/ready" ] || { kill -KILL $study; fail "the program was not ready within 120 s: $(cat "$d/err")"; }
}
# Waits until signal $1 is no longer pending for process $2 (it was delivered), for up to 60 s.
delivered() {
  local bit pending deadline=$((SECONDS + 60))
  bit=$((1 << ($1 - 1)))
  while [ $SECONDS -lt $deadline ]; do
    pending=$(awk '/^ShdPnd:/ {print $2}' "/proc/$2/status")
    (( (16#$pending & bit) == 0 )) && return 0
    sleep 0.05
  done
  fail "signal $1 was still pending for dlpverify after 60 s"
}

case $mode in
leave)
  "$dlpverify" converge "${small[@]}" --integrator "$prog leave {input} {output}" >/dev/null 2>"$d/err" ||
    fail "exit $?: $(cat "$d/err")"
  all_ended
  ;;
paren-name)
  # A link's name is the process's name (the kernel takes it from the path exec was given).
  ln -s "$(command -v sleep)" "$d/sl) 1 2"
  "$dlpverify" converge "${small[@]}" --integrator "$prog paren-name {input} {output}" >/dev/null 2>"$d/err" ||
    fail "exit $?: $(cat "$d/err")"
  [ "$(wc -l <"$d/pids")" -eq 4 ] || fail "the program did not start its two processes at each of the 2 levels"
  all_ended
  ;;
fail)
  "$dlpverify" converge "${small[@]}" --integrator "$prog fail {input} {output}" >/dev/null 2>"$d/err"
  code=$?
  [ $code -eq 3 ] || fail "exit $code, expected 3: $(cat "$d/err")"
  all_ended
  ;;
timeout)
  for limit in "${limits[@]}"; do
    rm -f "$d/ready"
    mkdir -p "$d/tmp"
    TMPDIR=$d/tmp timeout -k 10 600 "$dlpverify" converge "${small[@]}" --exec-timeout "$limit" \
      --integrator "$prog hang {input} {output}" >/dev/null 2>"$d/err"
    code=$?
    grep -q "timed out after $limit s" "$d/err" || fail "exit $code with --exec-timeout $limit: $(cat "$d/err")"
    [ -e "$d/ready" ] && break
    all_ended
    echo "the program was not ready within --exec-timeout $limit s on this machine: again with a longer limit"
  done
  [ -e "$d/ready" ] || fail "the program was never ready before its timeout (the last limit ${limits[-1]} s)"
  [ $code -eq 3 ] || fail "exit $code, expected 3: $(cat "$d/err")"
  all_ended
  empty "$d/tmp"
  ;;
signal)
  study_bg converge "${small[@]}" --integrator "$prog hang {input} {output}"
  kill -TERM $study
  wait $study
  code=$?
  [ $code -eq 143 ] || fail "exit $code, expected 143 (SIGTERM): $(cat "$d/err")"
  all_ended
  empty "$d/tmp"
  ;;
signal-journal)
  study_bg converge "${small[@]}" --json "$d/s.json" --integrator "$prog hang {input} {output}"
  kill -TERM $study
  delivered 15 $study  # two at once would be one
  kill -0 $study 2>/dev/null || fail "the first SIGTERM ended the journaled study: $(cat "$d/err")"
  kill -TERM $study
  wait $study
  code=$?
  [ $code -eq 143 ] || fail "exit $code, expected 143 (SIGTERM): $(cat "$d/err")"
  all_ended
  empty "$d/tmp"
  ;;
fifo)
  mkdir "$d/tmp"
  TMPDIR=$d/tmp timeout -k 10 120 "$dlpverify" converge "${small[@]}" --exec-timeout 600 \
    --integrator "$prog fifo {input} {output}" >/dev/null 2>"$d/err"
  code=$?
  [ $code -eq 3 ] || fail "exit $code, expected 3: $(cat "$d/err")"
  lines=$(wc -l <"$d/err")
  [ "$lines" -eq 1 ] || fail "$lines lines on stderr, expected one: $(cat "$d/err")"
  grep -q "its output .*output.h5 is a FIFO, not a regular file" "$d/err" || fail "no line naming the FIFO: $(cat "$d/err")"
  all_ended
  empty "$d/tmp"
  ;;
fifo-hang)
  mkdir "$d/tmp"
  TMPDIR=$d/tmp timeout -k 10 600 "$dlpverify" converge "${small[@]}" --exec-timeout 1 \
    --integrator "$prog fifo-hang {input} {output}" >/dev/null 2>"$d/err"
  code=$?
  [ $code -eq 3 ] || fail "exit $code, expected 3: $(cat "$d/err")"
  grep -q "timed out after 1 s" "$d/err" || fail "no timeout: $(cat "$d/err")"
  empty "$d/tmp"
  ;;
quoting-space | quoting-semicolon)
  if [ "$mode" = quoting-space ]; then folders=("$d/a b" "$d/q'\"\$x\`b\\c d"); else folders=("$d/t;touch X;"); fi
  mkdir "$d/work"
  for folder in "${folders[@]}"; do
    mkdir "$folder"
    for shell in --exec-shell ""; do
      for command in "cp {input} {output}" "cp \"{input}\" \"{output}\"" "cp '{input}' '{output}'"; do
        [ -z "$shell" ] && [ "$command" != "cp {input} {output}" ] && continue  # the same words without a shell
        (cd "$d/work" && TMPDIR=$folder "$dlpverify" converge "${small[@]}" $shell --integrator "exec:$command") \
          >/dev/null 2>"$d/err" || fail "TMPDIR '$folder', ${shell:-no shell}, $command: exit $?: $(cat "$d/err")"
        empty "$folder"
        empty "$d/work"
      done
    done
  done
  ;;
*) fail "unknown mode $mode" ;;
esac
echo "ok: $mode"
