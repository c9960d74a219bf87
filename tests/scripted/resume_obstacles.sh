# resume.sh with two plane obstacles on two processes: an inclined floor
# under the beam and a wall beyond its tip, which the tip face (id 1) may
# touch as well as the bottom (the bottom's tip vertex a corner of two
# nodes), killed and resumed with the same results.
source "$TESTS/common.bash"
SCENE=("subsection Obstacle" "  set Type   = plane" "  set Height = 0"
  "  set Point  = 0, -0.15" "  set Normal = 0.02, 1"
  "  set Contact boundary ids = 1, 2" "end"
  "subsection Obstacle 2" "  set Type   = plane" "  set Point  = 10.005, 0"
  "  set Normal = -1, 0" "end")
CYCLES=4 KILL_AFTER=1
resume_test mpirun -np 2
