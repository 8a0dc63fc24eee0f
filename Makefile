# The two commands of the README, plus the builds they share.
#   make demo       the tool alone, then the study as out/report/index.html
#   make test       everything (tool, test suites, benchmarks), then CTest
#   make doc-check  every command of README.md and docs/*.md verbatim (long)
# Paths are the checkout's, wherever make runs from (make -f).
ROOT := $(patsubst %/,%,$(dir $(realpath $(firstword $(MAKEFILE_LIST)))))
BUILD_DIR ?= build
JOBS ?= $(shell nproc)

.PHONY: all deps configure tool build demo test doc-check clean

all: build

deps:
	@$(ROOT)/scripts/install-deps

# The tools stay on here even if BUILD_DIR was configured without them
# (docs/library.md builds the core alone in build-core/ instead).
configure: deps
	@cmake -S $(ROOT) -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DPENUMBRA_WERROR=ON \
		-DPENUMBRA_BUILD_TOOLS=ON >/dev/null

# The command-line tool alone: all the demo needs.
tool: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target penumbra_cli

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# The main job: build the tool, write the study under out/, say how long
# it took (scripts/demo times the report itself).
demo:
	@start=$$(date +%s); \
	$(MAKE) --no-print-directory tool && $(ROOT)/scripts/demo $(BUILD_DIR)/penumbra out; \
	status=$$?; seconds=$$(( $$(date +%s) - start )); \
	echo "make demo: $$((seconds / 60)) min $$((seconds % 60)) s wall in all"; \
	exit $$status

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

doc-check: tool
	@python3 $(ROOT)/tests/docs/run_doc_commands --verbatim $(ROOT) $(BUILD_DIR)

clean:
	rm -rf $(BUILD_DIR) out
