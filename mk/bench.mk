# Work-precision benchmark (issue 5): `make bench` runs example/bench against
# the installed bin/xcable (one thread) and writes docs/benchmark_tables.md,
# docs/benchmark.dat and the figure docs/benchmark.png (bench/benchmark.gp).
# `make bench-quick` times only the target configurations (before/after checks).

.PHONY: bench bench-quick

bench: build
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 $(FPM) run --example bench --profile $(PROFILE) -- \
		exe=bin/xcable work=build/bench out=docs
	gnuplot bench/benchmark.gp

bench-quick: build
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 $(FPM) run --example bench --profile $(PROFILE) -- \
		quick exe=bin/xcable work=build/bench out=docs
