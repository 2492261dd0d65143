#!/usr/bin/env bash
# Renders the city and the forest under each sky and weather of docs/rendering.md ("Sky and weather") with
# `airis scene preview`, and tiles the RGB images into docs/images/realism_SCENE.png: the flat look of the
# gradient sky, then a clear noon, a clear evening (both with sun shadows) and overcast fog.
# Usage: scripts/realism-sheet.sh [BUILD_DIR]   (run from the repository root; needs python3-pil)
set -euo pipefail
build=${1:-build}
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
for scene in city forest; do
  tiles=()
  for c in "${conditions[@]}"; do
    name=${c%%|*}
    sets=()
    for s in ${c#*|}; do
      case $s in NOON) s=${noon[$scene]} ;; EVENING) s=${evening[$scene]} ;; esac
      sets+=(--set "$s")
    done
    "$build/airis" scene preview "scenes/$scene.yaml" --pose "${pose[$scene]}" "${sets[@]}" \
      --out "$work/${scene}_$name.png" > /dev/null
    tiles+=("$work/${scene}_$name.png:$name")
  done
  python3 - "docs/images/realism_$scene.png" "${tiles[@]}" <<'PY'
import sys
from PIL import Image, ImageDraw
out, tiles = sys.argv[1], sys.argv[2:]
images = []
for t in tiles:
    path, label = t.rsplit(":", 1)
    im = Image.open(path).convert("RGB")
    w, h = im.size
    rgb = im.crop((0, 0, w // 3, h)).resize((w // 6, h // 2))  # the preview's RGB third, halved
    ImageDraw.Draw(rgb).text((6, 4), label, fill=(255, 255, 255))
    images.append(rgb)
w, h = images[0].size
sheet = Image.new("RGB", (w * len(images), h))
for i, im in enumerate(images):
    sheet.paste(im, (i * w, 0))
sheet.save(out, optimize=True)
print("wrote", out, sheet.size)
PY
done
