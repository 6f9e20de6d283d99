#!/usr/bin/env bash
# Install what xcable needs and is missing, and only that, saying what it installs.
#   Debian/Ubuntu packages: gfortran liblapack-dev libhdf5-dev hdf5-tools pkg-config gnuplot-nox
#   PyPI: fpm, h5py (the tests edit a checkpoint's attributes with it, to check that a foreign
#     checkpoint is refused)
# Run as root (or with sudo available). Without root, it only reports what is missing.
set -euo pipefail

missing_apt=()
have_pkg() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
for pkg in gfortran liblapack-dev libhdf5-dev hdf5-tools pkg-config gnuplot-nox; do
  if ! have_pkg "$pkg"; then
    # gnuplot from another flavour (gnuplot-qt, gnuplot-x11) is as good
    if [ "$pkg" = gnuplot-nox ] && command -v gnuplot >/dev/null 2>&1; then continue; fi
    missing_apt+=("$pkg")
  fi
done

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo_cmd=(sudo); else sudo_cmd=(none); fi
fi

if [ ${#missing_apt[@]} -gt 0 ]; then
  if [ "${sudo_cmd[0]:-}" = none ]; then
    echo "install-deps: missing Debian packages: ${missing_apt[*]} (no root: install them, or load the" \
         "cluster's modules; see docs/user/install.md, 'On a cluster')" >&2
    exit 1
  fi
  echo "install-deps: installing from apt: ${missing_apt[*]}"
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing_apt[@]}" >/dev/null
fi

if ! command -v fpm >/dev/null 2>&1; then
  py=$(command -v python3 || true)
  if [ -z "$py" ]; then
    if [ "${sudo_cmd[0]:-}" = none ]; then echo "install-deps: python3 is missing" >&2; exit 1; fi
    echo "install-deps: installing from apt: python3 python3-pip"
    "${sudo_cmd[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq python3 python3-pip >/dev/null
    py=$(command -v python3)
  fi
  if ! "$py" -m pip --version >/dev/null 2>&1; then
    if [ "${sudo_cmd[0]:-}" = none ]; then echo "install-deps: pip is missing" >&2; exit 1; fi
    echo "install-deps: installing from apt: python3-pip"
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq python3-pip >/dev/null
  fi
  echo "install-deps: installing fpm from PyPI"
  if [ "$(id -u)" -eq 0 ]; then
    "$py" -m pip install -q fpm 2>/dev/null || "$py" -m pip install -q --break-system-packages fpm
  else
    "$py" -m pip install -q --user fpm 2>/dev/null || "$py" -m pip install -q --user --break-system-packages fpm
    echo "install-deps: fpm went to ~/.local/bin; put it on PATH" >&2
  fi
  hash -r
fi
if ! python3 -c 'import h5py' >/dev/null 2>&1; then
  echo "install-deps: installing h5py from PyPI"
  if [ "$(id -u)" -eq 0 ]; then
    python3 -m pip install -q h5py 2>/dev/null || python3 -m pip install -q --break-system-packages h5py
  else
    python3 -m pip install -q --user h5py 2>/dev/null || python3 -m pip install -q --user --break-system-packages h5py
  fi
fi
exit 0
