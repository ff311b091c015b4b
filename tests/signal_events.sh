# Sourced by the tests that stop a study with a signal (cli/journal.sh, mpi/resume.sh,
# mpi/mpirun_sigterm.sh). No wait
# here is a fixed time: each is for an event that the study reports (a level in its journal) or
# the kernel does (a process's state in /proc/PID/stat, its pending signals in /proc/PID/status),
# polled every 10 ms. The only clock is a deadline per wait that catches a hang, 600 s, far
# beyond any event here on any machine; its expiry fails the test and names what was awaited.
# The caller defines fail MESSAGE.
await_deadline=600

# await WHAT COMMAND...: polls COMMAND until it succeeds.
await() {
  local what=$1 deadline=$((SECONDS + await_deadline))
  shift
  until "$@"; do
    [ "$SECONDS" -lt "$deadline" ] || fail "$what: not within $await_deadline s (hung?)"
    sleep 0.01
  done
}

# journaled JOURNAL: how many levels the journal holds (its whole lines after the header).
journaled() {
  local lines=0
  [ -f "$1" ] && lines=$(wc -l <"$1")
  echo $((lines > 1 ? lines - 1 : 0))
}

# kept_levels JOURNAL TOTAL: the levels a study stands still with, once its journal was seen
# holding one: TOTAL when the journal is gone (removed once every output was written).
kept_levels() {
  if [ -e "$1" ]; then journaled "$1"; else echo "$2"; fi
}

# has_a_level JOURNAL PID: the journal holds a finished level; fails the test if PID ended first.
has_a_level() {
  [ "$(journaled "$1")" -ge 1 ] && return 0
  ended "$2" && fail "the study ended before its first level was journaled"
  return 1
}

# state PID: its state letter (R running, S sleeping, T stopped, Z ended), empty once it is gone.
state() {
  local stat
  read -r stat 2>/dev/null <"/proc/$1/stat" || return 0
  stat=${stat##*) }
  echo "${stat%% *}"
}

# ended PID: the process has exited (a zombie, or gone).
ended() {
  case $(state "$1") in Z | "") return 0 ;; *) return 1 ;; esac
}

# all_stopped PID...: every process stands still (SIGSTOP), or has already exited.
all_stopped() {
  local pid
  for pid in "$@"; do [ "$(state "$pid")" = T ] || ended "$pid" || return 1; done
}

# none_stopped PID...: no process stands still (a SIGCONT reached every one).
none_stopped() {
  local pid
  for pid in "$@"; do [ "$(state "$pid")" != T ] || return 1; done
}

# freeze PID...: SIGSTOP, and wait until every process stands still (or has exited).
freeze() {
  kill -STOP "$@" 2>/dev/null
  await "SIGSTOP to $*" all_stopped "$@"
}

# sigterm_pending PID...: SIGTERM (signal 15: bit 14 of the mask) waits in the shared pending set
# of every process that has not exited, as a process-directed signal does while it is stopped.
sigterm_pending() {
  local pid mask
  for pid in "$@"; do
    ended "$pid" && continue
    mask=$(awk '$1 == "ShdPnd:" { print $2 }' "/proc/$pid/status" 2>/dev/null)
    [ -n "$mask" ] && (((16#$mask >> 14) & 1)) || return 1
  done
}

# stopped_study CODE KEPT TOTAL JOURNAL [STOP_CODE FINISH_CODE]: what a study signalled with
# SIGTERM while it stood still with KEPT of TOTAL levels journaled must show, its exit code CODE.
# With KEPT < TOTAL its last level was not yet recorded, so the signal came before the study's
# last decision to go on: exit STOP_CODE (143), one stop line, every finished level in the
# journal (KEPT or more), no JSON. With KEPT = TOTAL the signal may also come after that decision,
# or after the study ended: then exit FINISH_CODE (0) with the JSON written and the journal
# removed. (mpirun signalled itself exits 1 either way.) Reads the study's stderr and out.json in the current folder; sets outcome
# to stopped or finished, and levels to the levels journaled.
stopped_study() {
  local code=$1 kept=$2 total=$3 journal=$4 stop_code=${5:-143} finish_code=${6:-0}
  if [ "$kept" -eq "$total" ] && [ "$code" -eq "$finish_code" ] && [ ! -e "$journal" ]; then
    [ -s out.json ] || fail "finished after the signal (exit $code), but no JSON"
    outcome=finished levels=$total
    return
  fi
  [ "$code" -eq "$stop_code" ] || fail "SIGTERM with $kept of $total levels journaled: exit $code, expected $stop_code"
  levels=$(journaled "$journal")
  [ "$levels" -ge "$kept" ] || fail "the journal lost levels: $levels, $kept before the signal"
  [ "$(wc -l <stderr)" -eq 1 ] && grep -q "SIGTERM: stopped after $levels of $total levels; $journal keeps the first.*--resume" stderr ||
    fail "no single stop line for the $levels journaled levels"
  [ ! -e out.json ] || fail "a stopped study wrote its JSON"
  outcome=stopped
}
