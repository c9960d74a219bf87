# resume.sh on two processes: both are killed, both resume.
source "$TESTS/common.bash"
resume_test mpirun -np 2
