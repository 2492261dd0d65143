#!/usr/bin/env bash
# Renders the city and the forest under each sky and weather of docs/rendering.md ("Sky and weather") with
# `airis scene preview`, and tiles the RGB images into docs/images/realism_SCENE.png: the flat look of the
# gradient sky, then a clear noon, a clear evening (both with sun shadows) and overcast fog. Given the
# checkout of a build from before the realism work (BEFORE: a directory with scenes/ and build/airis), a
# first row shows the same views as that build drew them: the scene as it was, noon, evening and fog (the
# fog of the same 600 m visibility, uniform: that build had no sky models, height fog or shadows).
# Usage: scripts/realism-sheet.sh [BUILD_DIR] [BEFORE]   (run from the repository root; needs python3-pil)
set -euo pipefail
build=${1:-build}
before=${2:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

declare -A pose=([city]="0,-6,-70,20,-16" [forest]="-90,-60,-70,35,-14")
# Noon and evening suns in each scene's own terms (the city places its sun by the time of day, the forest by
# its angles; a scene takes one or the other).
declare -A noon=([city]="scene.lighting.time_of_day_h=12.5" [forest]="scene.lighting.sun_elevation_deg=60")
declare -A evening=([city]="scene.lighting.time_of_day_h=18.7" [forest]="scene.lighting.sun_elevation_deg=8")
conditions=(
  "flat|scene.lighting.sky=gradient"
  "noon|scene.lighting.sky=clear NOON scene.lighting.shadows.enabled=true"
  "evening|scene.lighting.sky=clear EVENING scene.lighting.turbidity=4 scene.lighting.shadows.enabled=true"
  "fog|scene.lighting.sky=overcast scene.lighting.fog_distance_m=0 scene.lighting.visibility_m=600 scene.lighting.fog_height_m=60"
)
# The same views in the keys the build before knew (fog distance = visibility / 3.912).
before_conditions=(
  "before|"
  "before: noon|NOON"
  "before: evening|EVENING"
  "before: fog|scene.lighting.fog_distance_m=153"
)

# Renders one tile: render AIRIS ROOT SCENE NAME SETTINGS...; appends "png|label" to tiles.
render() {
  local airis=$1 root=$2 scene=$3 name=$4
  shift 4
  local sets=() s
  for s in "$@"; do
    case $s in NOON) s=${noon[$scene]} ;; EVENING) s=${evening[$scene]} ;; esac
    sets+=(--set "$s")
  done
  local png="$work/${scene}_${name//[: ]/_}.png"
  "$airis" scene preview "$root/scenes/$scene.yaml" --pose "${pose[$scene]}" "${sets[@]}" \
    --out "$png" > /dev/null
  tiles+=("$png|$name")
}

for scene in city forest; do
  tiles=()
  rows=1
  if [[ -n $before ]]; then
    rows=2
    for c in "${before_conditions[@]}"; do
      # shellcheck disable=SC2086
      render "$before/build/airis" "$before" "$scene" "${c%%|*}" ${c#*|}
    done
  fi
  for c in "${conditions[@]}"; do
    # shellcheck disable=SC2086
    render "$build/airis" . "$scene" "${c%%|*}" ${c#*|}
  done
  python3 - "docs/images/realism_$scene.png" "$rows" "${tiles[@]}" <<'PY'
import sys
from PIL import Image, ImageDraw
out, rows, tiles = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
images = []
for t in tiles:
    path, label = t.rsplit("|", 1)
    im = Image.open(path).convert("RGB")
    w, h = im.size
    rgb = im.crop((0, 0, w // 3, h)).resize((w // 6, h // 2))  # the preview's RGB third, halved
    ImageDraw.Draw(rgb).text((6, 4), label, fill=(255, 255, 255))
    images.append(rgb)
w, h = images[0].size
columns = len(images) // rows
sheet = Image.new("RGB", (w * columns, h * rows))
for i, im in enumerate(images):
    sheet.paste(im, ((i % columns) * w, (i // columns) * h))
sheet.save(out, optimize=True)
print("wrote", out, sheet.size)
PY
done
