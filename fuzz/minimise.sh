#!/usr/bin/env bash
# Cuts a target's working corpus (fuzz/work/<target>/, grown by run.sh) down
# to the committed one (docs/fuzzing.md, "Minimising the corpus"):
#   fuzz/minimise.sh <target> [inputs, default 100]
# 1. libFuzzer's set-cover merge (edges only, hit counts ignored);
# 2. each remaining input's own edge list (one merge per input);
# 3. greedily, the input that adds the most edges not yet reached (the
#    smaller on ties), until <inputs> are chosen or nothing is added.
# Replaces fuzz/corpus/<target>/ and prints the edges the kept inputs reach.
set -euo pipefail
cd "$(dirname "$0")"
target=$1
keep=${2:-100}
bin=target/x86_64-unknown-linux-gnu/release/$target
cargo fuzz build -s none -O -a "$target"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/merged" "$tmp/edges"
"$bin" -merge=1 -set_cover_merge=1 -use_counters=0 "$tmp/merged" work/"$target" 2>&1 | tail -n 1
for f in "$tmp"/merged/*; do
    n=$(basename "$f")
    mkdir -p "$tmp/one/in" "$tmp/one/out"
    cp "$f" "$tmp/one/in/"
    "$bin" -merge=1 -use_counters=0 -merge_control_file="$tmp/one/control" \
        "$tmp/one/out" "$tmp/one/in" > /dev/null 2>&1
    grep '^COV' "$tmp/one/control" | cut -d' ' -f3- > "$tmp/edges/$n"
    rm -rf "$tmp/one"
done
python3 - "$tmp" "$keep" > "$tmp/chosen" <<'PY'
import os, sys
tmp, keep = sys.argv[1], int(sys.argv[2])
edges = {n: set(open(f"{tmp}/edges/{n}").read().split()) for n in os.listdir(f"{tmp}/edges")}
size = {n: os.path.getsize(f"{tmp}/merged/{n}") for n in edges}
every = set().union(*edges.values())
reached, chosen = set(), []
while len(chosen) < keep:
    best = max(edges, key=lambda n: (len(edges[n] - reached), -size[n], n))
    if not edges[best] - reached:
        break
    chosen.append(best)
    reached |= edges[best]
print("\n".join(chosen))
print(f"{len(chosen)} inputs reach {len(reached)} of {len(every)} edges", file=sys.stderr)
PY
rm -rf corpus/"$target"
mkdir -p corpus/"$target"
while read -r n; do cp "$tmp/merged/$n" corpus/"$target"/; done < "$tmp/chosen"
echo "corpus/$target: $(ls corpus/"$target" | wc -l) files, $(du -sb corpus/"$target" | cut -f1) bytes"
