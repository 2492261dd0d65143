#!/usr/bin/env bash
# Makes `import airis` work for this user: writes airis.pth into the user's site-packages (of Debian's
# /usr/bin/python3 unless PYTHON is set), pointing at the package the build assembled in BUILD/python.
# Nothing is downloaded or copied; rebuilding updates what Python imports. Remove the .pth to undo.
set -euo pipefail
BUILD="${1:-build}"
PYTHON="${PYTHON:-/usr/bin/python3}"
package="$(cd "$BUILD/python" && pwd)"
if ! ls "$package"/airis/_airis*.so >/dev/null 2>&1; then
  echo "install-python: $package/airis has no built extension: run 'make python' (or build target airis_python)" >&2
  exit 1
fi
site="$("$PYTHON" -m site --user-site)"
mkdir -p "$site"
echo "$package" > "$site/airis.pth"
echo "install-python: $site/airis.pth -> $package"
"$PYTHON" -c "import airis; print('install-python: import airis', airis.__version__, 'from', airis.__file__)"
