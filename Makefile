# xcable: the two commands of the README are `make run` and `make test`.
# Each installs what is missing first (tools/install-deps.sh).

SHELL := /bin/bash
export PATH := $(HOME)/.local/bin:$(PATH)
FPM ?= fpm
PROFILE ?= release
CASE ?= slow_315kN

.PHONY: all deps build run test clean

all: build

deps:
	@tools/install-deps.sh

# fpm builds and installs bin/xcable; tools/link-static.sh then links fpm's objects
# again with HDF5, LAPACK, BLAS and libgfortran static (a faster start, the same
# bits; it keeps fpm's program when it cannot). The program's old link is removed
# first so that fpm links it again and its log holds the link command. The library archive is
# removed too: fpm adds objects to it and never takes one out, so a source file that was moved or
# deleted would stay in it (and clash at the link).
build: deps
	@rm -f build/gfortran_*/app/xcable build/gfortran_*/xcable/libxcable.a
	@log=$$(mktemp); \
	if ! $(FPM) install --profile $(PROFILE) --prefix . --verbose >$$log 2>&1; then \
		grep -v '<INFO>' $$log | tail -40; rm -f $$log; exit 1; fi; \
	tools/link-static.sh $$log bin/xcable; rm -f $$log
	@echo "built bin/xcable"

run: build
	./bin/xcable input/$(CASE).nml
	@$(MAKE) --no-print-directory figures-case CASE=$(CASE)
	@echo "figures of $(CASE) in results/figures/$(CASE)/"

# When make build has rebuilt the library, the test program and the tests' objects and modules
# are removed first: fpm neither links the test program again nor compiles the tests against the
# library's new modules (it ran a stale program, or stopped at a module mismatch).
test: build
	@for exe in build/gfortran_*/test/xcable-test; do \
		[ -e "$$exe" ] || continue; \
		if [ -n "$$(find build -name libxcable.a -newer "$$exe")" ]; then \
			rm -f build/gfortran_*/test/xcable-test build/gfortran_*/xcable/test_*.o build/gfortran_*/suite_*.mod \
				build/gfortran_*/xcable_testing.mod build/gfortran_*/xcable_fixtures.mod build/gfortran_*/xcable_fdcheck.mod; \
		fi; \
	done
	$(FPM) test --profile $(PROFILE)
	tools/check_links.py
	tools/golden_cases.py check bin/xcable
	test/test_figures.sh
	test/test_fuzz.sh bin/xcable
	test/test_checkpoint.sh bin/xcable
	test/test_xdmf.sh bin/xcable
	test/test_outputs.py bin/xcable

clean:
	rm -rf build bin

# Further targets (figures, bench, stress, test-slurm) live in mk/*.mk.
-include mk/*.mk
