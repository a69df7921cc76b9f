#!/usr/bin/env bash
# Installs everything fourbar needs to build, test and benchmark, from Debian
# packages only. Run as root on a fresh Debian 12 machine; safe to run again.
set -euo pipefail

packages=(
  build-essential cmake pkg-config ninja-build
  libfftw3-dev            # FFT filtering and spectra (analyze)
  libeigen3-dev           # small dense linear algebra (sim, analyze)
  libsndfile1-dev         # WAV/W64/RF64/FLAC/CAF/AIFF recordings (acquire)
  libmatio-dev            # MATLAB .mat v5 and v7.3 (HDF5) recordings (acquire)
  zlib1g-dev              # acquire: the headers of compressed .mat variables, checked before libmatio
  libboost-dev            # Boost.Odeint integrators (header-only)
  libboost-program-options-dev  # the fourbar command line
  libtomlplusplus-dev     # rig, scene and manifest files
  nlohmann-json3-dev      # JSON summaries
  libnlopt-dev            # derivative-free optimisers for the contact-parameter fit (fit/)
  libsundials-dev         # CVODE with root finding (sim events)
  libgtest-dev libgmock-dev     # unit tests
  libbenchmark-dev        # bench/ programs
  python3                 # scripts/check-readme.py (CTest readme, doc_links)
  python3-scipy           # bench/compare_analyze_scipy.py (numpy/scipy reference of the analyze chain)
  python3-pandas          # tests/cli/csv_in_pandas.py: every CSV fourbar writes opens with plain read_csv
  libopenmpi-dev openmpi-bin    # fourbar sweep over MPI ranks (cluster/; optional at build time)
  libssl-dev              # SHA-256 (libcrypto) for the report's checksums and cache keys
  libjs-dygraphs          # charting library inlined into the HTML report
  chromium                # headless browser test of the HTML report
  poppler-utils           # pdftoppm: the printed report's pages as images (browser print test)
  clang libclang-rt-14-dev      # scripts/fuzz.sh: libFuzzer, ASan and UBSan runtimes (Debian 12's clang 14)
)

if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then exec sudo "$0" "$@"; fi
  echo "install-deps: apt-get needs root; run this script as root" >&2
  exit 1
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
