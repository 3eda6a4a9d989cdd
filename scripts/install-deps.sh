#!/usr/bin/env bash
# Installs the Debian packages pds builds against. Idempotent: packages already
# present are not touched, and apt is not asked at all when nothing is missing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config ccache      # ccache: rebuilds and the consumer tests' nested builds reuse objects
  libgtest-dev libgmock-dev libbenchmark-dev   # tests and benchmarks
  libcli11-dev nlohmann-json3-dev              # command line and JSON output
  libcairo2-dev libpng-dev fonts-dejavu-core   # pictures (Cairo draws text with a system font)
  libfftw3-dev libgsl-dev                      # spectra, quasi-random sequences
  libcgal-dev                                  # Delaunay/Voronoi (the cgal component)
  pybind11-dev python3-dev python3-numpy       # the Python module (for Debian's /usr/bin/python3)
  python3-scipy python3-pytest python3-matplotlib  # its tests, the SciPy drop-in's reference, the example
  libopenmpi-dev openmpi-bin                   # pds-mpi (optional: chunks across processes and machines)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
