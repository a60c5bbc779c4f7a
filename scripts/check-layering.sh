#!/usr/bin/env bash
# Layering rules of gibi (style.md): pest is named only in src/syntax, and
# the numerical layers never see the language side.
set -u
cd "$(dirname "$0")/.."
fail=0
if grep -rn --include=*.rs -E '\bpest(_derive)?::' src | grep -v '^src/syntax/' ; then
  echo "pest is used outside src/syntax"; fail=1
fi
for layer in src/solve src/fem src/analysis; do
  if grep -rn --include=*.rs -E 'crate::(syntax|eval|ops|value)\b' "$layer"; then
    echo "$layer imports the language side"; fail=1
  fi
done
exit $fail
