# Numerical stability (issue 6). Included by the main Makefile.
#   make stress        the stress-test sweep (example/stress, in process, about a minute on one core):
#                      writes docs/stress.md and docs/stress.csv; docs/stability.md reads them
#   make stress-quick  a smoke test of the sweep (21 nodes only), tables in build/stress-quick/
#   make test-fuzz     bad-input fuzzing of bin/xcable (test/test_fuzz.sh, 133 malformed namelists)

.PHONY: stress stress-quick test-fuzz

stress: deps
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 $(FPM) run --example stress --profile $(PROFILE) -- out=docs

stress-quick: deps
	@mkdir -p build/stress-quick
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 $(FPM) run --example stress --profile $(PROFILE) -- quick out=build/stress-quick

test-fuzz: build
	test/test_fuzz.sh bin/xcable
