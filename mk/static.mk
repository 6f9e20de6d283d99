# bin/xcable-static (issue 16): the same program with HDF5, LAPACK, BLAS and
# libgfortran linked statically, for sweeps of many short runs. Linking
# dynamically loads 43 shared libraries (HDF5 pulls in curl, TLS, Kerberos
# and LDAP), which costs about 10-20 ms per process on the development
# machine; the static program loads 6 (libsz, libaec, libz, libm, libquadmath,
# libc; docs/speed.md). Results are the same
# bit for bit (the same objects). Needs the static libraries of
# libhdf5-dev, liblapack-dev and libblas-dev and gfortran's libgfortran.a
# (all in the Debian packages of tools/install-deps.sh).

.PHONY: static

HDF5_LIBDIR ?= $(or $(shell pkg-config --variable=libdir hdf5 2>/dev/null),/usr/lib/x86_64-linux-gnu/hdf5/serial)
STATIC_LIBDIR ?= /usr/lib/x86_64-linux-gnu

static: build
	@lib=$$(ls -t build/gfortran_*/xcable/libxcable.a | head -1); \
	main=$$(ls -t build/gfortran_*/xcable/app_main.f90.o | head -1); \
	apps=$$(ls $$(dirname $$main)/app_*.f90.o); \
	set -x; gfortran -O3 -o bin/xcable-static $$apps $$lib \
		$(HDF5_LIBDIR)/libhdf5_fortran.a $(HDF5_LIBDIR)/libhdf5.a \
		$(STATIC_LIBDIR)/liblapack.a $(STATIC_LIBDIR)/libblas.a \
		-static-libgfortran -static-libgcc -Wl,-Bstatic -lquadmath -Wl,-Bdynamic -lsz -lz -lm -ldl
	@./bin/xcable-static --check input/fast_180kN.nml >/dev/null && \
		echo "built bin/xcable-static ($$(ldd bin/xcable-static | wc -l) shared libraries, bin/xcable: $$(ldd bin/xcable | wc -l))"
