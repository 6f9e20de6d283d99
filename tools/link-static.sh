#!/usr/bin/env bash
# Link bin/xcable again with HDF5, LAPACK, BLAS and libgfortran from their static
# libraries (issue 16). `make build` calls it after `fpm install --verbose`.
#
#   tools/link-static.sh INSTALL_LOG EXECUTABLE
#
# Why: linked dynamically, xcable loads 43 shared libraries (HDF5 brings curl, TLS,
# Kerberos and LDAP along), and loading them costs about 13 ms of CPU per process
# on the development machine, 16 % of the shipped fast_180kN (docs/measurements/data/speed_rounds.md,
# "Static linking by default"). Linked this way it loads 8. The objects are
# fpm's, taken from its own link command in INSTALL_LOG, so the program computes
# the same bits.
#
# Never fatal: when a static library is missing or the link or its check fails,
# the dynamically linked EXECUTABLE that fpm installed stays, and one line says so.
set -u
log=$1
exe=$2
keep() {
  echo "note: $exe stays dynamically linked ($1); the results are the same, start-up is slower" >&2
  rm -f "$exe.static"
  exit 0
}
[ "${XCABLE_DYNAMIC:-0}" = 1 ] && keep "XCABLE_DYNAMIC=1"
# fpm's link command of the program: "gfortran <flags> <objects> <libxcable.a> -l... -o build/.../app/xcable".
line=$(grep -E -- '-o build/[^ ]+/app/xcable *$' "$log" | tail -1)
[ -n "$line" ] || keep "no link command of the program in $log"
objects=()
for word in $line; do
  case $word in
    *.o | *.a) objects+=("$word") ;;
  esac
done
[ ${#objects[@]} -gt 0 ] || keep "no objects in fpm's link command"
hdf5_dir=$(pkg-config --variable=libdir hdf5 2>/dev/null)
[ -n "$hdf5_dir" ] || hdf5_dir=/usr/lib/x86_64-linux-gnu/hdf5/serial
# The high-level library (dimension scales, io/output.f90) before the library it builds on.
archives=("$hdf5_dir/libhdf5hl_fortran.a" "$hdf5_dir/libhdf5_fortran.a" "$hdf5_dir/libhdf5_hl.a" "$hdf5_dir/libhdf5.a")
# gfortran prints the full path of a library it finds on its search path, the bare name otherwise.
for name in liblapack.a libblas.a; do
  archives+=("$(gfortran -print-file-name=$name)")
done
for a in "${archives[@]}"; do
  [ -f "$a" ] || keep "no static library $a"
done
if ! gfortran -O3 -o "$exe.static" "${objects[@]}" "${archives[@]}" \
  -static-libgfortran -static-libgcc -Wl,-Bstatic -lquadmath -Wl,-Bdynamic -lsz -lz -lm -ldl \
  >build/link-static.log 2>&1; then
  keep "the static link failed: build/link-static.log"
fi
"./$exe.static" --check input/fast_180kN.nml >/dev/null 2>&1 || keep "the statically linked program failed its check"
mv -f "$exe.static" "$exe"
echo "$exe: HDF5, LAPACK, BLAS and libgfortran linked statically ($(ldd "$exe" | wc -l) shared libraries loaded)"
