# The namelist reference docs/user/namelist.md holds, between the markers
# <!-- schema:begin --> and <!-- schema:end -->, the input table written from the
# schema (src/xcable/io/schema.f90) by `xcable --schema markdown`.
#   make schema   rewrite that table (fpm test, and so make test, checks that it is current)

.PHONY: schema

SCHEMA_DOC = docs/user/namelist.md

schema: build
	@grep -q '^<!-- schema:begin -->$$' $(SCHEMA_DOC) && grep -q '^<!-- schema:end -->$$' $(SCHEMA_DOC) || \
		{ echo "make schema: $(SCHEMA_DOC) lacks the markers <!-- schema:begin --> / <!-- schema:end -->" >&2; exit 2; }
	@mkdir -p build
	./bin/xcable --schema markdown >build/schema.md
	awk -v table=build/schema.md \
		'/^<!-- schema:begin -->$$/ { print; while ((getline line < table) > 0) print line; skip = 1; next } \
		 /^<!-- schema:end -->$$/ { skip = 0 } !skip' $(SCHEMA_DOC) >build/namelist.md.new
	mv build/namelist.md.new $(SCHEMA_DOC)
	@echo "$(SCHEMA_DOC): input table rewritten from bin/xcable --schema markdown"

# The page of the result file's datasets, docs/user/output.md, is written from the output
# registry (src/xcable/io/output_registry.f90) by `xcable --outputs markdown`.
#   make outputs  rewrite it (fpm test checks that it is current: suite output, outputs_page_current)

.PHONY: outputs

outputs: build
	@mkdir -p docs/user
	./bin/xcable --outputs markdown >docs/user/output.md
	@echo "docs/user/output.md: written from bin/xcable --outputs markdown"
