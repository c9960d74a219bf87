# No #include <signorini/FOLDER/...> in include/ or source/ runs upward
# against the "Dependency order" of doc/architecture.md (read from the page
# when the test runs): each upward include is listed with its file and line.
python3 "$TESTS/architecture.py" includes
