# doc/parameters.md is what the program prints: scripts/parameter-reference
# regenerates it from `signorini --print-parameters 2` and `3` here, and the
# page must equal the committed one byte for byte.
root=$(cd "$TESTS/../.." && pwd)
"$root/scripts/parameter-reference" --program "$SIGNORINI" \
  --output parameters.md > generate.log 2>&1 || {
  echo "scripts/parameter-reference failed:"
  cat generate.log
}
if cmp -s parameters.md "$root/doc/parameters.md"; then
  echo "doc/parameters.md: as the program prints it"
else
  echo "doc/parameters.md differs from what the program prints; regenerate it:"
  echo "  scripts/parameter-reference   (or: scripts/parameter-reference --program build/signorini)"
  diff -u "$root/doc/parameters.md" parameters.md | head -40
fi
