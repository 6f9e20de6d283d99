# `make dynamic`: bin/xcable as fpm links it (43 shared libraries), for comparison
# with the default build's statically linked one (tools/link-static.sh,
# docs/measurements/data/speed_rounds.md "Static linking by default"). XCABLE_DYNAMIC=1 make build does the same.
.PHONY: dynamic
dynamic:
	@XCABLE_DYNAMIC=1 $(MAKE) --no-print-directory build
