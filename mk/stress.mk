# Numerical stability. Included by the main Makefile.
#   make stress        the stress-test sweep (example/stress, in process through the simulation driver, one
#                      thread, both schemes, the slack releases to 2 s; about 25 minutes on one free core):
#                      writes docs/measurements/data/stress.md and docs/measurements/data/stress.csv; docs/measurements/stability.md reads them
#   make stress-quick  a smoke test of the sweep (under a minute), tables in build/stress-quick/
#   make stress-3d     the 3-D scenes of the sweep alone (only=scenes3d, under a minute): writes
#                      docs/measurements/data/stress3d.md and docs/measurements/data/stress3d.csv (make stress writes them too)
#   make test-fuzz     bad-input fuzzing of bin/xcable (test/test_fuzz.sh, malformed namelists)
# The slack positions are compared with the peer runs in bench/peer/runs (if present). The code
# version (git describe) goes into the tables' provenance line.

.PHONY: stress stress-quick stress-3d test-fuzz

STRESS_VERSION = $(shell git describe --always --dirty 2>/dev/null || echo unknown)

stress: deps
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 $(FPM) run --example stress --profile $(PROFILE) -- \
		out=docs/measurements/data peer=bench/peer/runs version=$(STRESS_VERSION)

stress-quick: deps
	@mkdir -p build/stress-quick
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 $(FPM) run --example stress --profile $(PROFILE) -- \
		quick out=build/stress-quick peer=bench/peer/runs version=$(STRESS_VERSION)

stress-3d: deps
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 $(FPM) run --example stress --profile $(PROFILE) -- \
		only=scenes3d out=docs/measurements/data version=$(STRESS_VERSION)

test-fuzz: build
	test/test_fuzz.sh bin/xcable
