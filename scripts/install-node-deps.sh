#!/usr/bin/env bash
# Installs the npm packages of the MAVLink conformance test (node-mavlink and its pinned mavlink-mappings,
# exactly as tests/mavlink/package-lock.json records them) into BUILD_DIR/node/node_modules, with npm's
# cache in BUILD_DIR/npm-cache. Both are inside the build folder, which git ignores.
#
#   scripts/install-node-deps.sh [BUILD_DIR]     (default: build)
#
# Idempotent: when BUILD_DIR/node already holds an install of the same package-lock.json it does nothing
# (no network); otherwise `npm ci`, which prefers the cache, so a reinstall after the first one works
# offline. CMake runs it when it configures the tests (tests/mavlink/CMakeLists.txt). Without node or npm
# it says so and exits 0: the conformance test then skips, saying why.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-build}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
src="$root/tests/mavlink"
dest="$build/node"

for tool in node npm; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "install-node-deps: $tool not found; the node-mavlink conformance test will be skipped" \
         "(scripts/install-deps.sh installs nodejs and npm)"
    exit 0
  fi
done

stamp="$dest/node_modules/.airis-lock.sha256"
want="$(sha256sum "$src/package-lock.json" | cut -d' ' -f1)"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ] && [ -d "$dest/node_modules/node-mavlink" ]; then
  echo "install-node-deps: node-mavlink already installed in $dest"
  exit 0
fi

mkdir -p "$dest"
cp "$src/package.json" "$src/package-lock.json" "$dest/"
echo "install-node-deps: npm ci in $dest"
# Optional and peer packages (TypeScript compilers pulled in by the mappings' generator) are not needed
# to run node-mavlink.
(cd "$dest" && npm ci --cache "$build/npm-cache" --prefer-offline --omit=optional --omit=peer \
   --no-audit --no-fund --loglevel=error)
echo "$want" > "$stamp"
echo "install-node-deps: node-mavlink $(node -p "require('$dest/node_modules/node-mavlink/package.json').version") installed in $dest"
