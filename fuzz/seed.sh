#!/usr/bin/env bash
# Builds the fuzz targets' starting corpora and dictionaries from the repo:
# the shipped materials and scenes and the diagnostics corpora. Writes
# fuzz/seeds/<target>/ (not committed: the committed fuzz/corpus/ is this,
# grown by a long run and minimised; docs/fuzzing.md) and fuzz/dict/*.dict.
set -euo pipefail
cd "$(dirname "$0")/.."
out=fuzz/seeds
rm -rf "$out"
mkdir -p "$out"/{material_front,material_compile,scene} fuzz/dict

# Material TOML files, with the folder they sit in and their materials root.
materials=$(ls materials/*/*.toml tests/diagnostics/materials/*/*.toml \
    tests/diagnostics/scenes/materials/*/*.toml docs/example/*/*.toml \
    tests/fixtures/materials/*/*.toml)

for toml in $materials; do
    dir=$(dirname "$toml")
    stem=$(basename "$toml" .toml)
    tag=$(echo "$dir" | tr '/' '_')_$stem
    # (a) the TOML alone.
    cp "$toml" "$out/material_front/$tag.toml"
    # (b) the TOML, its source (named by `source`, else <stem>.wgsl) as m/<file>,
    # and its root's lib/ unless that is the shipped one (the target adds it).
    src=$(sed -n 's/^source *= *"\(.*\)".*/\1/p' "$toml" | head -n1)
    src=${src:-$stem.wgsl}
    root=$(dirname "$dir")
    {
        cat "$toml"
        if [ -f "$dir/$src" ]; then
            printf '\n%%%%%% m/%s\n' "$src"
            cat "$dir/$src"
        fi
        if [ "$root" != materials ] && [ -d "$root/lib" ]; then
            for lib in "$root"/lib/*.wgsl; do
                printf '\n%%%%%% lib/%s\n' "$(basename "$lib")"
                cat "$lib"
            done
        fi
    } > "$out/material_compile/$tag.txt"
done

# (c) scenes, named `fuzz` (the target reads them as fuzz.scene.toml); the
# shipped ones get the shipped materials root as seen from the corpus folder.
for scene in scenes/*.scene.toml tests/diagnostics/scenes/*/*.scene.toml; do
    tag=$(dirname "$scene" | tr '/' '_')_$(basename "$scene" .scene.toml)
    case "$scene" in
        scenes/*) extra='materials = "../../../../materials"' ;;
        *) extra='' ;;
    esac
    awk -v extra="$extra" '
        /^name *= *"/ && !named { print "name = \"fuzz\""; named = 1; next }
        { print }
        /^\[scene\]/ && extra != "" { print extra }
    ' "$scene" > "$out/scene/$tag.toml"
done

# Dictionaries: every lower-case word the front end and the metadata spell
# (keys, enum values, types), TOML punctuation, and WGSL tokens for (b).
words() {
    grep -ohE '"[a-z][a-z0-9_]{1,30}"' "$@" | sort -u
}
punct='"="
"[["
"]]"
"["
"]"
"{"
"}"
"\\x22\\x22\\x22"
"\\x0a"
", "
"1e308"
"-1"
"0.5"
"4294967296"
"9223372036854775807"
"nan"
"inf"
"true"
"false"
"=="
"!="
"&&"
"||"
" in "
"tier"'
{
    words crates/weft-front/src/*.rs crates/weft-front/src/parse/*.rs crates/weft-meta/src/*.rs
    echo "$punct"
} > fuzz/dict/material.dict
{
    cat fuzz/dict/material.dict
    printf '%s\n' '"\x0a%%% m/m.wgsl\x0a"' '"\x0a%%% lib/brdf.wgsl\x0a"' '"// @include \x22lib/brdf.wgsl\x22\x0a"' \
        '"fn "' '"override "' '"const "' '"var<uniform> "' '"@vertex"' '"@fragment"' '"@group(1) @binding(0)"' \
        '"if ("' '"switch "' '"return "' '"f32"' '"u32"' '"bool"' '"vec4<f32>"' '"textureSample("' '"loop {"' '"for ("'
} > fuzz/dict/material_compile.dict
{
    words crates/weft-front/src/scene/*.rs crates/weft-front/src/parse/*.rs crates/weft-meta/src/scene.rs
    echo "$punct"
    for m in materials/*/; do echo "\"$(basename "$m")\""; done
} | sort -u > fuzz/dict/scene.dict
for t in material_front material_compile scene; do
    echo "$t: $(ls "$out/$t" | wc -l) seeds, $(du -sk "$out/$t" | cut -f1) KiB"
done
