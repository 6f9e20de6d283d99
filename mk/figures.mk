# Figures with gnuplot (plots/, docs/user/results.md "Figures", docs/user/scenes.md). Included by the main Makefile.
#   make figures                 run the four paper cases and draw every figure (PNG)
#   make figures FORMAT=pdf      the same as PDF (pdfcairo), for papers
#   make figures-scenes          run the example scenes (input/<scene>.nml, docs/user/scenes.md) and
#                                draw their figures into $(FIGDIR)/<scene>/ (FORMAT=pdf too)
#   make figures-case            draw the figures of results/$(CASE) (no run); CASE=slow_315kN by default
#   make test-figures            check that every plot script draws a PNG without gnuplot warnings
# Figures go to $(FIGDIR): fig2..fig7 (the paper's pairings) and one directory per case or scene.
# A case's results are taken from results/<case>.*, where the input files put them.

FORMAT ?= png
FIGDIR ?= results/figures
PAPER_CASES := fast_180kN fast_315kN slow_180kN slow_315kN
SCENES := inclined_break_middle slack_swing hanging_mass_heave koh_swinging_cable polyester_break \
          chain_mooring_heave polyester_mooring_break buoy_spread_break

.PHONY: figures figures-scenes figures-case test-figures

figures: build
	@for c in $(PAPER_CASES); do ./bin/xcable input/$$c.nml || exit $$?; done
	plots/draw-paper.sh $(FORMAT) results $(FIGDIR)
	@for c in $(PAPER_CASES); do plots/draw.sh results/$$c $(FIGDIR)/$$c $(FORMAT) || exit $$?; done

figures-scenes: build
	@for c in $(SCENES); do ./bin/xcable input/$$c.nml || exit $$?; done
	@for c in $(SCENES); do plots/draw.sh results/$$c $(FIGDIR)/$$c $(FORMAT) || exit $$?; done

figures-case:
	plots/draw.sh results/$(CASE) $(FIGDIR)/$(CASE) $(FORMAT)

test-figures: build
	test/test_figures.sh
