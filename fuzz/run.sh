#!/usr/bin/env bash
# Runs one fuzz target with libFuzzer on stable Rust (docs/fuzzing.md):
#   fuzz/run.sh <material_front|material_compile|scene> <seconds> [libFuzzer flags...]
# The working corpus is fuzz/work/<target>/ (started from the committed
# fuzz/corpus/<target>/ and fuzz/seeds/<target>/ the first time; new inputs
# are added there), crashes and hangs go to fuzz/artifacts/<target>/, the
# log to fuzz/work/<target>.log.
# Needs cargo-fuzz (`cargo install cargo-fuzz --locked`).
set -euo pipefail
cd "$(dirname "$0")"
target=$1
seconds=$2
shift 2
case "$target" in
    material_front) dict=material ;;
    material_compile) dict=material_compile ;;
    scene) dict=scene ;;
    *) echo "unknown target $target" >&2; exit 2 ;;
esac
mkdir -p work artifacts/"$target"
if [ ! -d work/"$target" ]; then
    cp -r corpus/"$target" work/"$target"
    # The seeds too, when fuzz/seed.sh has written them.
    if [ -d seeds/"$target" ]; then cp seeds/"$target"/* work/"$target"/; fi
fi
# -s none: no sanitizer, so no -Z flag and no nightly toolchain; -a: debug
# assertions and overflow checks on, as in the test suite's builds.
cargo fuzz build -s none -O -a "$target"
cargo fuzz run -s none -O -a "$target" work/"$target" -- \
    -dict=dict/"$dict".dict -timeout=1 -rss_limit_mb=2048 \
    -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix=artifacts/"$target"/ "$@" 2>&1 | tee work/"$target".log |
    grep -v -e '^#[0-9]*[[:space:]]*\(NEW\|REDUCE\)' -e '# Uses:'
