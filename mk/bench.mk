# Work-precision benchmark: `make bench` runs example/bench against
# the installed bin/xcable (one thread) for the box scheme and the rod (averaged
# and lumped mass), and writes docs/measurements/data/benchmark_tables.md, docs/measurements/data/benchmark.dat and
# the figure docs/measurements/benchmark.png (bench/benchmark.gp); about 8 minutes on 2
# cores (2026-12-02), of which the instruction counts (valgrind --tool=callgrind,
# BENCH_JOBS at a time) take a third. `make bench-quick` times only the target configurations
# (before/after checks, a few minutes). Neither is part of `make test`.

.PHONY: bench bench-quick

BENCH_VERSION = $(shell git describe --always --dirty 2>/dev/null || echo unknown)
BENCH_JOBS ?= 2

bench: build
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 $(FPM) run --example bench --profile $(PROFILE) -- \
		exe=bin/xcable work=build/bench out=docs/measurements/data version=$(BENCH_VERSION) jobs=$(BENCH_JOBS)
	gnuplot bench/benchmark.gp

bench-quick: build
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 $(FPM) run --example bench --profile $(PROFILE) -- \
		quick exe=bin/xcable work=build/bench out=docs/measurements/data version=$(BENCH_VERSION)
	@echo "tables in build/bench/benchmark_quick.md"
