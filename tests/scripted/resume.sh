# A run killed after a cycle and resumed gives the uninterrupted run's
# results; the resume refuses another parameter set.
source "$TESTS/common.bash"
resume_test
