# The file map of doc/architecture.md matches the tree as it is when the
# test runs: every .h under include/ and .cc under source/ is named there
# (by its path, e.g. `contact/obstacle`, or its file name), and every entry
# of the map's first column exists. A finding names the file.
python3 "$TESTS/architecture.py" files
