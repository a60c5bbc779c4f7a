#!/usr/bin/env bash
# Layering rules of gibi (ARCHITECTURE.md): every import points down.
#
#   lib.rs, bin/         the embedding API and the command line
#   ops/                 operator families
#   eval/                machine, registry, argument reader
#   value/               Gibiane objects
#   syntax/              text to instructions
#   analysis/ io/ fem/ solve/ props/   below the language
#   error.rs source.rs   the basement, shared by all
#
# A folder may import only the folders its line below allows. Imports are
# read as text: `crate::layer`, `use crate::{…, layer, …}`, a chain of
# `super::` that climbs to the crate root, and the root's re-exports
# (`crate::Value`, `crate::Interpreter` …), each counted as the layer it
# comes from. pest is named only in src/syntax.
set -u
cd "$(dirname "$0")/.."

# What each layer may import (besides itself and the basement).
declare -A ALLOWED=(
  [syntax]=""
  [value]="syntax fem solve analysis"
  [eval]="syntax value fem solve io analysis"
  [ops]="syntax value eval fem solve io analysis props"
  [io]="fem"
  [fem]=""
  [solve]=""
  [analysis]="fem solve io props"
  [props]=""
)
LAYERS="syntax value eval ops io fem solve analysis props"
# The crate root's re-exports, by the layer they come from; `lib` names
# the embedding API, which no layer may use.
declare -A ROOT_NAME=(
  [Value]=value [Args]=eval [OpSpec]=eval [Registry]=eval [FilePolicy]=eval
  [Interpreter]=lib [InterpreterBuilder]=lib [Capture]=lib [Outcome]=lib
)

fail=0
report() { # file line layer target
  echo "$1:$2: src/$3 imports $4"
  fail=1
}

# The layers a line names, through crate:: paths, brace groups and the
# root's re-exports.
targets() {
  local line=$1 t
  for t in $LAYERS; do
    if [[ $line =~ crate::$t([^A-Za-z0-9_]|$) ]] || [[ $line =~ crate::\{[^}]*(^|[^A-Za-z0-9_:])$t([^A-Za-z0-9_]|$) ]]; then
      echo "$t"
    fi
  done
  for t in "${!ROOT_NAME[@]}"; do
    if [[ $line =~ crate::$t([^A-Za-z0-9_]|$) ]] || [[ $line =~ crate::\{[^}]*(^|[^A-Za-z0-9_:])$t([^A-Za-z0-9_]|$) ]]; then
      echo "${ROOT_NAME[$t]}"
    fi
  done
}

# `super::` repeated as often as the file is deep reaches the crate root:
# src/a/mod.rs is one level down, src/a/b.rs and src/a/b/mod.rs two …
root_chain() {
  local file=${1#src/} depth
  depth=$(awk -F/ '{ n = NF; if ($NF == "mod.rs") n--; print n }' <<<"$file")
  printf 'super::%.0s' $(seq 1 "$depth")
}

for dir in src/*/; do
  layer=$(basename "$dir")
  [[ $layer == bin ]] && continue
  allowed=" $layer ${ALLOWED[$layer]-__unknown__} "
  if [[ $allowed == *__unknown__* ]]; then
    echo "src/$layer is not a known layer: add it to scripts/check-layering.sh and ARCHITECTURE.md"
    fail=1
    continue
  fi
  while IFS= read -r file; do
    chain=$(root_chain "$file")
    lineno=0
    while IFS= read -r line; do
      lineno=$((lineno + 1))
      code=${line%%//*}
      [[ $code == *crate::* || $code == *"$chain"* ]] || continue
      # A super:: chain to the root reads as crate::.
      code=${code//$chain/crate::}
      for t in $(targets "$code"); do
        [[ $allowed == *" $t "* ]] || report "$file" "$lineno" "$layer" "$t"
      done
    done <"$file"
  done < <(find "$dir" -name '*.rs' | sort)
done

# The basement may use what is below the language, never the language.
for file in src/error.rs src/source.rs; do
  lineno=0
  while IFS= read -r line; do
    lineno=$((lineno + 1))
    code=${line%%//*}
    for t in $(targets "$code"); do
      case $t in fem | solve | io) ;; *) echo "$file:$lineno: the basement imports $t"; fail=1 ;; esac
    done
  done <"$file"
done

if grep -rn --include=*.rs -E '\bpest(_derive)?::' src | grep -v '^src/syntax/'; then
  echo "pest is used outside src/syntax"
  fail=1
fi
[[ $fail == 0 ]] && echo "layering: every import points down"
exit $fail
