#!/usr/bin/env bash
# Builds the Python package areagraph (python/) and installs it for a Python:
#   bash tools/install-python.sh                      Debian's /usr/bin/python3, or the active venv
#   bash tools/install-python.sh --python VENV/bin/python
# It goes into that Python's site-packages: /usr/local/lib/python3.X/dist-packages for Debian's
# python3 (so that `import areagraph` works from any folder), the venv's own for a venv. A venv
# must be made with --system-site-packages from Debian's python3, to see Debian's numpy,
# shapely, networkx and protobuf, which tools/install-deps.sh installs with everything else.
#   --build-dir DIR   build in DIR (default build/)
#   --no-build        install what DIR holds, without installing packages or building
set -euo pipefail
cd "$(dirname "$0")/.."
python=""
build_dir=build
build=1
while [ $# -gt 0 ]; do
  case "$1" in
    --python) python="$2"; shift 2 ;;
    --build-dir) build_dir="$2"; shift 2 ;;
    --no-build) build=0; shift ;;
    -h | --help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "install-python: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
if [ -z "$python" ]; then
  if [ -n "${VIRTUAL_ENV:-}" ]; then python="$VIRTUAL_ENV/bin/python"; else python=/usr/bin/python3; fi
fi

if [ "$build" = 1 ]; then
  tools/install-deps.sh
  echo "install-python: building the package in $build_dir (a first build takes about 10 minutes on 2 cores)"
  cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build_dir" -j "$(nproc)" --target areagraph_python
fi
if [ ! -x "$python" ]; then
  echo "install-python: no Python at '$python'" >&2
  exit 1
fi
package="$build_dir/python/areagraph"
module=$(ls "$package"/_core*.so 2>/dev/null || true)
if [ ! -f "$package/__init__.py" ] || [ -z "$module" ]; then
  echo "install-python: $package holds no built package; run without --no-build" >&2
  exit 1
fi
# The module is built for Debian's python3; another version cannot load it.
suffix=$("$python" -c 'import sysconfig; print(sysconfig.get_config_var("EXT_SUFFIX"))')
if [ "$(basename "$module")" != "_core$suffix" ]; then
  echo "install-python: $python wants modules named _core$suffix, the build made $(basename "$module") (for /usr/bin/python3)" >&2
  exit 1
fi
site=$("$python" -c 'import sysconfig; print(sysconfig.get_path("platlib"))')
mkdir -p "$site"
rm -rf "$site/areagraph"
mkdir "$site/areagraph"
cp "$package"/*.py "$module" "$package/libag_image_codecs.so" "$site/areagraph/"
if ! (cd / && env -u PYTHONPATH "$python" -c 'import areagraph, numpy, shapely, networkx, google.protobuf') 2>/dev/null; then
  echo "install-python: installed into $site, but $python cannot import areagraph's dependencies (numpy, shapely, networkx, protobuf from Debian; a venv needs --system-site-packages)" >&2
  exit 1
fi
echo "install-python: installed areagraph for $python in $site/areagraph"
