# API documentation with FORD (PyPI ford) from the !> comments of src/ and app/.
#   make docs     writes build/doc/index.html (installs ford with pip if it is missing)

.PHONY: docs

docs:
	@command -v ford >/dev/null 2>&1 || { echo "docs: installing ford from PyPI"; \
		python3 -m pip install -q ford 2>/dev/null || python3 -m pip install -q --break-system-packages ford; }
	cd docs && ford ford.md
	@echo "API documentation in build/doc/index.html"
