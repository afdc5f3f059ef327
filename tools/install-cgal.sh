#!/bin/sh
# Installs g++ and CGAL (header-only; pulls in GMP and MPFR) with apt if
# either is missing. Used by tools/cgal-fixtures/build.sh and
# tools/cgal-timing/build.sh.
set -eu
if [ ! -f /usr/include/CGAL/version.h ] || ! command -v g++ >/dev/null 2>&1; then
    sudo_cmd=""
    [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
    $sudo_cmd apt-get update
    $sudo_cmd apt-get install -y g++ libcgal-dev libgmp-dev libmpfr-dev
fi
