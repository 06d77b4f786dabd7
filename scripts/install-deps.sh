#!/usr/bin/env bash
# Installs the Debian packages sphv needs, when any is missing: directly as root, through
# sudo when that works without a password, otherwise prints the exact apt-get line and fails.
# With --tex also pdflatex and the packages the bundle's .tex files use (booktabs, longtable,
# xcolor, natbib: texlive-latex-recommended), and pdffonts (poppler-utils), which checks that the
# PDFs embed no Type 3 font: for scripts/bundle.sh and the bundle_compiles test.
set -euo pipefail
packages=(g++ cmake make ninja-build git libeigen3-dev libgsl-dev libsundials-dev catch2 nlohmann-json3-dev
          libcli11-dev libhdf5-dev libssl-dev libopenmpi-dev openmpi-bin python3-matplotlib python3-numpy)
case "${1:-}" in
  --tex) packages+=(texlive-latex-base texlive-latex-recommended poppler-utils) ;;
  "") ;;
  *) echo "sphv: error: unknown option '$1' (--tex)" >&2; exit 2 ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
line="apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends ${missing[*]}"
echo "sphv: installing missing Debian packages: ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then
  sh -c "$line" >&2
elif command -v sudo >/dev/null && sudo -n true 2>/dev/null; then
  sudo sh -c "$line" >&2
else
  echo "sphv: error: missing packages and no root rights; run as root: $line" >&2
  exit 1
fi
