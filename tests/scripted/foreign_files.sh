# An output directory that holds files a run would overwrite or remove
# (its statistics.csv, a file named like a cycle's) and that no run wrote
# (no parameters.prm of one) is refused before anything is written: the
# user's files stay as they were. With the files of a run it is the run's.
source "$TESTS/common.bash"
mkdir out
echo "my table" > out/statistics.csv
echo "my picture" > out/solution-01.vtu
echo "notes" > out/notes.txt
scene scene.prm out
echo "a directory with the user's statistics.csv and solution-01.vtu:"
run "$SIGNORINI" scene.prm
echo "files:"
files out
echo "unchanged:" $(cat out/statistics.csv out/solution-01.vtu out/notes.txt | tr '\n' ' ')
echo "the same files moved away:"
rm out/statistics.csv out/solution-01.vtu
run "$SIGNORINI" scene.prm
echo "run again into the directory it wrote:"
run "$SIGNORINI" scene.prm
echo "notes kept:" $(cat out/notes.txt)
