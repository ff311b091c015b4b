# Sourced by the MPI tests: OpenMPI as the tests need it, set here and never in the user's shell.
# CI runs as root, which mpirun refuses unless told twice; a container's ptrace rules make the
# shared-memory transport's single-copy mechanism fail noisily, and two cores carry three ranks.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_hwloc_base_binding_policy=none
# Three ranks of two OpenMP threads each on two cores: a spinning thread waits at every barrier for
# one that is descheduled. Waiting threads sleep instead (the bits do not depend on it).
export OMP_WAIT_POLICY=passive
# run_ranks N ARGS...: the command on N ranks; -q: mpirun adds no banner of its own to an error line
run_ranks() {
  local ranks=$1
  shift
  "$mpiexec" -q -np "$ranks" --oversubscribe "$@"
}
