#!/usr/bin/env bash
# The layer check is itself checked: in a scratch tree that obeys the rule it passes; a planted
# include of model/ from impl/, of impl/ from spec/, of model/ from apps/, or a mutant hook in
# impl/ each make it fail, naming the file and line.
set -u
check="$1/scripts/check-layers"
tree=$(mktemp -d); trap 'rm -rf "$tree"' EXIT
mkdir -p "$tree"/{spec/a,model/a,impl/a,apps/a}
echo '#include "spec/a/x.hpp"' > "$tree/model/a/m.cpp"
echo '#include "spec/a/x.hpp"' > "$tree/impl/a/i.cpp"
echo '#include <vector>' > "$tree/spec/a/x.hpp"
"$check" "$tree" > /dev/null || { echo "FAIL: a clean tree was rejected"; exit 1; }

plant() {   # plant FILE LINE: add LINE to FILE in the tree; the check must fail naming FILE:1
  local file=$1 line=$2 saved; saved=$(cat "$tree/$file" 2>/dev/null || true)
  printf '%s\n%s\n' "$line" "$saved" > "$tree/$file"
  out=$("$check" "$tree"); rc=$?
  if [ $rc -ne 1 ] || ! grep -q "^$file:1:" <<<"$out"; then
    echo "FAIL: planted '$line' in $file: exit $rc, output: $out"; exit 1
  fi
  if [ -n "$saved" ]; then printf '%s\n' "$saved" > "$tree/$file"; else rm "$tree/$file"; fi
  echo "caught: $file: $line"
}
plant impl/a/i.cpp '#include "model/a/m.hpp"'
plant impl/a/i.cpp '#include "conformance/x/y.hpp"'
plant spec/a/x.hpp '#include "impl/a/i.hpp"'
plant model/a/m.cpp '#include "impl/a/i.hpp"'
plant apps/a/v.cpp '#include "model/a/m.hpp"'
plant impl/a/i.cpp 'constexpr int kMutant = 3;'
"$check" "$tree" > /dev/null || { echo "FAIL: the restored tree was rejected"; exit 1; }
echo "every planted violation was caught"
